// The plan card's sentences from the report, in the CLI's words
// (src/cli/plan_command.cpp): the question and, for a target out of reach,
// what was asked, what can be reached and what was chosen, with the other
// choice's figures; the refinement's coverage before and after and each
// moved station. Strings only, so they are unit-tested without a DOM.

import type { PlanResult } from "../plan_report";
import { fixed, integer, percent } from "./format";

/** The question asked, and whether it was answered. */
export function planQuestion(result: PlanResult): string {
  if (result.targetCoverage === null) {
    return `best ${result.stations.filter((s) => !s.existing).length} stations`;
  }
  const asked = `fewest stations for ${percent(result.targetCoverage, 1)}`;
  if (result.targetReached) return `${asked} (reached)`;
  if (result.outOfReach !== null) {
    return `${asked}: not reachable, the candidates see ${percent(result.outOfReach.mostCoverage, 1)} at most`;
  }
  const aimed =
    result.aimedCoverage === null ? "" : `, aimed at ${percent(result.aimedCoverage, 1)}`;
  return `${asked} (not reached${aimed})`;
}

/** A target out of reach: the choice made and both choices' figures; none otherwise. */
export function outOfReachFacts(result: PlanResult): [string, string][] {
  const o = result.outOfReach;
  if (o === null) return [];
  const aimed =
    result.aimedCoverage === null ? "" : `: aimed at ${percent(result.aimedCoverage, 1)}`;
  const stations = (n: number) => `${n} new station${n === 1 ? "" : "s"}`;
  return [
    ["Out of reach", `${o.chosen}${aimed}`],
    ["All reachable", `${percent(o.mostCoverage, 1)} with ${stations(o.mostStations)}`],
    [
      `${percent(result.targetCoverage, 0)} of it`,
      `${percent(o.shareCoverage, 1)}, reached by the first ${stations(o.shareStations)} (at ${percent(o.shareReachedAt, 1)})`,
    ],
  ];
}

/** "before → after, N of M new stations searched, P positions traced (budget B)"; null without one. */
export function refinementSummary(result: PlanResult): string | null {
  const r = result.refinement;
  if (r === null) return null;
  return (
    `${percent(r.coverageBefore, 2)} → ${percent(r.coverageAfter, 2)}, ` +
    `${r.stationsRefined} of ${r.stations.length} new station(s) searched, ` +
    `${integer(r.positionsTraced)} positions traced (budget ${integer(r.positionsBudget)})`
  );
}

/** The stations the refinement moved: rank before, from, to, how far, gain before → after. */
export function refinementRows(result: PlanResult): string[][] {
  const position = (p: readonly number[]) => p.map((v) => fixed(v, 2)).join(", ");
  return (result.refinement?.stations ?? [])
    .filter((s) => s.moves > 0)
    .map((s) => [
      String(s.rankBefore),
      position(s.from),
      position(s.to),
      fixed(s.moved, 3),
      `+${percent(s.gainBefore, 2)} → +${percent(s.gainAfter, 2)}`,
    ]);
}
