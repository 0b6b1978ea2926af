// The point model's settings: the server's declarations (hello) give the
// primitive's default and choices and make the point radius "auto"; the cloud
// jobs send only what the user set; reports show the model they traced with.

import { afterEach, beforeEach, describe, expect, test } from "vitest";
import { parseServerMessage } from "../../src/protocol/messages";
import type { HelloMessage } from "../../src/protocol/messages";
import { reportPointRadius } from "../../src/results";
import { viewpointWarning } from "../../src/scene/viewpoint_checks";
import { CHOICES, SETTINGS, adoptServerKeys, cloudJobParams } from "../../src/settings_defaults";
import type { CloudSettings } from "../../src/settings_defaults";
import { pointModelText } from "../../src/ui/occlusion_view";

// The shape `occlusion serve` publishes (src/app/key.cpp, to_json): per job, a list.
const POINT_KEYS = [
  {
    name: "point_radius",
    type: "number",
    default: "auto",
    auto: true,
    min: 0,
    min_exclusive: true,
    max: 1e6,
    unit: "scene units",
    doc: "radius of each point's disc or sphere",
  },
  {
    name: "primitive",
    type: "string",
    default: "disc",
    choices: ["disc", "sphere"],
    doc: "each point is a disc in its surface or a sphere",
  },
  { name: "num_rays_per_vp", type: "integer", default: 20000, min: 1, doc: "rays" },
];

function hello(): HelloMessage {
  const message = parseServerMessage(
    JSON.stringify({
      type: "hello",
      protocol: 1,
      commands: { cloud_occlusion: true, scan: true },
      jobs: {
        cloud_occlusion: { section: "occlusion.point_cloud", keys: POINT_KEYS },
        scan: { section: "occlusion.scan", keys: POINT_KEYS.slice(0, 2) },
      },
    }),
  );
  if (message.type !== "hello") throw new Error("not a hello");
  return message;
}

const saved = {
  settings: structuredClone(SETTINGS),
  choices: structuredClone(CHOICES),
};

function defaults(): CloudSettings {
  return {
    raysPerViewpoint: SETTINGS.raysPerViewpoint.default,
    pointRadiusAuto: SETTINGS.pointRadius.auto ?? false,
    pointRadius: SETTINGS.pointRadius.default,
    primitive: CHOICES.primitive.default,
  };
}

beforeEach(() => {
  for (const [k, v] of Object.entries(structuredClone(saved.settings))) {
    Object.assign(SETTINGS[k as keyof typeof SETTINGS], v);
  }
  Object.assign(CHOICES.primitive, structuredClone(saved.choices.primitive));
});

afterEach(() => {
  Object.assign(CHOICES.primitive, structuredClone(saved.choices.primitive));
});

describe("point model settings from hello", () => {
  test("before hello: radius auto, no primitive of the viewer's own, nothing sent", () => {
    expect(SETTINGS.pointRadius.auto).toBe(true);
    expect(CHOICES.primitive).toMatchObject({ default: "", choices: [] });
    expect(cloudJobParams(defaults(), "poc")).toEqual({});
    expect(cloudJobParams(defaults(), "scan")).toEqual({});
    // A primitive the server never declared is not sent either.
    expect(cloudJobParams({ ...defaults(), primitive: "sphere" }, "poc")).toEqual({});
  });

  test("hello declares the primitive's default and choices, and point_radius auto", () => {
    const range = { min: SETTINGS.pointRadius.min, max: SETTINGS.pointRadius.max };
    const changed = adoptServerKeys({ keys: hello().keys });
    expect(changed).toEqual(
      expect.arrayContaining(["pointRadius", "primitive", "raysPerViewpoint"]),
    );
    expect(CHOICES.primitive.default).toBe("disc");
    expect(CHOICES.primitive.choices).toEqual(["disc", "sphere"]);
    expect(CHOICES.primitive.doc).toContain("disc in its surface");
    expect(SETTINGS.pointRadius.auto).toBe(true);
    // Its slider's range is the scene's (scene_view.ts), not 0 to 1e6.
    expect({ min: SETTINGS.pointRadius.min, max: SETTINGS.pointRadius.max }).toEqual(range);
    expect(SETTINGS.pointRadius.doc).toBe("radius of each point's disc or sphere");
  });

  test("a server whose point_radius defaults to a number: no auto, that number", () => {
    adoptServerKeys({
      keys: { cloud_occlusion: { point_radius: { default: 0.04, min: 0, max: 1e6 } } },
    });
    expect(SETTINGS.pointRadius.auto).toBe(false);
    expect(SETTINGS.pointRadius.default).toBe(0.04);
    const s = { ...defaults(), pointRadiusAuto: false };
    expect(cloudJobParams(s, "poc")).toEqual({}); // its default: not sent
    expect(cloudJobParams({ ...s, pointRadius: 0.03 }, "poc")).toEqual({ point_radius: 0.03 });
  });
});

describe("cloudJobParams: only what the user set", () => {
  beforeEach(() => {
    adoptServerKeys({ keys: hello().keys });
  });

  test("the defaults send nothing: the server's defaults apply, as in the CLI", () => {
    expect(cloudJobParams(defaults(), "poc")).toEqual({});
    expect(cloudJobParams(defaults(), "scan")).toEqual({});
  });

  test("auto off sends the slider's radius to both jobs", () => {
    const s = { ...defaults(), pointRadiusAuto: false, pointRadius: 0.025 };
    expect(cloudJobParams(s, "poc")).toEqual({ point_radius: 0.025 });
    expect(cloudJobParams(s, "scan")).toEqual({ point_radius: 0.025 });
    // Auto on: the slider's number stays in the viewer.
    expect(cloudJobParams({ ...s, pointRadiusAuto: true }, "poc")).toEqual({});
    // No radius that is not a positive number.
    expect(cloudJobParams({ ...s, pointRadius: 0 }, "poc")).toEqual({});
    expect(cloudJobParams({ ...s, pointRadius: Number.NaN }, "poc")).toEqual({});
  });

  test("a primitive other than the server's default is sent; the default and unknown ones are not", () => {
    expect(cloudJobParams({ ...defaults(), primitive: "sphere" }, "scan")).toEqual({
      primitive: "sphere",
    });
    expect(cloudJobParams({ ...defaults(), primitive: "disc" }, "poc")).toEqual({});
    expect(cloudJobParams({ ...defaults(), primitive: "cube" }, "poc")).toEqual({});
    expect(
      cloudJobParams(
        { ...defaults(), primitive: "sphere", pointRadiusAuto: false, pointRadius: 0.06 },
        "poc",
      ),
    ).toEqual({ primitive: "sphere", point_radius: 0.06 });
  });

  test("rays per viewpoint: sent to -poc when changed, never to the scan", () => {
    const s = { ...defaults(), raysPerViewpoint: 5000 };
    expect(cloudJobParams(s, "poc")).toEqual({ num_rays_per_vp: 5000 });
    expect(cloudJobParams(s, "scan")).toEqual({});
  });
});

const DISC_REPORT = {
  job: "cloud_occlusion",
  parameters: { point_radius: 0.0213, point_radius_auto: true },
  point_model: {
    primitive: "disc",
    point_radius: 0.0213,
    point_radius_auto: true,
    discs: 31204,
    spheres: 1815,
    stray_points: 12,
    radius_quantile_10: 0.0151,
    radius_median: 0.0213,
    radius_quantile_90: 0.0342,
    open_surface_share: 0.0087,
    surface_noise: {
      band_sigmas: 8,
      stations: [
        {
          station: "s1",
          bins: [
            [1.5, 1.875, 5000, 0.0021],
            [1.875, 2.34, 4000, 0.0034],
          ],
        },
      ],
    },
  },
  timings: { total_seconds: 1.2, surfel_seconds: 0.25 },
};

describe("the report's point model", () => {
  test("discs: counts and the median radius in a line, the rest in its tooltip", () => {
    const model = pointModelText(DISC_REPORT);
    expect(model?.text).toBe("discs 31,204, spheres 1,815, median radius 0.0213 (auto)");
    expect(model?.detail).toContain("radius 10–90 %: 0.0151–0.0342");
    expect(model?.detail).toContain("stray points: 12");
    expect(model?.detail).toContain("open surface: 0.87%");
    expect(model?.detail).toContain("surface noise σ 0.0021–0.0034, band 8 σ");
    expect(model?.detail).toContain("250 ms");
  });

  test("spheres of a given radius; reports without a point model", () => {
    const sphere = {
      point_model: { primitive: "sphere", point_radius: 0.06, point_radius_auto: false },
    };
    expect(pointModelText(sphere)?.text).toBe("spheres of radius 0.06");
    expect(pointModelText({ job: "mesh_occlusion" })).toBeNull();
  });

  test("the radius a job traced with: point_model's, else its parameters'", () => {
    expect(reportPointRadius(DISC_REPORT)).toBe(0.0213);
    expect(reportPointRadius({ parameters: { point_radius: 0.05 } })).toBe(0.05);
    expect(reportPointRadius({ parameters: { point_radius: "auto" } })).toBeUndefined();
    expect(reportPointRadius({ job: "mesh_occlusion" })).toBeUndefined();
  });
});

describe("viewpoint warning: the radius in use, or the cloud's spacing there", () => {
  const box = {
    min: [0, 0, 0] as [number, number, number],
    max: [6, 4, 3] as [number, number, number],
  };
  // A row of points 0.02 apart (one duplicated) on a table top at z 0.75.
  const row = [0, 0.02, 0.04, 0.04, 0.06].flatMap((dx) => [3 + dx, 2, 0.75]);
  const cloud = { positions: new Float32Array(row), count: 5 };

  test("a radius from a report (or the user): inside an object within it", () => {
    expect(viewpointWarning([3, 2, 0.76], box, cloud, 0.0213)).toBe(
      "inside an object: a scanned point 0.010 m away (point radius 0.0213)",
    );
    expect(viewpointWarning([3, 2, 0.78], box, cloud, 0.0213)).toBeNull();
    expect(viewpointWarning([7, 2, 1], box, cloud, 0.0213)).toContain("outside");
  });

  test("none yet: closer than the nearest point's own neighbour (duplicates aside)", () => {
    expect(viewpointWarning([3.04, 2, 0.76], box, cloud, null)).toBe(
      "inside an object: a scanned point 0.010 m away (the point spacing there is 0.02)",
    );
    expect(viewpointWarning([3.04, 2, 0.78], box, cloud, null)).toBeNull();
    const lone = { positions: new Float32Array([3, 2, 0.75]), count: 1 };
    expect(viewpointWarning([3, 2, 0.751], box, lone, null)).toBeNull();
  });
});
