// The point model's settings: the server's declarations (hello) give the
// primitive's default and choices and make the point radius "auto"; the cloud
// jobs send only what the user set.

import { afterEach, beforeEach, describe, expect, test } from "vitest";
import { parseServerMessage } from "../../src/protocol/messages";
import type { HelloMessage } from "../../src/protocol/messages";
import { CHOICES, SETTINGS, adoptServerKeys, cloudJobParams } from "../../src/settings_defaults";
import type { CloudSettings } from "../../src/settings_defaults";

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
