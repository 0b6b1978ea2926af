// A synthetic labelled room of N points as a binary PLY, in the layout
// `occlusion` writes (class names in header comments): floor, ceiling, four
// walls and a grid of tables, sampled uniformly by area with a fixed seed.

import { mkdirSync, writeFileSync } from "node:fs";
import { dirname } from "node:path";

const CLASSES = [
  "ceiling",
  "floor",
  "wall",
  "beam",
  "column",
  "window",
  "door",
  "table",
  "chair",
  "sofa",
  "bookcase",
  "board",
  "clutter",
];

interface Patch {
  origin: [number, number, number];
  u: [number, number, number];
  v: [number, number, number];
  label: number;
  colour: [number, number, number];
}

function quad(
  origin: [number, number, number],
  u: [number, number, number],
  v: [number, number, number],
  label: number,
  colour: [number, number, number],
): Patch {
  return { origin, u, v, label, colour };
}

export function writeMillionPointRoom(path: string, count = 1_000_000): void {
  const [W, D, H] = [12, 10, 3.5];
  const patches: Patch[] = [
    quad([0, 0, 0], [W, 0, 0], [0, D, 0], 1, [150, 140, 120]),
    quad([0, 0, H], [W, 0, 0], [0, D, 0], 0, [235, 235, 230]),
    quad([0, 0, 0], [W, 0, 0], [0, 0, H], 2, [200, 205, 210]),
    quad([0, D, 0], [W, 0, 0], [0, 0, H], 2, [200, 205, 210]),
    quad([0, 0, 0], [0, D, 0], [0, 0, H], 2, [190, 195, 205]),
    quad([W, 0, 0], [0, D, 0], [0, 0, H], 2, [190, 195, 205]),
  ];
  for (let i = 0; i < 4; ++i) {
    for (let j = 0; j < 3; ++j) {
      patches.push(
        quad([1.5 + i * 2.6, 1.5 + j * 2.8, 0.75], [1.6, 0, 0], [0, 0.9, 0], 7, [140, 90, 50]),
      );
    }
  }
  const areas = patches.map((p) => Math.hypot(...p.u) * Math.hypot(...p.v));
  const total = areas.reduce((a, b) => a + b, 0);
  let seed = 12345;
  const random = () => {
    seed = (seed * 1664525 + 1013904223) >>> 0;
    return seed / 4294967296;
  };
  const header =
    "ply\nformat binary_little_endian 1.0\ncomment written by the occlusion viewer e2e test\n" +
    CLASSES.map((c, i) => `comment class ${i} ${c}\n`).join("") +
    `element vertex ${count}\nproperty float x\nproperty float y\nproperty float z\n` +
    "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty int label\nproperty int instance\nend_header\n";
  const stride = 12 + 3 + 8;
  const body = Buffer.alloc(count * stride);
  let written = 0;
  patches.forEach((p, k) => {
    const n = k === patches.length - 1 ? count - written : Math.round((count * areas[k]!) / total);
    for (let i = 0; i < n && written < count; ++i, ++written) {
      const a = random();
      const b = random();
      const o = written * stride;
      for (let c = 0; c < 3; ++c)
        body.writeFloatLE(p.origin[c]! + a * p.u[c]! + b * p.v[c]!, o + c * 4);
      const shade = 0.85 + 0.3 * random();
      for (let c = 0; c < 3; ++c)
        body.writeUInt8(Math.min(255, Math.round(p.colour[c]! * shade)), o + 12 + c);
      body.writeInt32LE(p.label, o + 15);
      body.writeInt32LE(k, o + 19);
    }
  });
  mkdirSync(dirname(path), { recursive: true });
  writeFileSync(path, Buffer.concat([Buffer.from(header, "ascii"), body]));
}
