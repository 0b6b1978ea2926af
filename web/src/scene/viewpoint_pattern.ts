// The seed's viewpoint pattern on a bounding box (README, -moc --pattern):
// C the centre, U the midpoint between the centre and the max corner, L the
// midpoint between the centre and the min corner.

import type { Bounds, Vec3 } from "../decode/types";

export type ViewpointName = "centre" | "max" | "min";

export function patternPoints(bounds: Bounds): Record<ViewpointName, Vec3> {
  const c = [0, 1, 2].map((a) => (bounds.min[a]! + bounds.max[a]!) / 2) as Vec3;
  const mid = (p: Vec3) => [0, 1, 2].map((a) => (c[a]! + p[a]!) / 2) as Vec3;
  return { centre: c, max: mid(bounds.max), min: mid(bounds.min) };
}
