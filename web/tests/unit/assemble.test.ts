import { describe, expect, test } from "vitest";
import {
  assemble,
  assembleCloud,
  assembleEscapes,
  assembleFaceFraction,
  assembleMesh,
  assembleVisibility,
  checkFrameList,
  computeBounds,
} from "../../src/decode/assemble";
import {
  classColour,
  ramp,
  segmentColour,
  stationColour,
  UNSEEN_COLOUR,
} from "../../src/decode/colour_maps";
import { byteSize, transferables } from "../../src/decode/types";
import type { CloudData, MeshData } from "../../src/decode/types";
import { FrameError, decodeFrame, encodeFrame } from "../../src/protocol/frame";
import type { Frame, FrameKind } from "../../src/protocol/frame";
import type { FrameInfo } from "../../src/protocol/messages";

function frame(kind: FrameKind, data: ArrayBufferView, item = 0): Frame {
  return decodeFrame(encodeFrame(kind, 1, data, { item }));
}

function listing(frames: Frame[]): FrameInfo[] {
  return frames.map((f) => ({
    kind: f.kind,
    type: f.type,
    components: f.components,
    count: f.count,
    item: f.item,
  }));
}

const CLASSES = ["ceiling", "floor", "wall"];

function cloudFrames(): Frame[] {
  return [
    frame("positions", new Float32Array([0, 0, 0, 1, 2, 3, -1, 5, 0.5, 2, 2, 2])),
    frame("colours", new Uint8Array([255, 0, 0, 0, 255, 0, 0, 0, 255, 9, 9, 9])),
    frame("labels", new Int32Array([0, 2, -1, 7])),
    frame("instances", new Int32Array([3, 3, -1, 8])),
  ];
}

describe("clouds", () => {
  test("positions, colours, labels and instances become attributes with bounds and counts", () => {
    const cloud = assemble(cloudFrames(), listing(cloudFrames()), {
      classNames: CLASSES,
    }) as CloudData;
    expect(cloud.kind).toBe("cloud");
    expect(cloud.count).toBe(4);
    expect(cloud.bounds).toEqual({ min: [-1, 0, 0], max: [2, 5, 3] });
    expect(Array.from(cloud.colours!.subarray(0, 3))).toEqual([255, 0, 0]);
    expect(cloud.classCounts).toEqual([1, 0, 1]);
    expect(cloud.unlabelled).toBe(2); // -1 and 7 (no such class)
    expect(cloud.segments).toBe(2);
    expect(Array.from(cloud.classColours!.subarray(0, 3))).toEqual(classColour("ceiling", 0));
    expect(Array.from(cloud.classColours!.subarray(3, 6))).toEqual(classColour("wall", 2));
    expect(Array.from(cloud.classColours!.subarray(6, 9))).toEqual(classColour(undefined, -1));
    expect(Array.from(cloud.segmentColours!.subarray(0, 3))).toEqual(segmentColour(3));
    expect(Array.from(cloud.segmentColours!.subarray(3, 6))).toEqual(segmentColour(3));
  });

  test("a cloud of positions only has no colour, class or segment arrays", () => {
    const frames = [frame("positions", new Float32Array([1, 1, 1]))];
    const cloud = assembleCloud(frames, {});
    expect(cloud.colours).toBeNull();
    expect(cloud.classColours).toBeNull();
    expect(cloud.segmentColours).toBeNull();
  });

  test("an attribute with another count than the positions is an error", () => {
    const frames = [
      frame("positions", new Float32Array([0, 0, 0, 1, 1, 1])),
      frame("labels", new Int32Array([1])),
    ];
    expect(() => assembleCloud(frames, {})).toThrow(/labels: 1 values for 2 points/);
  });

  test("two frames of the same attribute are an error", () => {
    const frames = [
      frame("positions", new Float32Array([0, 0, 0])),
      frame("positions", new Float32Array([0, 0, 0])),
    ];
    expect(() => assembleCloud(frames, {})).toThrow(/positions: 2 frames, expected one/);
  });

  test("bounds skip non-finite coordinates", () => {
    expect(computeBounds(new Float32Array([NaN, 0, 0, 1, Infinity, 2, 3, 4, 5]))).toEqual({
      min: [1, 0, 0],
      max: [3, 4, 5],
    });
    expect(computeBounds(new Float32Array([]))).toEqual({ min: [0, 0, 0], max: [0, 0, 0] });
  });
});

describe("meshes", () => {
  const positions = new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]);
  const indices = new Uint32Array([0, 1, 2, 0, 1, 3]);

  test("indices are expanded to three vertices per face, with flat normals and group colours", () => {
    const frames = [
      frame("positions", positions),
      frame("indices", indices),
      frame("face_groups", new Uint32Array([0, 1])),
    ];
    const mesh = assemble(frames, listing(frames), { groups: ["a", "b"] }) as MeshData;
    expect(mesh.kind).toBe("mesh");
    expect(mesh.faces).toBe(2);
    expect(mesh.vertices).toBe(4);
    expect(Array.from(mesh.positions.subarray(9, 18))).toEqual([0, 0, 0, 1, 0, 0, 0, 0, 1]);
    expect(Array.from(mesh.normals.subarray(0, 3))).toEqual([0, 0, 1]);
    expect(Array.from(mesh.normals.subarray(9, 12))).toEqual([0, -1, 0]);
    expect(Array.from(mesh.groupColours.subarray(0, 3))).toEqual(segmentColour(0));
    expect(Array.from(mesh.groupColours.subarray(9, 12))).toEqual(segmentColour(1));
    expect(mesh.groups).toEqual(["a", "b"]);
  });

  test("an index past the last vertex is an error naming the face", () => {
    const frames = [
      frame("positions", positions),
      frame("indices", new Uint32Array([0, 1, 2, 0, 1, 4])),
    ];
    expect(() => assembleMesh(frames, {})).toThrow(/indices: face 1 uses vertex 4, the mesh has 4/);
  });

  test("face groups must match the face count", () => {
    const frames = [
      frame("positions", positions),
      frame("indices", indices),
      frame("face_groups", new Uint32Array([0])),
    ];
    expect(() => assembleMesh(frames, {})).toThrow(/face_groups: 1 values for 2 faces/);
  });
});

describe("region growing", () => {
  test("the estimated mesh, its visible fractions and the points' clusters, in matching colours", () => {
    const frames = [
      frame("positions", new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0])),
      frame("indices", new Uint32Array([0, 1, 2])),
      frame("face_groups", new Uint32Array([4])),
      frame("face_visible_fraction", new Float32Array([0.25])),
      frame("point_clusters", new Int32Array([4, -1, 4])),
    ];
    const data = assemble(frames, listing(frames), {});
    expect(data?.kind).toBe("region_growing");
    if (data?.kind !== "region_growing") return;
    expect(data.mesh.faces).toBe(1);
    expect(data.fraction!.mean).toBe(0.25);
    expect(Array.from(data.clusters!)).toEqual([4, -1, 4]);
    expect(Array.from(data.clusterColours!.subarray(0, 3))).toEqual(
      Array.from(data.mesh.groupColours.subarray(0, 3)),
    );
    expect(Array.from(data.clusterColours!.subarray(3, 6))).toEqual(segmentColour(-1));
    const buffers = transferables(data);
    expect(new Set(buffers).size).toBe(buffers.length);
  });

  test("extract_polygons: the planes and the clusters, no fractions", () => {
    const frames = [
      frame("positions", new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0])),
      frame("indices", new Uint32Array([0, 1, 2])),
      frame("face_groups", new Uint32Array([0])),
      frame("point_clusters", new Int32Array([0, 0])),
    ];
    const data = assemble(frames, listing(frames), {});
    expect(data?.kind).toBe("region_growing");
    if (data?.kind !== "region_growing") return;
    expect(data.fraction).toBeNull();
    expect(data.clusters?.length).toBe(2);
  });

  test("a fraction per face is required", () => {
    const frames = [
      frame("positions", new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0])),
      frame("indices", new Uint32Array([0, 1, 2])),
      frame("face_visible_fraction", new Float32Array([0.25, 0.5])),
    ];
    expect(() => assemble(frames, listing(frames), {})).toThrow(
      /face_visible_fraction: 2 values for 1 faces/,
    );
  });
});

describe("job data", () => {
  test("face visible fractions are coloured on the ramp, with min, max and mean", () => {
    const data = assembleFaceFraction(
      frame("face_visible_fraction", new Float32Array([0, 0.5, 1])),
    );
    expect(data).toMatchObject({ faces: 3, min: 0, max: 1, mean: 0.5 });
    expect(Array.from(data.colours.subarray(0, 3))).toEqual(ramp(0));
    expect(Array.from(data.colours.subarray(6, 9))).toEqual(ramp(0)); // 3 vertices per face
    expect(Array.from(data.colours.subarray(18, 21))).toEqual(ramp(1));
  });

  test("a visible fraction outside [0, 1] or NaN is an error", () => {
    expect(() =>
      assembleFaceFraction(frame("face_visible_fraction", new Float32Array([0.2, 1.5]))),
    ).toThrow(/face 1 has 1.5, outside \[0, 1\]/);
    expect(() =>
      assembleFaceFraction(frame("face_visible_fraction", new Float32Array([NaN]))),
    ).toThrow(FrameError);
  });

  test("visibility counts give a histogram over 0..viewpoints and red for unseen points", () => {
    const data = assembleVisibility(frame("visible_count", new Uint16Array([0, 1, 1, 3])), {
      viewpoints: 3,
    });
    expect(data.max).toBe(3);
    expect(data.histogram).toEqual([1, 2, 0, 1]);
    expect(Array.from(data.colours.subarray(0, 3))).toEqual(UNSEEN_COLOUR);
  });

  test("a scan's first viewpoints colour each point by its station, unseen red", () => {
    const counts = frame("visible_count", new Uint16Array([0, 1, 2, 1]));
    const first = frame("covered_by", new Int32Array([-1, 2, 1, 1]));
    const data = assemble([counts, first], listing([counts, first]), { viewpoints: 2 });
    if (data?.kind !== "visibility") throw new Error("not visibility");
    expect(Array.from(data.firstStation!)).toEqual([-1, 2, 1, 1]);
    expect(Array.from(data.firstColours!.subarray(0, 3))).toEqual(UNSEEN_COLOUR);
    expect(Array.from(data.firstColours!.subarray(3, 6))).toEqual(stationColour(2));
    expect(Array.from(data.firstColours!.subarray(6, 9))).toEqual(stationColour(1));
    expect(data.histogram).toEqual([1, 2, 1]);
    const buffers = transferables(data);
    expect(new Set(buffers).size).toBe(4);
    // Without the frame (the live station) there is nothing to colour by.
    expect(assembleVisibility(counts, { viewpoints: 2 }).firstColours).toBeNull();
  });

  test("a first viewpoint that disagrees with its point's count is an error", () => {
    const counts = frame("visible_count", new Uint16Array([0, 1]));
    const check = (first: number[]) => () =>
      assembleVisibility(counts, { viewpoints: 2 }, frame("covered_by", new Int32Array(first)));
    expect(check([-1, 1])).not.toThrow();
    expect(check([1, 1])).toThrow(/point 0 has first viewpoint 1 but is seen by 0/);
    expect(check([-1, -1])).toThrow(/point 1 has first viewpoint -1 but is seen by 1/);
    expect(check([-1, 3])).toThrow(/point 1 has first viewpoint 3/);
    expect(check([-1])).toThrow(/1 values for 2 visible counts/);
  });

  test("escape directions are placed by viewpoint (item), empty for viewpoints without any", () => {
    const frames = [
      frame("escape_directions", new Float32Array([0, 0, 1]), 2),
      frame("escape_directions", new Float32Array([1, 0, 0, 0, 1, 0]), 0),
    ];
    const data = assembleEscapes(frames, { viewpoints: 4 });
    expect(data.directions.map((d) => d.length)).toEqual([6, 0, 3, 0]);
    expect(data.total).toBe(3);
  });

  test("assemble dispatches on the frames and returns null for none", () => {
    expect(assemble([], [], {})).toBeNull();
    const counts = [frame("visible_count", new Uint16Array([2]))];
    expect(assemble(counts, listing(counts), {})?.kind).toBe("visibility");
    const mixed = [
      frame("visible_count", new Uint16Array([2])),
      frame("face_visible_fraction", new Float32Array([1])),
    ];
    expect(() => assemble(mixed, listing(mixed), {})).toThrow(/unexpected mix of frames/);
    const lonely = [frame("labels", new Int32Array([1]))];
    expect(() => assemble(lonely, listing(lonely), {})).toThrow(/labels frames without positions/);
  });
});

describe("checkFrameList", () => {
  test("the frames that arrived must be the ones the result lists", () => {
    const frames = cloudFrames();
    expect(() => checkFrameList(frames, listing(frames))).not.toThrow();
    expect(() => checkFrameList(frames.slice(1), listing(frames))).toThrow(
      /lists 4 frames, 3 arrived/,
    );
    const wrong = listing(frames);
    wrong[2] = { ...wrong[2]!, count: 5 };
    expect(() => checkFrameList(frames, wrong)).toThrow(
      /frame 2 is labels\[0\] x4, the result lists labels\[0\] x5/,
    );
  });
});

describe("transfer", () => {
  test("lists each underlying buffer once, and sizes them", () => {
    const cloud = assemble(cloudFrames(), listing(cloudFrames()), { classNames: CLASSES });
    const buffers = transferables(cloud);
    expect(new Set(buffers).size).toBe(buffers.length);
    expect(buffers.length).toBe(6);
    expect(byteSize(cloud)).toBe(buffers.reduce((n, b) => n + b.byteLength, 0));
    expect(transferables(null)).toEqual([]);
  });
});
