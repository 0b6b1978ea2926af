import { describe, expect, test } from "vitest";
import { ramp, segmentColour, visibilityColour, UNSEEN_COLOUR } from "../../src/decode/colour_maps";
import { studyPoints } from "../../src/results";
import { SceneCache, cacheKey } from "../../src/scene_cache";
import { fitLine, measuresPresent, niceRange } from "../../src/ui/scatter_plot";
import { assembleVisibility } from "../../src/decode/assemble";
import { decodeFrame, encodeFrame } from "../../src/protocol/frame";
import { patternPoints } from "../../src/scene/viewpoint_pattern";

describe("colour maps", () => {
  test("ramp runs from viridis' purple to its yellow and clamps", () => {
    expect(ramp(0)).toEqual([68, 1, 84]);
    expect(ramp(1)).toEqual([253, 231, 37]);
    expect(ramp(-3)).toEqual(ramp(0));
    expect(ramp(7)).toEqual(ramp(1));
  });

  test("segment colours are stable and distinct for neighbours", () => {
    expect(segmentColour(5)).toEqual(segmentColour(5));
    expect(segmentColour(5)).not.toEqual(segmentColour(6));
  });

  test("visibility: unseen is red, the most-seen is the ramp's top", () => {
    expect(visibilityColour(0, 3)).toEqual(UNSEEN_COLOUR);
    expect(visibilityColour(3, 3)).toEqual(ramp(1));
  });
});

describe("scene cache", () => {
  const visibility = (n: number) =>
    assembleVisibility(decodeFrame(encodeFrame("visible_count", 1, new Uint16Array(n))), {});

  test("keys by path, mtime and size; evicts the least recently used beyond the limit", () => {
    const cache = new SceneCache<string>(3000);
    cache.put(cacheKey("a", 1, 2), "A", visibility(200)); // 432 + 600 bytes
    cache.put(cacheKey("b"), "B", visibility(200));
    expect(cache.get(cacheKey("a", 1, 2))?.result).toBe("A"); // a is now the most recent
    cache.put(cacheKey("c"), "C", visibility(200));
    expect(cache.get(cacheKey("b"))).toBeUndefined();
    expect(cache.get(cacheKey("a", 1, 2))).toBeDefined();
    expect(cache.bytes).toBeLessThanOrEqual(3000);
    cache.forget("a");
    expect(cache.get(cacheKey("a", 1, 2))).toBeUndefined();
    expect(cacheKey("a", 1, 2)).not.toBe(cacheKey("a", 1, 3));
  });
});

describe("study", () => {
  test("finds rows with a miou and the study's measures anywhere in a report", () => {
    const report = {
      rows: [
        { scene: "office_1", configuration: "pattern_1", occlusion_level: 0.2, miou: 0.7 },
        { occlusion_level: 0.4, visible_fraction: 0.9, miou: 0.5 },
        { occlusion_level: 0.3 }, // no miou: not a point
      ],
      other: 1,
    };
    expect(studyPoints(report, "study")).toEqual([
      {
        measures: { occlusion_level: 0.2 },
        miou: 0.7,
        label: "office_1 pattern_1",
        series: "study",
      },
      {
        measures: { visible_fraction: 0.9, occlusion_level: 0.4 },
        miou: 0.5,
        label: "study.rows#2",
        series: "study",
      },
    ]);
  });

  test("fits a line and zooms the axes to the data with round ticks", () => {
    const line = fitLine([
      [0, 0.8],
      [0.5, 0.3],
    ]);
    expect(line!.a).toBeCloseTo(0.8);
    expect(line!.b).toBeCloseTo(-1);
    expect(fitLine([[0.1, 0.1]])).toBeNull();
    expect(niceRange(0.62, 0.71)).toEqual({ min: 0.6, max: 0.725, step: 0.025 });
    const r = niceRange(0.013, 0.019);
    expect(r.min).toBeCloseTo(0.012);
    expect(r.max).toBeCloseTo(0.02);
    expect(niceRange(0, 1)).toEqual({ min: 0, max: 1, step: 0.25 });
    // One value: a small range around it, never beyond [0, 1].
    const one = niceRange(1, 1);
    expect(one.max).toBe(1);
    expect(one.min).toBeLessThan(1);
  });

  test("lists only the measures the points have, never mixing them", () => {
    const points = [
      { measures: { session_poc: 0.1 }, miou: 0.5, label: "a", series: "session" as const },
      { measures: { visible_fraction: 0.8 }, miou: 0.6, label: "b", series: "study" as const },
    ];
    expect(measuresPresent(points)).toEqual(["visible_fraction", "session_poc"]);
  });
});

describe("viewpoint pattern", () => {
  test("centre and the midpoints towards the box's max and min corners", () => {
    expect(patternPoints({ min: [0, 0, 0], max: [8, 6, 3] })).toEqual({
      centre: [4, 3, 1.5],
      max: [6, 4.5, 2.25],
      min: [2, 1.5, 0.75],
    });
  });
});
