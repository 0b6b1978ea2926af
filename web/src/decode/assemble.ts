// Turns the decoded frames of one request into geometry-ready arrays. Pure
// (no DOM, no three.js): it runs in the decode worker, and unit tests call it
// directly. Every inconsistency (a missing or extra frame, counts that do not
// match, an index out of range) is a FrameError naming it.

import { FrameError } from "../protocol/frame";
import type { Frame } from "../protocol/frame";
import type { FrameInfo } from "../protocol/messages";
import {
  classColour,
  firstViewpointColour,
  ramp,
  segmentColour,
  visibilityColour,
} from "./colour_maps";
import type { Rgb } from "./colour_maps";
import type {
  AssembleContext,
  Bounds,
  CloudData,
  CoveredByData,
  Decoded,
  EscapeData,
  FaceFractionData,
  MeshData,
  RegionGrowingData,
  VisibilityData,
} from "./types";

/** Checks the frames that arrived against the `frames` list of the result. */
export function checkFrameList(frames: Frame[], listed: FrameInfo[]): void {
  if (frames.length !== listed.length) {
    throw new FrameError(`the result lists ${listed.length} frames, ${frames.length} arrived`);
  }
  frames.forEach((frame, i) => {
    const info = listed[i] as FrameInfo;
    if (info.kind !== frame.kind || info.count !== frame.count || info.item !== frame.item) {
      throw new FrameError(
        `frame ${i} is ${frame.kind}[${frame.item}] x${frame.count}, ` +
          `the result lists ${info.kind}[${info.item}] x${info.count}`,
      );
    }
  });
}

export function computeBounds(positions: Float32Array): Bounds {
  const min: [number, number, number] = [Infinity, Infinity, Infinity];
  const max: [number, number, number] = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i + 2 < positions.length; i += 3) {
    for (let a = 0; a < 3; ++a) {
      const v = positions[i + a] as number;
      if (!Number.isFinite(v)) continue;
      if (v < min[a]!) min[a] = v;
      if (v > max[a]!) max[a] = v;
    }
  }
  if (!(min[0] <= max[0])) return { min: [0, 0, 0], max: [0, 0, 0] };
  return { min, max };
}

function single(frames: Frame[], kind: Frame["kind"]): Frame | undefined {
  const found = frames.filter((f) => f.kind === kind);
  if (found.length > 1) throw new FrameError(`${kind}: ${found.length} frames, expected one`);
  return found[0];
}

function expectCount(frame: Frame | undefined, count: number, per: string): void {
  if (frame !== undefined && frame.count !== count) {
    throw new FrameError(`${frame.kind}: ${frame.count} values for ${count} ${per}`);
  }
}

function paint(
  count: number,
  colourOf: (i: number) => readonly [number, number, number],
  repeat = 1,
): Uint8Array {
  const out = new Uint8Array(count * 3 * repeat);
  let o = 0;
  for (let i = 0; i < count; ++i) {
    const c = colourOf(i);
    for (let r = 0; r < repeat; ++r) {
      out[o++] = c[0];
      out[o++] = c[1];
      out[o++] = c[2];
    }
  }
  return out;
}

/** Paints by an integer key, computing each distinct key's colour once. */
function paintByKey(
  keys: Int32Array | Uint32Array,
  colourOf: (key: number) => readonly [number, number, number],
  repeat = 1,
): Uint8Array {
  const cache = new Map<number, readonly [number, number, number]>();
  return paint(
    keys.length,
    (i) => {
      const key = keys[i] as number;
      let c = cache.get(key);
      if (c === undefined) {
        c = colourOf(key);
        cache.set(key, c);
      }
      return c;
    },
    repeat,
  );
}

/** Clouds above this many points get a draw order for level of detail. */
export const LOD_MIN_POINTS = 20_000;

/** A seeded random permutation of 0..n-1 (Fisher–Yates, xorshift32). */
export function randomOrder(n: number, seed = 0x9e3779b9): Uint32Array {
  const order = new Uint32Array(n);
  for (let i = 0; i < n; ++i) order[i] = i;
  let x = seed >>> 0 || 1;
  for (let i = n - 1; i > 0; --i) {
    x ^= x << 13;
    x >>>= 0;
    x ^= x >>> 17;
    x ^= x << 5;
    x >>>= 0;
    const j = x % (i + 1);
    const t = order[i]!;
    order[i] = order[j]!;
    order[j] = t;
  }
  return order;
}

export function assembleCloud(frames: Frame[], context: AssembleContext): CloudData {
  const positions = single(frames, "positions");
  if (positions === undefined) throw new FrameError("cloud without a positions frame");
  const count = positions.count;
  const colours = single(frames, "colours");
  const labels = single(frames, "labels");
  const instances = single(frames, "instances");
  expectCount(colours, count, "points");
  expectCount(labels, count, "points");
  expectCount(instances, count, "points");
  const classNames = context.classNames ?? [];

  let classColours: Uint8Array | null = null;
  const classCounts = new Array<number>(classNames.length).fill(0);
  let unlabelled = 0;
  if (labels !== undefined) {
    const l = labels.data as Int32Array;
    for (let i = 0; i < l.length; ++i) {
      const k = l[i] as number;
      if (k >= 0 && k < classNames.length) classCounts[k] = (classCounts[k] as number) + 1;
      else unlabelled += 1;
    }
    classColours = paintByKey(l, (k) =>
      k >= 0 && k < classNames.length ? classColour(classNames[k], k) : classColour(undefined, -1),
    );
  }
  let segmentColours: Uint8Array | null = null;
  let segments = 0;
  if (instances !== undefined) {
    const ids = instances.data as Int32Array;
    segmentColours = paintByKey(ids, segmentColour);
    const seen = new Set<number>();
    for (let i = 0; i < ids.length; ++i) if ((ids[i] as number) >= 0) seen.add(ids[i] as number);
    segments = seen.size;
  }
  const p = positions.data as Float32Array;
  return {
    kind: "cloud",
    count,
    positions: p,
    bounds: computeBounds(p),
    colours: colours ? (colours.data as Uint8Array) : null,
    labels: labels ? (labels.data as Int32Array) : null,
    instances: instances ? (instances.data as Int32Array) : null,
    classColours,
    segmentColours,
    order: count > LOD_MIN_POINTS ? randomOrder(count) : null,
    classNames,
    classCounts,
    unlabelled,
    segments,
  };
}

const MESH_GREY: [number, number, number] = [200, 200, 205];

export function assembleMesh(frames: Frame[], context: AssembleContext): MeshData {
  const positions = single(frames, "positions");
  const indices = single(frames, "indices");
  if (positions === undefined || indices === undefined) {
    throw new FrameError("mesh without positions and indices frames");
  }
  const groupsFrame = single(frames, "face_groups");
  const faces = indices.count;
  expectCount(groupsFrame, faces, "faces");
  const vertices = positions.count;
  const p = positions.data as Float32Array;
  const idx = indices.data as Uint32Array;
  const out = new Float32Array(faces * 9);
  const normals = new Float32Array(faces * 9);
  for (let f = 0; f < faces; ++f) {
    const base = f * 9;
    for (let c = 0; c < 3; ++c) {
      const v = idx[f * 3 + c] as number;
      if (v >= vertices) {
        throw new FrameError(`indices: face ${f} uses vertex ${v}, the mesh has ${vertices}`);
      }
      out[base + c * 3] = p[v * 3] as number;
      out[base + c * 3 + 1] = p[v * 3 + 1] as number;
      out[base + c * 3 + 2] = p[v * 3 + 2] as number;
    }
    // Flat normal: (b - a) x (c - a), normalised.
    const ax = out[base]!,
      ay = out[base + 1]!,
      az = out[base + 2]!;
    const ux = out[base + 3]! - ax,
      uy = out[base + 4]! - ay,
      uz = out[base + 5]! - az;
    const vx = out[base + 6]! - ax,
      vy = out[base + 7]! - ay,
      vz = out[base + 8]! - az;
    let nx = uy * vz - uz * vy,
      ny = uz * vx - ux * vz,
      nz = ux * vy - uy * vx;
    const length = Math.hypot(nx, ny, nz) || 1;
    nx /= length;
    ny /= length;
    nz /= length;
    for (let c = 0; c < 3; ++c) {
      normals[base + c * 3] = nx;
      normals[base + c * 3 + 1] = ny;
      normals[base + c * 3 + 2] = nz;
    }
  }
  const faceGroups = groupsFrame ? (groupsFrame.data as Uint32Array) : null;
  const groupColours = faceGroups
    ? paintByKey(faceGroups, (g) => segmentColour(g), 3)
    : paint(faces, () => MESH_GREY, 3);
  return {
    kind: "mesh",
    faces,
    vertices,
    positions: out,
    normals,
    faceGroups,
    groupColours,
    groups: context.groups ?? [],
    groupCount: faceGroups ? new Set(faceGroups).size : 0,
    bounds: computeBounds(p),
  };
}

/** A mesh estimated from a cloud, with its fractions (if measured) and the points' clusters. */
export function assembleRegionGrowing(
  frames: Frame[],
  context: AssembleContext,
): RegionGrowingData {
  const mesh = assembleMesh(
    frames.filter(
      (f) => f.kind === "positions" || f.kind === "indices" || f.kind === "face_groups",
    ),
    context,
  );
  const fractionFrame = single(frames, "face_visible_fraction");
  expectCount(fractionFrame, mesh.faces, "faces");
  const clusters = single(frames, "point_clusters");
  const ids = clusters ? (clusters.data as Int32Array) : null;
  return {
    kind: "region_growing",
    mesh,
    fraction: fractionFrame ? assembleFaceFraction(fractionFrame) : null,
    clusters: ids,
    clusterColours: ids ? paintByKey(ids, segmentColour) : null,
  };
}

export function assembleFaceFraction(frame: Frame): FaceFractionData {
  const fraction = frame.data as Float32Array;
  let min = Infinity;
  let max = -Infinity;
  let sum = 0;
  for (let i = 0; i < fraction.length; ++i) {
    const v = fraction[i] as number;
    if (!(v >= 0 && v <= 1)) {
      throw new FrameError(`face_visible_fraction: face ${i} has ${v}, outside [0, 1]`);
    }
    if (v < min) min = v;
    if (v > max) max = v;
    sum += v;
  }
  const faces = fraction.length;
  return {
    kind: "face_fraction",
    faces,
    fraction,
    colours: paint(faces, (i) => ramp(fraction[i] as number), 3),
    min: faces ? min : 0,
    max: faces ? max : 0,
    mean: faces ? sum / faces : 0,
  };
}

/**
 * Per point: how many viewpoints see it and, with -fscan's covered_by frame,
 * the first that does (a number from 1 no greater than its count's viewpoints).
 */
export function assembleVisibility(
  frame: Frame,
  context: AssembleContext,
  first: Frame | null = null,
): VisibilityData {
  const counts = frame.data as Uint16Array;
  let largest = 0;
  for (let i = 0; i < counts.length; ++i) if ((counts[i] as number) > largest) largest = counts[i]!;
  const max = Math.max(context.viewpoints ?? 0, largest, 1);
  const histogram = new Array<number>(max + 1).fill(0);
  for (let i = 0; i < counts.length; ++i) histogram[counts[i]!] = (histogram[counts[i]!] ?? 0) + 1;
  const palette = histogram.map((_, k) => visibilityColour(k, max));
  const firstStation = first === null ? null : (first.data as Int32Array);
  if (firstStation !== null) {
    if (firstStation.length !== counts.length) {
      throw new FrameError(
        `covered_by: ${firstStation.length} values for ${counts.length} visible counts`,
      );
    }
    for (let i = 0; i < counts.length; ++i) {
      const k = firstStation[i] as number;
      const seen = (counts[i] as number) > 0;
      if (seen ? k < 1 || k > max : k !== -1) {
        throw new FrameError(
          `covered_by: point ${i} has first viewpoint ${k} but is seen by ${counts[i]}`,
        );
      }
    }
  }
  return {
    kind: "visibility",
    count: counts.length,
    visibleCount: counts,
    colours: paint(counts.length, (i) => palette[counts[i]!]!),
    max,
    histogram,
    firstStation,
    firstColours: firstStation === null ? null : paintFirstViewpoint(firstStation),
  };
}

/** Per point, the colour of the first viewpoint that sees it (firstViewpointColour). */
export function paintFirstViewpoint(
  firstStation: Int32Array,
  colours: readonly Rgb[] = [],
): Uint8Array {
  return paintByKey(firstStation, (k) => firstViewpointColour(k, colours));
}

export function assembleCoveredBy(frame: Frame): CoveredByData {
  const rank = frame.data as Int32Array;
  const covered = [0];
  for (let i = 0; i < rank.length; ++i) {
    const k = rank[i] as number;
    if (k === -1) covered[0] = (covered[0] as number) + 1;
    else if (k >= 1 && k <= rank.length) {
      while (covered.length <= k) covered.push(0);
      covered[k] = (covered[k] as number) + 1;
    } else throw new FrameError(`covered_by: target ${i} has rank ${k}, not −1 or a station's`);
  }
  return {
    kind: "covered_by",
    count: rank.length,
    rank,
    colours: paintByKey(rank, (k) => firstViewpointColour(k)),
    covered,
  };
}

export function assembleEscapes(frames: Frame[], context: AssembleContext): EscapeData {
  const n = Math.max(context.viewpoints ?? 0, ...frames.map((f) => f.item + 1));
  const directions: Float32Array[] = Array.from({ length: n }, () => new Float32Array(0));
  let total = 0;
  for (const frame of frames) {
    directions[frame.item] = frame.data as Float32Array;
    total += frame.count;
  }
  return { kind: "escapes", directions, total };
}

/**
 * Assembles what a request's frames describe: a cloud (positions …), a mesh
 * (positions + indices), a job's per-element data, or null when there are none.
 */
export function assemble(
  frames: Frame[],
  listed: FrameInfo[],
  context: AssembleContext,
): Decoded | null {
  checkFrameList(frames, listed);
  if (frames.length === 0) return null;
  const kinds = new Set(frames.map((f) => f.kind));
  if (kinds.has("indices") && (kinds.has("face_visible_fraction") || kinds.has("point_clusters"))) {
    return assembleRegionGrowing(frames, context);
  }
  if (kinds.has("indices")) return assembleMesh(frames, context);
  if (kinds.has("positions")) return assembleCloud(frames, context);
  if (kinds.size === 2 && kinds.has("visible_count") && kinds.has("covered_by")) {
    // -fscan: how many viewpoints see each point, and the first that does.
    const first = single(frames, "covered_by")!;
    return assembleVisibility(single(frames, "visible_count")!, context, first);
  }
  const first = frames[0] as Frame;
  if (kinds.size > 1) throw new FrameError(`unexpected mix of frames: ${[...kinds].join(", ")}`);
  switch (first.kind) {
    case "face_visible_fraction":
      return assembleFaceFraction(single(frames, "face_visible_fraction")!);
    case "visible_count":
      return assembleVisibility(single(frames, "visible_count")!, context);
    case "escape_directions":
      return assembleEscapes(frames, context);
    case "covered_by":
      return assembleCoveredBy(single(frames, "covered_by")!);
    default:
      throw new FrameError(`${first.kind} frames without positions`);
  }
}
