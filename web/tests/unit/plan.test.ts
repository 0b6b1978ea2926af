// The plan's pure parts: the report as the viewer reads it, the heat map's
// colours, the curve's geometry, the params sent, the covered_by frame, and
// the live station's latest-only scheduling.

import { describe, expect, test } from "vitest";
import { assemble, assembleCoveredBy } from "../../src/decode/assemble";
import { heatColour, ramp, stationColour, UNSEEN_COLOUR } from "../../src/decode/colour_maps";
import { LatestOnly } from "../../src/app/latest_only";
import { PlanReportError, parsePlanReport } from "../../src/plan_report";
import { FrameError, decodeFrame, encodeFrame } from "../../src/protocol/frame";
import { CHART_BOX, curvePoints } from "../../src/ui/coverage_chart";
import {
  planChoiceDeclaration,
  planDeclarations,
  planFlagDeclarations,
  planJobParams,
  planLimitParams,
  planUpDeclaration,
} from "../../src/ui/plan_view";

/** A report as the contract of issue 28 gives it: two rooms, two stations. */
function report(): Record<string, unknown> {
  return {
    job: "plan",
    stations: [
      {
        rank: 1,
        candidate: 2,
        name: "S1",
        position: [6, 2, 1.5],
        existing: false,
        gain: 0.55,
        coverage: 0.55,
      },
      {
        rank: 2,
        candidate: 0,
        name: "S2",
        position: [2, 2, 1.5],
        existing: false,
        gain: 0.44,
        coverage: 0.99,
      },
    ],
    coverage_curve: [0.55, 0.99],
    coverage: 0.99,
    target_coverage: 0.99,
    target_reached: true,
    guarantee: "greedy + improvement: at least 1 - 1/e of the best 2 stations",
    candidates: {
      positions: [
        [2, 2, 1.5],
        [4, 2, 1.5],
        [6, 2, 1.5],
      ],
      gain_left: [0, 0.01, 0],
      coverage_alone: [0.44, 0.6, 0.55],
      rejected: { clearance: 4, outside: 1 },
      spacing: 2,
      height: 1.5,
    },
    targets: "points",
    warnings: ["one"],
  };
}

describe("parsePlanReport", () => {
  test("reads stations in order, the curve and the candidates", () => {
    const plan = parsePlanReport(report());
    expect(plan.stations.map((s) => [s.rank, s.name, s.candidate])).toEqual([
      [1, "S1", 2],
      [2, "S2", 0],
    ]);
    expect(plan.stations[1]!.position).toEqual([2, 2, 1.5]);
    expect(plan.curve).toEqual([0.55, 0.99]);
    expect(plan.coverage).toBe(0.99);
    expect(plan.targetCoverage).toBe(0.99);
    expect(plan.targetReached).toBe(true);
    expect(plan.candidates.positions).toHaveLength(3);
    expect(plan.candidates.gainLeft).toEqual([0, 0.01, 0]);
    expect(plan.candidates.spacing).toBe(2);
    expect(plan.candidates.height).toBe(1.5);
    expect(plan.candidates.rejected).toEqual({ clearance: 4, outside: 1 });
    expect(plan.warnings).toEqual(["one"]);
  });

  test("the best-K question has no target", () => {
    const r = report();
    r.target_coverage = null;
    expect(parsePlanReport(r).targetCoverage).toBeNull();
  });

  test.each([
    ["a curve shorter than the stations", (r: Record<string, any>) => (r.coverage_curve = [0.5])],
    ["a gain list of another length", (r: Record<string, any>) => (r.candidates.gain_left = [0])],
    ["a station of no candidate", (r: Record<string, any>) => (r.stations[0].candidate = 3)],
    ["a share above 1", (r: Record<string, any>) => (r.stations[0].gain = 1.5)],
    ["a position of two numbers", (r: Record<string, any>) => (r.stations[0].position = [1, 2])],
    ["no candidates", (r: Record<string, any>) => delete r.candidates],
  ])("refuses %s", (_, spoil) => {
    const r = report();
    spoil(r as Record<string, any>);
    expect(() => parsePlanReport(r)).toThrow(PlanReportError);
  });
});

describe("heat map colours", () => {
  test("the candidate that adds most is the ramp's top, one that adds nothing its bottom", () => {
    expect(heatColour(0.2, 0.2)).toEqual(ramp(1));
    expect(heatColour(0, 0.2)).toEqual(ramp(0));
    expect(heatColour(0.1, 0.2)).toEqual(ramp(0.5));
  });
  test("nothing left to gain anywhere: all at the bottom, never NaN", () => {
    expect(heatColour(0, 0)).toEqual(ramp(0));
  });
  test("station colours are distinct and never the unseen red", () => {
    const colours = [1, 2, 3, 4, 5, 6].map((k) => stationColour(k).join(","));
    expect(new Set(colours).size).toBe(6);
    expect(colours).not.toContain(UNSEEN_COLOUR.join(","));
  });
});

describe("coverage curve", () => {
  test("stations run left to right, coverage bottom (0) to top (1)", () => {
    const [a, b, c] = curvePoints([0, 0.5, 1]);
    const bottom = CHART_BOX.height - CHART_BOX.pad - 12;
    expect(a).toEqual([CHART_BOX.left, bottom]);
    expect(c).toEqual([CHART_BOX.width - CHART_BOX.pad, CHART_BOX.pad]);
    expect(b![0]).toBeCloseTo((a![0] + c![0]) / 2, 2);
    expect(b![1]).toBeCloseTo((bottom + CHART_BOX.pad) / 2, 2);
  });
  test("one station sits in the middle; shares outside [0, 1] are clamped", () => {
    const [only] = curvePoints([1.2]);
    expect(only![0]).toBeCloseTo((CHART_BOX.left + CHART_BOX.width - CHART_BOX.pad) / 2, 2);
    expect(only![1]).toBe(CHART_BOX.pad);
  });
});

describe("plan params", () => {
  const declarations = planDeclarations({
    plan: {
      stations: { name: "stations", min: 1, max: 10000 },
      target_coverage: { name: "target_coverage", default: 0.99, min: 0, max: 1 },
      // As src/app/key.cpp declares an optional key whose default is the server's choice.
      spacing: { name: "spacing", default: "auto", auto: true, unit: "scene units", doc: "grid" },
      height: { name: "height", default: 1.5, unit: "scene units" },
    },
  });
  test("defaults come from the server's declaration", () => {
    expect(declarations.get("height")).toMatchObject({ default: 1.5, unit: "scene units" });
    expect(declarations.get("height")!.auto).toBe(false);
    expect(declarations.get("stations")!.default).toBeNull();
  });
  test("spacing auto: no number for a default, and a blank field sends none (the server's auto)", () => {
    expect(declarations.get("spacing")).toMatchObject({ default: null, auto: true });
    expect(planJobParams({ spacing: "", stations: "2" }, declarations)).toEqual({ stations: 2 });
    expect(planJobParams({ spacing: " " }, declarations)).toEqual({});
    // A number typed is sent as it is: no default it could equal.
    expect(planJobParams({ spacing: "0.25" }, declarations)).toEqual({ spacing: 0.25 });
  });
  test("only what the user set and differs from the server's default is sent", () => {
    expect(
      planJobParams({ height: "1.5", spacing: "", target_coverage: "" }, declarations),
    ).toEqual({});
    expect(planJobParams({ spacing: "0.25", target_coverage: "0.9" }, declarations)).toEqual({
      spacing: 0.25,
      target_coverage: 0.9,
    });
  });
  test("a number of stations is the question asked", () => {
    expect(planJobParams({ stations: "2", target_coverage: "0.9" }, declarations)).toEqual({
      stations: 2,
    });
  });
  test("text that is not a number is refused, naming the field", () => {
    expect(() => planJobParams({ height: "tall" }, declarations)).toThrow(/height/);
  });
  test("a server without the plan job declares nothing", () => {
    expect(planDeclarations({ scan: {} }).size).toBe(0);
    expect(planUpDeclaration({ scan: {} })).toBeNull();
  });
  // Camera-frame data (y down): without "-y" the candidates stand on a wall.
  const up = planUpDeclaration({
    plan: { up: { default: "+z", choices: ["+x", "-x", "+y", "-y", "+z", "-z"], doc: "up" } },
  });
  test("the up axis: its choices and default from the server", () => {
    expect(up).toEqual({
      default: "+z",
      choices: ["+x", "-x", "+y", "-y", "+z", "-z"],
      doc: "up",
    });
  });
  test("an up axis other than the default goes to the plan and to the live station", () => {
    expect(planJobParams({ up: "+z" }, declarations, up)).toEqual({});
    expect(planJobParams({ up: "" }, declarations, up)).toEqual({});
    const params = planJobParams({ up: "-y", max_range: "" }, declarations, up);
    expect(params).toEqual({ up: "-y" });
    expect(planLimitParams({ ...params, spacing: 0.25 })).toEqual({ up: "-y" });
  });
  // A target beyond what the candidates see: all of the reachable (most) or its share.
  const outOfReach = planChoiceDeclaration(
    { plan: { out_of_reach: { default: "most", choices: ["most", "share"], doc: "aim" } } },
    "out_of_reach",
  );
  test("out_of_reach: the server's choices; only one other than its default is sent", () => {
    expect(outOfReach).toEqual({ default: "most", choices: ["most", "share"], doc: "aim" });
    expect(planJobParams({ out_of_reach: "most" }, declarations, up, outOfReach)).toEqual({});
    expect(planJobParams({ out_of_reach: "" }, declarations, up, outOfReach)).toEqual({});
    expect(
      planJobParams(
        { out_of_reach: "share", target_coverage: "0.9" },
        declarations,
        up,
        outOfReach,
      ),
    ).toEqual({ out_of_reach: "share", target_coverage: 0.9 });
    expect(() => planJobParams({ out_of_reach: "all" }, declarations, up, outOfReach)).toThrow(
      /out_of_reach: 'all'/,
    );
    expect(planChoiceDeclaration({ plan: {} }, "out_of_reach")).toBeNull();
  });
  test("refine: a box at the server's default sends nothing; unticked it sends false", () => {
    const flags = planFlagDeclarations({
      plan: { refine: { default: true, doc: "local search" }, improve: { default: true } },
    });
    expect([...flags]).toEqual([["refine", { default: true, doc: "local search" }]]);
    expect(planJobParams({ refine: "true" }, declarations, up, outOfReach, flags)).toEqual({});
    expect(planJobParams({ refine: "false" }, declarations, up, outOfReach, flags)).toEqual({
      refine: false,
    });
    // Not declared by the server: never sent.
    expect(planJobParams({ refine: "false" }, declarations, up, outOfReach, new Map())).toEqual({});
    expect(planFlagDeclarations({ plan: { refine: { default: "yes" } } }).size).toBe(0);
  });
  test("an up axis the server does not offer is refused", () => {
    expect(() => planJobParams({ up: "down" }, declarations, up)).toThrow(/up: 'down'/);
    expect(() => planJobParams({ up: "-y" }, declarations, null)).toThrow(/up/);
  });
});

describe("covered_by frames", () => {
  const frame = (values: number[]) =>
    decodeFrame(encodeFrame("covered_by", 1, new Int32Array(values)));
  test("counts what each station covers first and paints it in the station's colour", () => {
    const data = assembleCoveredBy(frame([1, 2, -1, 1, 2, 2]));
    expect(data.covered).toEqual([1, 2, 3]);
    expect([...data.colours.slice(0, 3)]).toEqual(stationColour(1));
    expect([...data.colours.slice(6, 9)]).toEqual(UNSEEN_COLOUR);
  });
  test("assemble routes it; a rank that is no station's is a FrameError", () => {
    const f = frame([1, -1]);
    const listed = [{ kind: f.kind, type: f.type, components: 1, count: 2, item: 0 }];
    expect(assemble([f], listed, {})?.kind).toBe("covered_by");
    expect(() => assembleCoveredBy(frame([0]))).toThrow(FrameError);
  });
});

describe("LatestOnly", () => {
  test("while a run is in flight only the latest value waits, and it runs next", async () => {
    const ran: number[] = [];
    const gates: (() => void)[] = [];
    const latest = new LatestOnly<number>(async (v) => {
      ran.push(v);
      await new Promise<void>((resolve) => gates.push(resolve));
    });
    latest.push(1);
    latest.push(2);
    latest.push(3);
    latest.push(4);
    expect(ran).toEqual([1]);
    gates.shift()!();
    await new Promise((resolve) => setTimeout(resolve, 0));
    expect(ran).toEqual([1, 4]);
    gates.shift()!();
    await new Promise((resolve) => setTimeout(resolve, 0));
    expect(latest.busy).toBe(false);
    expect(latest.runs).toBe(2);
    expect(latest.skipped).toBe(2);
  });
  test("a failed run does not stop the next one; cancel drops the waiting value", async () => {
    const ran: number[] = [];
    let release: () => void = () => {};
    const latest = new LatestOnly<number>(async (v) => {
      ran.push(v);
      if (v === 1) {
        await new Promise<void>((resolve) => (release = resolve));
        throw new Error("lost");
      }
    });
    latest.push(1);
    latest.push(2);
    release();
    await new Promise((resolve) => setTimeout(resolve, 0));
    expect(ran).toEqual([1, 2]);
    latest.push(3);
    expect(ran).toEqual([1, 2, 3]);
    latest.cancel();
  });
});
