// Is a viewpoint where a scanner could stand? Outside the occupied space (the
// scene's robust box) it sees the room from outside and its figures mean
// little; within a point radius of a scanned point it sits inside an object
// (the radius the last job traced with, or the user's; none before either).

import { contains } from "../decode/robust_extent";
import type { Bounds, Vec3 } from "../decode/types";

/** Distance from `p` to the nearest of `count` points (Infinity for none). */
export function nearestDistance(positions: Float32Array, count: number, p: Vec3): number {
  let best = Infinity;
  for (let i = 0; i < count; ++i) {
    const dx = positions[i * 3]! - p[0];
    const dy = positions[i * 3 + 1]! - p[1];
    const dz = positions[i * 3 + 2]! - p[2];
    const d = dx * dx + dy * dy + dz * dz;
    if (d < best) best = d;
  }
  return Math.sqrt(best);
}

/** Why this viewpoint is suspect, or null. */
export function viewpointWarning(
  p: Vec3,
  extent: Bounds,
  cloud: { positions: Float32Array; count: number } | null,
  radius: number | null,
): string | null {
  if (!contains(extent, p)) return "outside the occupied space (the scan's robust box)";
  if (cloud && radius !== null && radius > 0) {
    const d = nearestDistance(cloud.positions, cloud.count, p);
    if (d < radius) {
      return `inside an object: a scanned point ${d.toFixed(3)} m away (point radius ${Number(radius.toPrecision(3))})`;
    }
  }
  return null;
}
