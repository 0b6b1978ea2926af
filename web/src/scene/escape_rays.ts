// The escape rays of `cloud_occlusion` as line segments, drawn so they can be
// read: at most RAY_DISPLAY.perViewpoint per viewpoint (an even stride through
// each viewpoint's rays, so the picture is the same every time), each clipped
// where it leaves the scene's box, in the colour of its viewpoint's marker.
// Many escapes start hidden (they would cover the canvas); a new result or
// scene clears them.

import { BufferAttribute, BufferGeometry, LineBasicMaterial, LineSegments, Object3D } from "three";
import type { Bounds, EscapeData, Vec3 } from "../decode/types";

/** Distance along `d` from `o` to where the ray leaves `box` (0 when it never is inside). */
export function exitDistance(o: Vec3, d: Vec3, box: Bounds): number {
  let near = 0;
  let far = Infinity;
  for (let a = 0; a < 3; ++a) {
    if (d[a] === 0) {
      if (o[a]! < box.min[a]! || o[a]! > box.max[a]!) return 0;
      continue;
    }
    const t1 = (box.min[a]! - o[a]!) / d[a]!;
    const t2 = (box.max[a]! - o[a]!) / d[a]!;
    near = Math.max(near, Math.min(t1, t2));
    far = Math.min(far, Math.max(t1, t2));
  }
  return far > near ? far : 0;
}

/** Indices of at most `limit` of `n` items, evenly spread (all of them when n ≤ limit). */
export function evenSample(n: number, limit: number): number[] {
  if (n <= limit) return Array.from({ length: n }, (_, i) => i);
  return Array.from({ length: limit }, (_, i) => Math.floor((i * n) / limit));
}

export interface RayViewpoint {
  label: string;
  /** 0..1 RGB, the marker's. */
  colour: Vec3;
}

export interface RaySet {
  geometry: BufferGeometry;
  viewpoints: RayViewpoint[];
  /** Rays drawn per viewpoint, and the escapes the job reported per viewpoint. */
  drawn: number[];
  total: number[];
}

/**
 * Segments from each viewpoint along a sample of its escape directions, ending
 * where they leave `box`, in viewpoint v's colour.
 */
export function rayGeometry(
  escapes: EscapeData,
  origins: Vec3[],
  viewpoints: RayViewpoint[],
  box: Bounds,
  perViewpoint: number,
): RaySet {
  const positions: number[] = [];
  const rgb: number[] = [];
  const drawn: number[] = [];
  const total: number[] = [];
  escapes.directions.forEach((directions, v) => {
    const origin = origins[v] ?? ([0, 0, 0] as Vec3);
    const c = viewpoints[v]?.colour ?? ([1, 1, 1] as Vec3);
    const n = Math.floor(directions.length / 3);
    total.push(n);
    let count = 0;
    for (const i of evenSample(n, perViewpoint)) {
      const d: Vec3 = [directions[i * 3]!, directions[i * 3 + 1]!, directions[i * 3 + 2]!];
      const length = exitDistance(origin, d, box);
      if (length <= 0) continue;
      positions.push(...origin, ...origin.map((x, a) => x + d[a]! * length));
      rgb.push(...c, ...c);
      count += 1;
    }
    drawn.push(count);
  });
  const geometry = new BufferGeometry();
  geometry.setAttribute("position", new BufferAttribute(new Float32Array(positions), 3));
  geometry.setAttribute("color", new BufferAttribute(new Float32Array(rgb), 3));
  return { geometry, viewpoints, drawn, total };
}

export class EscapeRays {
  private lines: LineSegments | null = null;
  private set: RaySet | null = null;
  /** Called when rays appear, are toggled or are cleared (the legend follows). */
  onChange: () => void = () => undefined;

  constructor(private readonly parent: Object3D) {}

  show(
    escapes: EscapeData,
    origins: Vec3[],
    viewpoints: RayViewpoint[],
    box: Bounds,
    perViewpoint: number,
  ): RaySet {
    this.clear();
    const material = new LineBasicMaterial({ vertexColors: true, transparent: true, opacity: 0.7 });
    this.set = rayGeometry(escapes, origins, viewpoints, box, perViewpoint);
    this.lines = new LineSegments(this.set.geometry, material);
    this.lines.name = "escape-rays";
    this.parent.add(this.lines);
    this.onChange();
    return this.set;
  }

  set visible(on: boolean) {
    if (this.lines) this.lines.visible = on;
    this.onChange();
  }

  get visible(): boolean {
    return this.lines?.visible ?? false;
  }

  /** Segments drawn. */
  get count(): number {
    return this.lines ? this.lines.geometry.getAttribute("position").count / 2 : 0;
  }

  get summary(): RaySet | null {
    return this.set;
  }

  /** Colours of the segments drawn (0..1 RGB per segment), for tests. */
  segmentColours(): Vec3[] {
    if (!this.lines) return [];
    const c = this.lines.geometry.getAttribute("color");
    const out: Vec3[] = [];
    for (let i = 0; i < c.count; i += 2) out.push([c.getX(i), c.getY(i), c.getZ(i)]);
    return out;
  }

  clear(): void {
    if (this.lines === null) return;
    this.parent.remove(this.lines);
    this.lines.geometry.dispose();
    (this.lines.material as LineBasicMaterial).dispose();
    this.lines = null;
    this.set = null;
    this.onChange();
  }
}
