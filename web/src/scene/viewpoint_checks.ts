// Is a viewpoint where a scanner could stand? Outside the occupied space (the
// scene's robust box) it sees the room from outside and its figures mean
// little; within a point radius of a scanned point it sits inside an object.
// The radius is the one the last -poc traced with (its report), or the user's;
// before either, the spacing of the cloud at the nearest point (its distance
// to its own nearest neighbour) stands in: the viewer has no number of its own.

import { contains } from "../decode/robust_extent";
import type { Bounds, Vec3 } from "../decode/types";

/**
 * Index of the point nearest `p`, and its distance (-1, Infinity for none);
 * with `skip`, other than that point and its duplicates (distance 0).
 */
export function nearestPoint(
  positions: Float32Array,
  count: number,
  p: Vec3,
  skip = -1,
): { index: number; distance: number } {
  let best = Infinity;
  let index = -1;
  for (let i = 0; i < count; ++i) {
    if (i === skip) continue;
    const dx = positions[i * 3]! - p[0];
    const dy = positions[i * 3 + 1]! - p[1];
    const dz = positions[i * 3 + 2]! - p[2];
    const d = dx * dx + dy * dy + dz * dz;
    if (d < best && (skip < 0 || d > 0)) {
      best = d;
      index = i;
    }
  }
  return { index, distance: Math.sqrt(best) };
}

/** Distance from `p` to the nearest of `count` points (Infinity for none). */
export function nearestDistance(positions: Float32Array, count: number, p: Vec3): number {
  return nearestPoint(positions, count, p).distance;
}

const short = (x: number) => Number(x.toPrecision(3));

/**
 * Why this viewpoint is suspect, or null; `radius` null: none known yet (see
 * above). `outside`: the job's own answer for a default viewpoint the server
 * placed (a station is never outside, app/default_viewpoints.hpp); without
 * it, whether `p` lies outside `extent` (the server's robust box, when sent).
 */
export function viewpointWarning(
  p: Vec3,
  extent: Bounds,
  cloud: { positions: Float32Array; count: number } | null,
  radius: number | null,
  outside: boolean | null = null,
): string | null {
  if (outside ?? !contains(extent, p)) return "outside the occupied space (the scan's robust box)";
  if (!cloud) return null;
  const { positions, count } = cloud;
  const nearest = nearestPoint(positions, count, p);
  if (nearest.index < 0) return null;
  const away = `inside an object: a scanned point ${nearest.distance.toFixed(3)} m away`;
  if (radius !== null && radius > 0) {
    return nearest.distance < radius ? `${away} (point radius ${short(radius)})` : null;
  }
  const at = nearest.index * 3;
  const point: Vec3 = [positions[at]!, positions[at + 1]!, positions[at + 2]!];
  const spacing = nearestPoint(positions, count, point, nearest.index).distance;
  return Number.isFinite(spacing) && nearest.distance < spacing
    ? `${away} (the point spacing there is ${short(spacing)})`
    : null;
}
