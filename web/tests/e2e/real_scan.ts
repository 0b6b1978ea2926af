// A real-like laser scan of a room, as a binary PLY of x y z only (no colour,
// no labels): a 6 × 5 × 3 m shell with a window and a door left open, a table,
// sampled uniformly by area with a fixed seed, plus 1 % stray points 15 to 60 m
// away (reflections, passers-by) that a naive bounding box would frame.

import { mkdirSync, writeFileSync } from "node:fs";
import { dirname } from "node:path";

export const ROOM = { min: [0, 0, 0], max: [6, 5, 3] } as const;
type V = [number, number, number];

interface Patch {
  origin: V;
  u: V;
  v: V;
  /** Holes in (a, b) patch coordinates, 0..1. */
  holes: [number, number, number, number][];
}

export function writeRealLikeScan(path: string, roomPoints = 60_000, strayFraction = 0.01): number {
  const [W, D, H] = [6, 5, 3];
  const patches: Patch[] = [
    { origin: [0, 0, 0], u: [W, 0, 0], v: [0, D, 0], holes: [] },
    { origin: [0, 0, H], u: [W, 0, 0], v: [0, D, 0], holes: [] },
    { origin: [0, 0, 0], u: [W, 0, 0], v: [0, 0, H], holes: [] },
    // The window: x 2–4 m, z 1–2 m in the far wall.
    { origin: [0, D, 0], u: [W, 0, 0], v: [0, 0, H], holes: [[2 / W, 4 / W, 1 / H, 2 / H]] },
    // The door: y 1–2 m, z 0–2.1 m in the left wall.
    { origin: [0, 0, 0], u: [0, D, 0], v: [0, 0, H], holes: [[1 / D, 2 / D, 0, 2.1 / H]] },
    { origin: [W, 0, 0], u: [0, D, 0], v: [0, 0, H], holes: [] },
    { origin: [2, 1.5, 0.75], u: [2, 0, 0], v: [0, 1, 0], holes: [] },
  ];
  const area = (p: Patch) => Math.hypot(...p.u) * Math.hypot(...p.v);
  const total = patches.reduce((s, p) => s + area(p), 0);
  let seed = 2024;
  const random = () => {
    seed = (seed * 1664525 + 1013904223) >>> 0;
    return seed / 4294967296;
  };
  const points: V[] = [];
  for (const p of patches) {
    const n = Math.round((roomPoints * area(p)) / total);
    for (let i = 0; i < n;) {
      const a = random();
      const b = random();
      if (p.holes.some(([a0, a1, b0, b1]) => a > a0 && a < a1 && b > b0 && b < b1)) continue;
      points.push([0, 1, 2].map((c) => p.origin[c]! + a * p.u[c]! + b * p.v[c]!) as V);
      ++i;
    }
  }
  const strays = Math.round(points.length * strayFraction);
  for (let i = 0; i < strays; ++i) {
    const t = random() * Math.PI * 2;
    const z = random() * 2 - 1;
    const r = 15 + random() * 45;
    const s = Math.sqrt(1 - z * z);
    points.push([W / 2 + r * s * Math.cos(t), D / 2 + r * s * Math.sin(t), H / 2 + r * z]);
  }
  const header =
    "ply\nformat binary_little_endian 1.0\ncomment real-like scan for the viewer's e2e test\n" +
    `element vertex ${points.length}\nproperty float x\nproperty float y\nproperty float z\nend_header\n`;
  const body = Buffer.alloc(points.length * 12);
  points.forEach((p, i) => p.forEach((x, c) => body.writeFloatLE(x, i * 12 + c * 4)));
  mkdirSync(dirname(path), { recursive: true });
  writeFileSync(path, Buffer.concat([Buffer.from(header, "ascii"), body]));
  return points.length;
}
