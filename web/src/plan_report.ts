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
  height: number | null;
  rejected: Record<string, number>;
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
      height: optionalNumber(c.height),
      rejected,
    },
    targets: typeof report.targets === "string" ? report.targets : "points",
    warnings: Array.isArray(report.warnings)
      ? report.warnings.filter((w): w is string => typeof w === "string")
      : [],
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
