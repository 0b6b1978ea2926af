// The extent of a scan without its stray points: real laser scans carry a few
// points far outside the room (reflections, people walking by), and framing
// the camera, placing the pattern viewpoints or sizing points on the full
// bounding box makes the room tiny. Per axis, the box runs from the q-th to
// the (1−q)-th quantile of the coordinates, widened by a margin of its span
// and never beyond the full bounds. A frame the server computed (issue 12:
// `robust_box` or `frame.box` in the load report) wins over this estimate.

import type { Bounds, Vec3 } from "./types";

export interface RobustOptions {
  /** Fraction of the points allowed outside on each side of each axis. */
  quantile: number;
  /** Widening on each side, as a fraction of the quantile box's span. */
  margin: number;
  /** At most this many points are read (an even stride through the cloud). */
  sample: number;
}

export const ROBUST_DEFAULTS: RobustOptions = { quantile: 0.02, margin: 0.02, sample: 60_000 };

/** The value at fraction `q` of the sorted `values` (nearest rank). */
export function quantile(sorted: Float32Array, q: number): number {
  const n = sorted.length;
  if (n === 0) return NaN;
  const rank = Math.min(n - 1, Math.max(0, Math.round(q * (n - 1))));
  return sorted[rank]!;
}

/** The robust box of `count` xyz triples in `positions`, inside `full`. */
export function robustBounds(
  positions: Float32Array,
  count: number,
  full: Bounds,
  options: Partial<RobustOptions> = {},
): Bounds {
  const o = { ...ROBUST_DEFAULTS, ...options };
  if (count === 0) return full;
  const stride = Math.max(1, Math.floor(count / o.sample));
  const n = Math.ceil(count / stride);
  const min = [0, 0, 0] as Vec3;
  const max = [0, 0, 0] as Vec3;
  const values = new Float32Array(n);
  for (let axis = 0; axis < 3; ++axis) {
    let k = 0;
    for (let i = 0; i < count && k < n; i += stride) values[k++] = positions[i * 3 + axis]!;
    const sorted = values.subarray(0, k).sort();
    const lo = quantile(sorted, o.quantile);
    const hi = quantile(sorted, 1 - o.quantile);
    const pad = (hi - lo) * o.margin;
    min[axis] = Math.max(full.min[axis]!, lo - pad);
    max[axis] = Math.min(full.max[axis]!, hi + pad);
  }
  return { min, max };
}

function isVec3(v: unknown): v is Vec3 {
  return Array.isArray(v) && v.length === 3 && v.every((x) => typeof x === "number" && isFinite(x));
}

/** A box `{min, max}` with min ≤ max on every axis, or null. */
export function asBounds(value: unknown): Bounds | null {
  if (typeof value !== "object" || value === null) return null;
  const { min, max } = value as { min?: unknown; max?: unknown };
  if (!isVec3(min) || !isVec3(max)) return null;
  return min.every((m, a) => m <= max[a]!) ? { min, max } : null;
}

/** The server's robust frame from a load report, if it sent one. */
export function serverExtent(report: Record<string, unknown>): Bounds | null {
  const frame = report.frame as Record<string, unknown> | undefined;
  return asBounds(report.robust_box) ?? asBounds(frame?.robust_box) ?? asBounds(frame?.box);
}

/** True when the box holds the point (inclusive). */
export function contains(bounds: Bounds, p: Vec3): boolean {
  return p.every((x, a) => x >= bounds.min[a]! && x <= bounds.max[a]!);
}

export function diagonal(bounds: Bounds): number {
  const [a, b] = [bounds.min, bounds.max];
  return Math.hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]) || 1;
}
