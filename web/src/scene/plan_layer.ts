// The plan on the floor: one square per candidate station, coloured by the
// share it would still add (heatColour: the best next station is the ramp's
// top), at the floor under it. A click on a square names its candidate.

import {
  BufferGeometry,
  Color,
  DoubleSide,
  InstancedMesh,
  Matrix4,
  MeshBasicMaterial,
  Object3D,
  PlaneGeometry,
  SRGBColorSpace,
} from "three";
import type { Vec3 } from "../decode/types";
import { heatColour } from "../decode/colour_maps";

export class PlanLayer {
  private squares: InstancedMesh<BufferGeometry, MeshBasicMaterial> | null = null;

  constructor(private readonly overlays: Object3D) {}

  /**
   * Squares of `size` at each candidate's floor: its position lowered by the
   * scanner `height` along z (the viewer's up).
   */
  show(
    positions: readonly Vec3[],
    gainLeft: readonly number[],
    size: number,
    height: number,
  ): void {
    this.clear();
    if (positions.length === 0) return;
    const geometry = new PlaneGeometry(size, size);
    const material = new MeshBasicMaterial({
      side: DoubleSide,
      transparent: true,
      opacity: 0.85,
      depthWrite: false,
    });
    const squares = new InstancedMesh(geometry, material, positions.length);
    squares.name = "plan-candidates";
    const largest = Math.max(0, ...gainLeft);
    const matrix = new Matrix4();
    const colour = new Color();
    positions.forEach((p, i) => {
      matrix.makeTranslation(p[0], p[1], p[2] - height + size * 0.02);
      squares.setMatrixAt(i, matrix);
      const [r, g, b] = heatColour(gainLeft[i] ?? 0, largest);
      squares.setColorAt(i, colour.setRGB(r / 255, g / 255, b / 255, SRGBColorSpace));
    });
    squares.instanceMatrix.needsUpdate = true;
    if (squares.instanceColor) squares.instanceColor.needsUpdate = true;
    squares.renderOrder = 1;
    this.overlays.add(squares);
    this.squares = squares;
  }

  /** What a click can hit (the squares), empty without a plan. */
  pickables(): Object3D[] {
    return this.squares ? [this.squares] : [];
  }

  get shown(): number {
    return this.squares?.count ?? 0;
  }

  clear(): void {
    if (!this.squares) return;
    this.squares.removeFromParent();
    this.squares.geometry.dispose();
    this.squares.material.dispose();
    this.squares.dispose();
    this.squares = null;
  }
}
