// The plan card's figures for a target out of reach and the refinement: read
// from the report (out_of_reach, refinement, aimed_coverage) and said as the
// CLI says them.

import { describe, expect, test } from "vitest";
import { PlanReportError, parsePlanReport } from "../../src/plan_report";
import {
  outOfReachFacts,
  planQuestion,
  refinementRows,
  refinementSummary,
} from "../../src/ui/plan_figures";

/** A target of 90 % where the candidates see 86.1 % at most (issue 41, item 5), refined. */
function report(): Record<string, any> {
  return {
    job: "plan",
    stations: [
      { rank: 1, candidate: 3, name: "S1", position: [1.2, 2, 1.5], gain: 0.6, coverage: 0.6 },
      { rank: 2, candidate: 1, name: "S2", position: [6, 2, 1.5], gain: 0.261, coverage: 0.861 },
    ],
    coverage_curve: [0.6, 0.861],
    coverage: 0.861,
    target_coverage: 0.9,
    target_reached: false,
    reachable_coverage: 0.861,
    aimed_coverage: 0.861,
    out_of_reach: {
      chosen: "most",
      most_coverage: 0.861,
      most_reached_by_new_stations: 2,
      share_coverage: 0.7749,
      share_reached_by_first_new_stations: 1,
      share_reached_at: 0.8,
    },
    guarantee: "",
    candidates: {
      positions: [
        [2, 2, 1.5],
        [6, 2, 1.5],
        [1, 2, 1.5],
        [1.2, 2, 1.5],
      ],
      gain_left: [0, 0, 0, 0],
      coverage_alone: [0.5, 0.3, 0.55, 0.6],
      rejected: {},
      spacing: 0.25,
      spacing_auto: true,
      height: 1.5,
    },
    refinement: {
      coverage_before: 0.85,
      coverage_after: 0.861,
      positions_traced: 57,
      positions_budget: 192,
      stations_refined: 2,
      first_step: 0.125,
      stations: [
        {
          rank_before: 1,
          refined: true,
          from: [1, 2, 1.5],
          to: [1.2, 2, 1.5],
          moved: 0.2,
          moves: 1,
          gain_before: 0.55,
          gain_after: 0.6,
        },
        {
          rank_before: 2,
          refined: true,
          from: [6, 2, 1.5],
          to: [6, 2, 1.5],
          moved: 0,
          moves: 0,
          gain_before: 0.261,
          gain_after: 0.261,
        },
      ],
    },
    targets: "points",
    warnings: [],
  };
}

describe("a target out of reach", () => {
  const plan = parsePlanReport(report());

  test("the report's both choices are read", () => {
    expect(plan.reachableCoverage).toBe(0.861);
    expect(plan.aimedCoverage).toBe(0.861);
    expect(plan.outOfReach).toEqual({
      chosen: "most",
      mostCoverage: 0.861,
      mostStations: 2,
      shareCoverage: 0.7749,
      shareStations: 1,
      shareReachedAt: 0.8,
    });
    expect(plan.candidates.spacingAuto).toBe(true);
  });

  test("the question says it cannot be reached and what can", () => {
    expect(planQuestion(plan)).toBe(
      "fewest stations for 90.0%: not reachable, the candidates see 86.1% at most",
    );
  });

  test("the card says what was chosen, and the other choice's figures", () => {
    expect(outOfReachFacts(plan)).toEqual([
      ["Out of reach", "most: aimed at 86.1%"],
      ["All reachable", "86.1% with 2 new stations"],
      ["90% of it", "77.5%, reached by the first 1 new station (at 80.0%)"],
    ]);
  });

  test("a target within reach has no such figures", () => {
    const r = report();
    r.target_reached = true;
    r.out_of_reach = null;
    const within = parsePlanReport(r);
    expect(within.outOfReach).toBeNull();
    expect(outOfReachFacts(within)).toEqual([]);
    expect(planQuestion(within)).toBe("fewest stations for 90.0% (reached)");
  });

  test("a malformed block is refused, not drawn wrong", () => {
    const r = report();
    r.out_of_reach.most_reached_by_new_stations = -1;
    expect(() => parsePlanReport(r)).toThrow(PlanReportError);
  });
});

describe("the refinement", () => {
  const plan = parsePlanReport(report());

  test("coverage before and after, stations searched and positions traced", () => {
    expect(refinementSummary(plan)).toBe(
      "85.00% → 86.10%, 2 of 2 new station(s) searched, 57 positions traced (budget 192)",
    );
  });

  test("a row for each station it moved: from, to, how far, the gain before and after", () => {
    expect(refinementRows(plan)).toEqual([
      ["1", "1.00, 2.00, 1.50", "1.20, 2.00, 1.50", "0.200", "+55.00% → +60.00%"],
    ]);
  });

  test("without a refinement (refine off) nothing is said", () => {
    const r = report();
    r.refinement = null;
    const plain = parsePlanReport(r);
    expect(refinementSummary(plain)).toBeNull();
    expect(refinementRows(plain)).toEqual([]);
  });

  test("a station's from or to that is no position is refused", () => {
    const r = report();
    r.refinement.stations[0].to = [1, 2];
    expect(() => parsePlanReport(r)).toThrow(PlanReportError);
  });
});
