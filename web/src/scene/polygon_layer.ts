// Openings picked on the cloud: the polygon being built (picked points as
// spheres and an open outline) and the saved ones (closed outline + fill).

import {
  BufferAttribute,
  BufferGeometry,
  DoubleSide,
  Group,
  Line,
  LineBasicMaterial,
  LineLoop,
  Mesh,
  MeshBasicMaterial,
  Object3D,
  SphereGeometry,
} from "three";
import type { Vec3 } from "../decode/types";
import type { PickerMaterials } from "./picker_material";

function lineGeometry(points: Vec3[]): BufferGeometry {
  const geometry = new BufferGeometry();
  geometry.setAttribute("position", new BufferAttribute(new Float32Array(points.flat()), 3));
  return geometry;
}

/** Fan triangulation of a polygon's outline (right for convex openings). */
function fillGeometry(points: Vec3[]): BufferGeometry {
  const triangles: number[] = [];
  for (let i = 1; i + 1 < points.length; ++i) {
    triangles.push(...points[0]!, ...points[i]!, ...points[i + 1]!);
  }
  const geometry = new BufferGeometry();
  geometry.setAttribute("position", new BufferAttribute(new Float32Array(triangles), 3));
  return geometry;
}

export class PolygonLayer {
  readonly group = new Group();
  private readonly draft = new Group();
  private readonly saved = new Group();
  private readonly sphere = new SphereGeometry(1, 16, 12);
  points: Vec3[] = [];
  private size = 0.05;

  constructor(
    overlays: Object3D,
    private readonly materials: PickerMaterials,
  ) {
    this.group.name = "openings";
    this.group.add(this.saved, this.draft);
    overlays.add(this.group);
  }

  setPickerSize(size: number): void {
    this.size = size;
    this.redraw();
  }

  add(point: Vec3): void {
    this.points.push(point);
    this.redraw();
  }

  undo(): void {
    this.points.pop();
    this.redraw();
  }

  clearDraft(): void {
    this.points = [];
    this.redraw();
  }

  /** Moves the draft to the saved polygons (drawn closed and filled). */
  commit(): Vec3[] {
    const polygon = this.points;
    this.points = [];
    this.addSaved(polygon);
    this.redraw();
    return polygon;
  }

  /** Draws exactly these openings (those of the file in use), replacing the saved ones drawn. */
  showSaved(polygons: Vec3[][]): void {
    this.clearSaved();
    for (const polygon of polygons) this.addSaved(polygon);
  }

  /** Openings drawn (closed and filled). */
  get savedCount(): number {
    return this.saved.children.length / 2;
  }

  private addSaved(polygon: Vec3[]): void {
    const outline = new LineLoop(
      lineGeometry(polygon),
      new LineBasicMaterial({ color: 0x2ec4b6, depthTest: false }),
    );
    const fill = new Mesh(
      fillGeometry(polygon),
      new MeshBasicMaterial({
        color: 0x2ec4b6,
        transparent: true,
        opacity: 0.28,
        side: DoubleSide,
        depthWrite: false,
      }),
    );
    outline.renderOrder = fill.renderOrder = 10;
    this.saved.add(outline, fill);
  }

  clearSaved(): void {
    for (const child of [...this.saved.children]) {
      this.saved.remove(child);
      const object = child as Mesh;
      object.geometry.dispose();
      (object.material as MeshBasicMaterial).dispose();
    }
  }

  /** Re-applies the picker material (shader toggled). */
  redraw(): void {
    for (const child of [...this.draft.children]) {
      this.draft.remove(child);
      if (child instanceof Line) child.geometry.dispose();
    }
    for (const p of this.points) {
      const marker = new Mesh(this.sphere, this.materials.current);
      marker.position.set(...p);
      marker.scale.setScalar(this.size);
      marker.renderOrder = 20;
      this.draft.add(marker);
    }
    if (this.points.length >= 2) {
      const line = new Line(
        lineGeometry(this.points.length >= 3 ? [...this.points, this.points[0]!] : this.points),
        new LineBasicMaterial({ color: 0xff9f1c, depthTest: false }),
      );
      line.renderOrder = 19;
      this.draft.add(line);
    }
  }
}
