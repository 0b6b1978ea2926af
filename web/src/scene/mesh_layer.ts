// A triangle mesh, non-indexed so that each face takes its own colour: plain,
// by OBJ group, or by the visible fraction `mesh_occlusion` computed.

import {
  BufferAttribute,
  BufferGeometry,
  DoubleSide,
  Mesh,
  MeshStandardMaterial,
  Plane,
} from "three";
import type { FaceFractionData, MeshData } from "../decode/types";

export type MeshColourMode = "plain" | "group" | "visible_fraction";

export const MESH_MODE_LABELS: Record<MeshColourMode, string> = {
  plain: "Plain",
  group: "Group",
  visible_fraction: "Visible fraction",
};

export class MeshLayer {
  readonly mesh: Mesh<BufferGeometry, MeshStandardMaterial>;
  readonly geometry = new BufferGeometry();
  readonly material: MeshStandardMaterial;
  private fraction: FaceFractionData | null = null;
  private readonly attributes = new Map<MeshColourMode, BufferAttribute>();
  mode: MeshColourMode = "group";

  constructor(
    readonly data: MeshData,
    clipping: Plane[],
  ) {
    this.geometry.setAttribute("position", new BufferAttribute(data.positions, 3));
    this.geometry.setAttribute("normal", new BufferAttribute(data.normals, 3));
    this.geometry.computeBoundingSphere();
    this.material = new MeshStandardMaterial({
      vertexColors: true,
      side: DoubleSide,
      roughness: 0.85,
      metalness: 0,
      clippingPlanes: clipping,
    });
    this.mesh = new Mesh(this.geometry, this.material);
    this.mesh.name = "mesh";
    this.setMode(data.faceGroups ? "group" : "plain");
  }

  get fractionData(): FaceFractionData | null {
    return this.fraction;
  }

  availableModes(): MeshColourMode[] {
    const modes: MeshColourMode[] = ["plain"];
    if (this.data.faceGroups) modes.push("group");
    if (this.fraction) modes.push("visible_fraction");
    return modes;
  }

  setMode(mode: MeshColourMode): boolean {
    let attribute = this.attributes.get(mode);
    if (attribute === undefined) {
      let colours: Uint8Array | null = null;
      if (mode === "visible_fraction") colours = this.fraction?.colours ?? null;
      else if (mode === "group") colours = this.data.faceGroups ? this.data.groupColours : null;
      else colours = new Uint8Array(this.data.faces * 9).fill(205);
      if (colours === null) return false;
      attribute = new BufferAttribute(colours, 3, true);
      this.attributes.set(mode, attribute);
    }
    this.geometry.setAttribute("color", attribute);
    this.mode = mode;
    return true;
  }

  setFaceFraction(fraction: FaceFractionData): void {
    if (fraction.faces !== this.data.faces) {
      throw new Error(
        `face_visible_fraction: ${fraction.faces} values for ${this.data.faces} faces`,
      );
    }
    this.fraction = fraction;
    this.attributes.delete("visible_fraction");
  }

  dispose(): void {
    this.geometry.dispose();
    this.material.dispose();
  }
}
