// The `plan` job's report (scan planning, docs/protocol.md) as the viewer
// reads it: the chosen stations in order, the coverage curve, and every
// candidate's position and gain left. Parsed and checked in one place, so a
// malformed report is one readable error rather than a heat map drawn wrong.

import type { Vec3 } from "./decode/types";

export interface PlannedStation {
  rank: number;
  /** Index into the candidates. */
  candidate: number;
  name: string;
  position: Vec3;
  /** A station that was already there (given, or the file's own). */
  existing: boolean;
  /** Share of the total weight this station adds. */
  gain: number;
  /** Share covered once this station is placed. */
  coverage: number;
}

export interface PlanCandidates {
  positions: Vec3[];
  /** Per candidate: the share it would still add to the chosen stations. */
  gainLeft: number[];
  /** Per candidate: the share it sees alone. */
  coverageAlone: number[];
  /** Grid step and scanner height (null for candidates from a file). */
  spacing: number | null;
  /** The grid's spacing was chosen by the server (spacing auto). */
  spacingAuto: boolean;
  height: number | null;
  rejected: Record<string, number>;
}

/**
 * A target beyond what all the candidates see (report.out_of_reach): what
 * was chosen (out_of_reach: most or share) and both choices' figures.
 */
export interface PlanOutOfReach {
  chosen: string;
  /** All the candidates reach, and the new stations that reach it (greedy from the chosen on). */
  mostCoverage: number;
  mostStations: number;
  /** The target's share of that, and the first new stations that reach it, at what coverage. */
  shareCoverage: number;
  shareStations: number;
  shareReachedAt: number;
}

/** One new station's local search (report.refinement.stations[]). */
export interface RefinedStation {
  rankBefore: number;
  from: Vec3;
  to: Vec3;
  moved: number;
  moves: number;
  gainBefore: number;
  gainAfter: number;
}

/** The refinement of the new stations (report.refinement; refine on). */
export interface PlanRefinement {
  coverageBefore: number;
  coverageAfter: number;
  positionsTraced: number;
  positionsBudget: number;
  stationsRefined: number;
  stations: RefinedStation[];
}

export interface PlanResult {
  stations: PlannedStation[];
  curve: number[];
  coverage: number;
  targetCoverage: number | null;
  targetReached: boolean;
  guarantee: string;
  candidates: PlanCandidates;
  targets: string;
  warnings: string[];
  /** What all the candidates together see (null from a server without it). */
  reachableCoverage: number | null;
  /** Target mode: what the stations aimed at (the target, or out of reach the chosen figure). */
  aimedCoverage: number | null;
  /** A target out of reach: both choices (null when the target was within reach or stations were asked). */
  outOfReach: PlanOutOfReach | null;
  /** Null when there was none (refine off, no new station). */
  refinement: PlanRefinement | null;
}

export class PlanReportError extends Error {
  constructor(message: string) {
    super(`plan report: ${message}`);
    this.name = "PlanReportError";
  }
}

type Json = Record<string, unknown>;

function isObject(value: unknown): value is Json {
  return typeof value === "object" && value !== null && !Array.isArray(value);
}

function share(value: unknown, what: string): number {
  if (typeof value !== "number" || !(value >= -1e-9 && value <= 1 + 1e-9)) {
    throw new PlanReportError(`${what} must be a share in [0, 1], got ${JSON.stringify(value)}`);
  }
  return value;
}

function point(value: unknown, what: string): Vec3 {
  if (
    !Array.isArray(value) ||
    value.length !== 3 ||
    !value.every((v) => typeof v === "number" && Number.isFinite(v))
  ) {
    throw new PlanReportError(`${what} must be [x, y, z], got ${JSON.stringify(value)}`);
  }
  return value as Vec3;
}

function list(value: unknown, what: string): unknown[] {
  if (!Array.isArray(value)) throw new PlanReportError(`${what} must be a list`);
  return value;
}

function optionalNumber(value: unknown): number | null {
  return typeof value === "number" && Number.isFinite(value) ? value : null;
}

export function parsePlanReport(report: unknown): PlanResult {
  if (!isObject(report)) throw new PlanReportError("not an object");
  const c = report.candidates;
  if (!isObject(c)) throw new PlanReportError("'candidates' missing");
  const positions = list(c.positions, "candidates.positions").map((p, i) =>
    point(p, `candidates.positions[${i}]`),
  );
  const perCandidate = (key: string) => {
    const values = list(c[key], `candidates.${key}`);
    if (values.length !== positions.length) {
      throw new PlanReportError(
        `candidates.${key} has ${values.length} values for ${positions.length} candidates`,
      );
    }
    return values.map((v, i) => share(v, `candidates.${key}[${i}]`));
  };
  const rejected: Record<string, number> = {};
  if (isObject(c.rejected)) {
    for (const [k, v] of Object.entries(c.rejected)) if (typeof v === "number") rejected[k] = v;
  }
  const stations = list(report.stations, "stations").map((entry, i): PlannedStation => {
    if (!isObject(entry)) throw new PlanReportError(`stations[${i}] is not an object`);
    const candidate = entry.candidate;
    if (
      typeof candidate !== "number" ||
      !Number.isInteger(candidate) ||
      candidate < 0 ||
      candidate >= positions.length
    ) {
      throw new PlanReportError(
        `stations[${i}].candidate ${JSON.stringify(candidate)} is not one of the ` +
          `${positions.length} candidates`,
      );
    }
    const rank = typeof entry.rank === "number" ? entry.rank : i + 1;
    return {
      rank,
      candidate,
      name: typeof entry.name === "string" ? entry.name : `S${rank}`,
      position: point(entry.position, `stations[${i}].position`),
      existing: entry.existing === true,
      gain: share(entry.gain, `stations[${i}].gain`),
      coverage: share(entry.coverage, `stations[${i}].coverage`),
    };
  });
  const curve = list(report.coverage_curve, "coverage_curve").map((v, i) =>
    share(v, `coverage_curve[${i}]`),
  );
  if (curve.length !== stations.length) {
    throw new PlanReportError(
      `coverage_curve has ${curve.length} values for ${stations.length} stations`,
    );
  }
  return {
    stations,
    curve,
    coverage: share(report.coverage, "coverage"),
    targetCoverage: optionalNumber(report.target_coverage),
    targetReached: report.target_reached === true,
    guarantee: typeof report.guarantee === "string" ? report.guarantee : "",
    candidates: {
      positions,
      gainLeft: perCandidate("gain_left"),
      coverageAlone: perCandidate("coverage_alone"),
      spacing: optionalNumber(c.spacing),
      spacingAuto: c.spacing_auto === true,
      height: optionalNumber(c.height),
      rejected,
    },
    targets: typeof report.targets === "string" ? report.targets : "points",
    warnings: Array.isArray(report.warnings)
      ? report.warnings.filter((w): w is string => typeof w === "string")
      : [],
    reachableCoverage:
      report.reachable_coverage === undefined
        ? null
        : share(report.reachable_coverage, "reachable_coverage"),
    aimedCoverage:
      report.aimed_coverage === undefined || report.aimed_coverage === null
        ? null
        : share(report.aimed_coverage, "aimed_coverage"),
    outOfReach: parseOutOfReach(report.out_of_reach),
    refinement: parseRefinement(report.refinement),
  };
}

function count(value: unknown, what: string): number {
  if (typeof value !== "number" || !Number.isInteger(value) || value < 0) {
    throw new PlanReportError(`${what} must be a count, got ${JSON.stringify(value)}`);
  }
  return value;
}

function parseOutOfReach(value: unknown): PlanOutOfReach | null {
  if (value === undefined || value === null) return null;
  if (!isObject(value)) throw new PlanReportError("out_of_reach is not an object");
  return {
    chosen: typeof value.chosen === "string" ? value.chosen : "",
    mostCoverage: share(value.most_coverage, "out_of_reach.most_coverage"),
    mostStations: count(
      value.most_reached_by_new_stations,
      "out_of_reach.most_reached_by_new_stations",
    ),
    shareCoverage: share(value.share_coverage, "out_of_reach.share_coverage"),
    shareStations: count(
      value.share_reached_by_first_new_stations,
      "out_of_reach.share_reached_by_first_new_stations",
    ),
    shareReachedAt: share(value.share_reached_at, "out_of_reach.share_reached_at"),
  };
}

function parseRefinement(value: unknown): PlanRefinement | null {
  if (value === undefined || value === null) return null;
  if (!isObject(value)) throw new PlanReportError("refinement is not an object");
  const number = (v: unknown, what: string) => {
    if (typeof v !== "number" || !Number.isFinite(v)) {
      throw new PlanReportError(`${what} must be a number, got ${JSON.stringify(v)}`);
    }
    return v;
  };
  const stations = list(value.stations, "refinement.stations").map((entry, i) => {
    const what = `refinement.stations[${i}]`;
    if (!isObject(entry)) throw new PlanReportError(`${what} is not an object`);
    return {
      rankBefore: count(entry.rank_before, `${what}.rank_before`),
      from: point(entry.from, `${what}.from`),
      to: point(entry.to, `${what}.to`),
      moved: number(entry.moved, `${what}.moved`),
      moves: count(entry.moves, `${what}.moves`),
      // A gain is a share; one station's before and after, so a search is judged by them.
      gainBefore: share(entry.gain_before, `${what}.gain_before`),
      gainAfter: share(entry.gain_after, `${what}.gain_after`),
    };
  });
  return {
    coverageBefore: share(value.coverage_before, "refinement.coverage_before"),
    coverageAfter: share(value.coverage_after, "refinement.coverage_after"),
    positionsTraced: count(value.positions_traced, "refinement.positions_traced"),
    positionsBudget: count(value.positions_budget, "refinement.positions_budget"),
    stationsRefined: count(value.stations_refined, "refinement.stations_refined"),
    stations,
  };
}

/** The candidate nearest `position` (a click on the heat map), or −1 for none. */
export function nearestCandidate(positions: readonly Vec3[], position: Vec3): number {
  let best = -1;
  let bestDistance = Infinity;
  positions.forEach((p, i) => {
    const d = Math.hypot(p[0] - position[0], p[1] - position[1], p[2] - position[2]);
    if (d < bestDistance) {
      bestDistance = d;
      best = i;
    }
  });
  return best;
}
