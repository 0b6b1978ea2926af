// The occlusion rays of `cloud_occlusion` as line segments: from each
// viewpoint along each escape direction, one colour per viewpoint.

import { BufferAttribute, BufferGeometry, LineBasicMaterial, LineSegments, Object3D } from "three";
import { segmentColour } from "../decode/colour_maps";
import type { EscapeData, Vec3 } from "../decode/types";

export function rayGeometry(escapes: EscapeData, origins: Vec3[], length: number): BufferGeometry {
  const total = escapes.directions.reduce((n, d) => n + d.length / 3, 0);
  const positions = new Float32Array(total * 6);
  const colours = new Float32Array(total * 6);
  let o = 0;
  escapes.directions.forEach((directions, v) => {
    const origin = origins[v] ?? [0, 0, 0];
    const c = segmentColour(v + 3).map((x) => x / 255);
    for (let i = 0; i + 2 < directions.length; i += 3) {
      const d = [directions[i]!, directions[i + 1]!, directions[i + 2]!];
      for (let a = 0; a < 3; ++a) {
        positions[o + a] = origin[a]!;
        positions[o + 3 + a] = origin[a]! + d[a]! * length;
        colours[o + a] = c[a]!;
        colours[o + 3 + a] = c[a]!;
      }
      o += 6;
    }
  });
  const geometry = new BufferGeometry();
  geometry.setAttribute("position", new BufferAttribute(positions, 3));
  geometry.setAttribute("color", new BufferAttribute(colours, 3));
  return geometry;
}

export class EscapeRays {
  private lines: LineSegments | null = null;

  constructor(private readonly parent: Object3D) {}

  show(escapes: EscapeData, origins: Vec3[], length: number): void {
    this.clear();
    const material = new LineBasicMaterial({
      vertexColors: true,
      transparent: true,
      opacity: 0.55,
    });
    this.lines = new LineSegments(rayGeometry(escapes, origins, length), material);
    this.lines.name = "escape-rays";
    this.parent.add(this.lines);
  }

  set visible(on: boolean) {
    if (this.lines) this.lines.visible = on;
  }

  get count(): number {
    return this.lines ? this.lines.geometry.getAttribute("position").count / 2 : 0;
  }

  clear(): void {
    if (this.lines === null) return;
    this.parent.remove(this.lines);
    this.lines.geometry.dispose();
    (this.lines.material as LineBasicMaterial).dispose();
    this.lines = null;
  }
}
