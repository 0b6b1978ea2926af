// Is a picked opening a polygon the occlusion job can use? At least three
// distinct points, on one plane (within a tolerance, picked points are
// noisy), enclosing an area, and a boundary that does not cross itself (a
// bow tie has no inside). Returns the reason it is refused, or null.

import type { Vec3 } from "./types";

const sub = (a: Vec3, b: Vec3): Vec3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a: Vec3, b: Vec3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const norm = (a: Vec3) => Math.sqrt(dot(a, a));

/** Newell's normal: its length is twice the polygon's (projected) area. */
export function newellNormal(points: Vec3[]): Vec3 {
  const n: Vec3 = [0, 0, 0];
  points.forEach((p, i) => {
    const q = points[(i + 1) % points.length]!;
    n[0] += (p[1] - q[1]) * (p[2] + q[2]);
    n[1] += (p[2] - q[2]) * (p[0] + q[0]);
    n[2] += (p[0] - q[0]) * (p[1] + q[1]);
  });
  return n;
}

/** True when 2-D segments ab and cd cross or touch. */
export function segmentsCross(
  a: [number, number],
  b: [number, number],
  c: [number, number],
  d: [number, number],
): boolean {
  const orient = (p: [number, number], q: [number, number], r: [number, number]) =>
    (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
  const o1 = orient(a, b, c);
  const o2 = orient(a, b, d);
  const o3 = orient(c, d, a);
  const o4 = orient(c, d, b);
  return o1 * o2 <= 0 && o3 * o4 <= 0;
}

/**
 * Why `points` (in boundary order) is not a usable opening, or null.
 * `planarity`: the largest distance off the polygon's plane allowed, as a
 * fraction of its size.
 */
export function polygonProblem(points: Vec3[], planarity = 0.1): string | null {
  if (points.length < 3) return `an opening needs at least 3 points, it has ${points.length}`;
  const size = Math.max(...points.flatMap((p) => points.map((q) => norm(sub(p, q)))));
  const eps = size * 1e-6;
  for (let i = 0; i < points.length; ++i) {
    const next = points[(i + 1) % points.length]!;
    if (norm(sub(points[i]!, next)) <= eps) {
      return `points ${i + 1} and ${((i + 1) % points.length) + 1} are the same point`;
    }
  }
  // The plane's normal from the widest corner (a bow tie's Newell normal is zero).
  let normal: Vec3 = [0, 0, 0];
  let widest = 0;
  for (let i = 1; i < points.length; ++i) {
    for (let j = i + 1; j < points.length; ++j) {
      const a = sub(points[i]!, points[0]!);
      const b = sub(points[j]!, points[0]!);
      const c: Vec3 = [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
      ];
      if (norm(c) > widest) [widest, normal] = [norm(c), c];
    }
  }
  if (widest <= size * size * 1e-4) return "the points are on one line: the polygon has no area";
  const unit = normal.map((x) => x / widest) as Vec3;
  const centre = points
    .reduce((s, p) => [s[0] + p[0], s[1] + p[1], s[2] + p[2]] as Vec3, [0, 0, 0] as Vec3)
    .map((x) => x / points.length) as Vec3;
  let worst = 0;
  let worstIndex = 0;
  points.forEach((p, i) => {
    const d = Math.abs(dot(sub(p, centre), unit));
    if (d > worst) [worst, worstIndex] = [d, i];
  });
  if (worst > planarity * size) {
    return (
      `the points are not on one plane: point ${worstIndex + 1} is ${worst.toFixed(3)} off it ` +
      "(pick the opening's corners on one wall)"
    );
  }
  // Into the plane's 2-D coordinates, then look for crossing edges.
  const u = sub(points[1]!, points[0]!);
  const uu = u.map((x) => x / norm(u)) as Vec3;
  const v: Vec3 = [
    unit[1] * uu[2] - unit[2] * uu[1],
    unit[2] * uu[0] - unit[0] * uu[2],
    unit[0] * uu[1] - unit[1] * uu[0],
  ];
  const flat = points.map(
    (p) => [dot(sub(p, centre), uu), dot(sub(p, centre), v)] as [number, number],
  );
  const m = flat.length;
  for (let i = 0; i < m; ++i) {
    for (let j = i + 1; j < m; ++j) {
      const adjacent = j === i + 1 || (i === 0 && j === m - 1);
      if (adjacent) continue;
      if (segmentsCross(flat[i]!, flat[(i + 1) % m]!, flat[j]!, flat[(j + 1) % m]!)) {
        return (
          `the boundary crosses itself (edge ${i + 1}–${((i + 1) % m) + 1} and edge ` +
          `${j + 1}–${((j + 1) % m) + 1}): pick the corners in order around the opening`
        );
      }
    }
  }
  const area = norm(newellNormal(points)) / 2;
  if (area <= size * size * 1e-4) return "the polygon has no area";
  return null;
}
