// The pure parts of the viewer on real scans: robust extent, escape-ray
// sampling and clipping, opening validation, viewpoint warnings, settings
// taken from the server's key declarations, number formatting.

import { describe, expect, test } from "vitest";
import { polygonProblem } from "../../src/decode/polygon_check";
import { asBounds, quantile, robustBounds, serverExtent } from "../../src/decode/robust_extent";
import type { Bounds, Vec3 } from "../../src/decode/types";
import { evenSample, exitDistance, rayGeometry } from "../../src/scene/escape_rays";
import { nearestDistance, viewpointWarning } from "../../src/scene/viewpoint_checks";
import { SETTINGS, adoptServerKeys } from "../../src/settings_defaults";
import { significantDecimals } from "../../src/ui/format";
import { defaultsNote } from "../../src/ui/viewpoint_panel";

const BOX: Bounds = { min: [0, 0, 0], max: [6, 5, 3] };

describe("robust extent", () => {
  test("nearest-rank quantiles", () => {
    const sorted = Float32Array.from([1, 2, 3, 4, 5]);
    expect(quantile(sorted, 0)).toBe(1);
    expect(quantile(sorted, 0.5)).toBe(3);
    expect(quantile(sorted, 1)).toBe(5);
  });

  test("a grid filling a box plus 1 % strays far away: the box, not the strays", () => {
    const points: number[] = [];
    for (let i = 0; i <= 60; ++i)
      for (let j = 0; j <= 50; ++j)
        for (let k = 0; k <= 30; k += 10) points.push(i / 10, j / 10, k / 10);
    const n = points.length / 3;
    for (let s = 0; s < n / 100; ++s) points.push(100 + s, -80 - s, 50 + s);
    const count = points.length / 3;
    const full: Bounds = { min: [0, -80 - n / 100, 0], max: [100 + n / 100, 5, 50 + n / 100] };
    const box = robustBounds(Float32Array.from(points), count, full, { margin: 0 });
    // The walls hold far more than 2 % of the points: the 2 % quantiles are the walls, give or take one step.
    for (let a = 0; a < 3; ++a) {
      expect(Math.abs(box.min[a]! - BOX.min[a]!)).toBeLessThanOrEqual(0.1 + 1e-6);
      expect(Math.abs(box.max[a]! - BOX.max[a]!)).toBeLessThanOrEqual(0.1 + 1e-6);
    }
  });

  test("the margin widens the box but never beyond the full bounds", () => {
    const p = Float32Array.from([0, 0, 0, 10, 10, 10]);
    const box = robustBounds(
      p,
      2,
      { min: [0, 0, 0], max: [10, 10, 10] },
      {
        quantile: 0,
        margin: 0.5,
      },
    );
    expect(box).toEqual({ min: [0, 0, 0], max: [10, 10, 10] });
  });

  test("a server frame wins; malformed ones are ignored", () => {
    expect(serverExtent({ robust_box: { min: [1, 2, 3], max: [4, 5, 6] } })).toEqual({
      min: [1, 2, 3],
      max: [4, 5, 6],
    });
    expect(serverExtent({ frame: { box: { min: [0, 0, 0], max: [1, 1, 1] } } })).toEqual({
      min: [0, 0, 0],
      max: [1, 1, 1],
    });
    expect(asBounds({ min: [2, 0, 0], max: [1, 1, 1] })).toBeNull(); // min > max
    expect(asBounds({ min: [0, 0], max: [1, 1, 1] })).toBeNull();
    expect(serverExtent({})).toBeNull();
  });
});

describe("escape rays", () => {
  test("exit distance from inside a box, along axes and diagonals", () => {
    expect(exitDistance([3, 2.5, 1.5], [1, 0, 0], BOX)).toBeCloseTo(3);
    expect(exitDistance([3, 2.5, 1.5], [0, 0, -1], BOX)).toBeCloseTo(1.5);
    const d = Math.SQRT1_2;
    expect(exitDistance([1, 1, 1], [d, d, 0], BOX)).toBeCloseTo(4 * Math.SQRT2); // leaves at y = 5
    expect(exitDistance([10, 10, 10], [1, 0, 0], BOX)).toBe(0); // outside, pointing away
  });

  test("even samples: all when few, evenly spread and distinct when many", () => {
    expect(evenSample(3, 5)).toEqual([0, 1, 2]);
    const s = evenSample(1000, 4);
    expect(s).toEqual([0, 250, 500, 750]);
  });

  test("a sample per viewpoint, clipped to the box, in the viewpoint's colour", () => {
    const many = new Float32Array(3 * 1000);
    for (let i = 0; i < 1000; ++i) many.set([1, 0, 0], i * 3);
    const escapes = {
      kind: "escapes" as const,
      directions: [many, Float32Array.from([0, 0, 1, 0, 1, 0])],
    };
    const origins: Vec3[] = [
      [3, 2.5, 1.5],
      [1, 1, 1],
    ];
    const viewpoints = [
      { label: "A", colour: [1, 0, 0] as Vec3 },
      { label: "B", colour: [0, 0, 1] as Vec3 },
    ];
    const set = rayGeometry(escapes as never, origins, viewpoints, BOX, 100);
    expect(set.total).toEqual([1000, 2]);
    expect(set.drawn).toEqual([100, 2]);
    const p = set.geometry.getAttribute("position");
    const c = set.geometry.getAttribute("color");
    expect(p.count).toBe(2 * 102);
    // First segment: from A's origin to x = 6 (the box's wall), red.
    expect([p.getX(1), p.getY(1), p.getZ(1)]).toEqual([6, 2.5, 1.5]);
    expect([c.getX(0), c.getY(0), c.getZ(0)]).toEqual([1, 0, 0]);
    // B's rays: to the ceiling (z = 3) and to the far wall (y = 5), blue.
    expect([p.getX(201), p.getY(201), p.getZ(201)]).toEqual([1, 1, 3]);
    expect([p.getX(203), p.getY(203), p.getZ(203)]).toEqual([1, 5, 1]);
    expect([c.getX(203), c.getY(203), c.getZ(203)]).toEqual([0, 0, 1]);
  });
});

describe("openings", () => {
  const square: Vec3[] = [
    [2, 5, 1],
    [4, 5, 1],
    [4, 5, 2],
    [2, 5, 2],
  ];

  test("a square window on a wall is accepted", () => {
    expect(polygonProblem(square)).toBeNull();
    // Picked points are noisy: 2 cm off the wall is still one plane.
    expect(polygonProblem([...square.slice(0, 3), [2, 5.02, 2]])).toBeNull();
  });

  test("refused, with the reason", () => {
    expect(polygonProblem(square.slice(0, 2))).toContain("at least 3 points");
    expect(polygonProblem([square[0]!, square[2]!, square[1]!, square[3]!])).toContain(
      "crosses itself",
    );
    expect(
      polygonProblem([
        [0, 0, 0],
        [1, 0, 0],
        [2, 0, 0],
      ]),
    ).toContain("on one line");
    expect(polygonProblem([square[0]!, square[0]!, square[2]!])).toContain("same point");
    expect(polygonProblem([...square.slice(0, 3), [2, 6, 2]])).toContain("not on one plane");
  });
});

describe("viewpoint warnings", () => {
  const cloud = { positions: Float32Array.from([3, 2, 0.75, 0, 0, 0]), count: 2 };

  test("nearest point by brute force", () => {
    expect(nearestDistance(cloud.positions, 2, [3, 2, 1.75])).toBeCloseTo(1);
  });

  test("outside the room, inside an object, or fine", () => {
    expect(viewpointWarning([7, 2, 1], BOX, cloud, 0.06)).toContain("outside");
    expect(viewpointWarning([3, 2, 0.78], BOX, cloud, 0.06)).toContain("inside an object");
    expect(viewpointWarning([3, 2, 1.5], BOX, cloud, 0.06)).toBeNull();
  });

  test("a default viewpoint takes the job's answer: a station outside the box is no warning", () => {
    expect(viewpointWarning([7, 2, 1], BOX, cloud, 0.06, false)).toBeNull();
    expect(viewpointWarning([3, 2, 1.5], BOX, cloud, 0.06, true)).toContain("outside");
  });
});

describe("default viewpoints note", () => {
  const defaults = {
    viewpoint_source: "num_vp 9",
    viewpoints: [
      { name: "viewpoint_1", position: [1, 2, 3] as Vec3, outside_occupied_space: false },
    ],
    warnings: ["up is +z, but the largest flat structure is perpendicular to y"],
  };

  test("the job's warnings show while the markers are its defaults, and only then", () => {
    const at = defaultsNote(defaults, true)!;
    expect(at.text).toContain("num_vp 9");
    expect(at.warnings).toEqual(defaults.warnings);
    expect(defaultsNote(defaults, false)!.warnings).toEqual([]);
    expect(defaultsNote(undefined, true)).toBeNull();
  });

  test("what reading found shows whether or not the markers are the defaults, and on a mesh", () => {
    const reading = ["frames/far.frame.json: 192 of 192 depths lie beyond 20 m"];
    for (const atDefaults of [true, false]) {
      const note = defaultsNote(defaults, atDefaults, reading)!;
      expect(note.reading).toEqual(reading);
      // Apart from the job's warnings about its defaults, which go when they are moved.
      expect(note.warnings).toEqual(atDefaults ? defaults.warnings : []);
    }
    const withoutDefaults = defaultsNote(undefined, true, reading)!;
    expect(withoutDefaults.reading).toEqual(reading);
    expect(withoutDefaults.text).toBeNull();
    expect(defaultsNote(defaults, true)!.reading).toEqual([]);
  });
});

describe("settings", () => {
  test("the server's key declarations override the viewer's defaults", () => {
    const before = { ...SETTINGS.raysPerViewpoint };
    const changed = adoptServerKeys({
      commands: {
        cloud_occlusion: {
          keys: { num_rays_per_vp: { default: 30000, min: 10, max: 1e6, doc: "rays per vp" } },
        },
      },
    });
    expect(changed).toEqual(["raysPerViewpoint"]);
    expect(SETTINGS.raysPerViewpoint.default).toBe(30000);
    expect(SETTINGS.raysPerViewpoint.max).toBe(1e6);
    expect(SETTINGS.raysPerViewpoint.doc).toBe("rays per vp");
    Object.assign(SETTINGS.raysPerViewpoint, before);
    expect(adoptServerKeys({ commands: { ping: true } })).toEqual([]);
  });

  test("slider numbers with three significant digits", () => {
    expect(significantDecimals(0.200235559148495)).toBe(3);
    expect(significantDecimals(0.0123)).toBe(4);
    expect(significantDecimals(25)).toBe(1);
    expect(significantDecimals(2500)).toBe(0);
  });
});
