// A point cloud as THREE.Points, with one colour attribute per colouring
// (RGB, semantic class, segment, per-point visibility, height), built once
// from the worker's arrays and swapped on demand.

import {
  BufferAttribute,
  BufferGeometry,
  CanvasTexture,
  Plane,
  Points,
  PointsMaterial,
  Texture,
} from "three";
import { paintFirstViewpoint } from "../decode/assemble";
import { ramp } from "../decode/colour_maps";
import type { Rgb } from "../decode/colour_maps";
import type { Bounds, CloudData, VisibilityData } from "../decode/types";

export type CloudColourMode =
  "rgb" | "class" | "segment" | "visibility" | "first" | "cluster" | "height";

export const CLOUD_MODE_LABELS: Record<CloudColourMode, string> = {
  rgb: "RGB",
  class: "Semantic class",
  segment: "Segment id",
  visibility: "Visibility (viewpoints that see it)",
  first: "First viewpoint that sees it",
  cluster: "Region cluster",
  height: "Height",
};

/** A point size that roughly closes the surfaces: the mean spacing on the box's faces. */
export function suggestedPointSize(count: number, extent: Bounds): number {
  const [a, b] = [extent.min, extent.max];
  const dx = b[0] - a[0],
    dy = b[1] - a[1],
    dz = b[2] - a[2];
  const area = 2 * (dx * dy + dy * dz + dx * dz) || 1;
  const spacing = Math.sqrt(area / Math.max(1, count));
  return Math.max(1e-4, spacing * 1.2);
}

/** Height on the ramp across the robust extent (stray points clamp to its ends). */
function heightColours(data: CloudData, extent: Bounds): Uint8Array {
  const out = new Uint8Array(data.count * 3);
  const z0 = extent.min[2];
  const span = extent.max[2] - z0 || 1;
  for (let i = 0; i < data.count; ++i) {
    const c = ramp((data.positions[i * 3 + 2]! - z0) / span);
    out[i * 3] = c[0];
    out[i * 3 + 1] = c[1];
    out[i * 3 + 2] = c[2];
  }
  return out;
}

let disc: Texture | null = null;

/** A white disc with a soft rim: round points instead of squares (alpha-tested). */
function discTexture(): Texture {
  if (disc) return disc;
  const canvas = document.createElement("canvas");
  canvas.width = canvas.height = 64;
  const g = canvas.getContext("2d")!;
  g.fillStyle = "#fff";
  g.beginPath();
  g.arc(32, 32, 30, 0, Math.PI * 2);
  g.fill();
  disc = new CanvasTexture(canvas);
  return disc;
}

export class CloudLayer {
  readonly points: Points<BufferGeometry, PointsMaterial>;
  readonly geometry = new BufferGeometry();
  readonly material: PointsMaterial;
  private visibility: VisibilityData | null = null;
  private clusters: Uint8Array | null = null;
  private readonly attributes = new Map<CloudColourMode, BufferAttribute>();
  mode: CloudColourMode;

  constructor(
    readonly data: CloudData,
    pointSize: number,
    clipping: Plane[],
    readonly extent: Bounds = data.bounds,
  ) {
    this.geometry.setAttribute("position", new BufferAttribute(data.positions, 3));
    // Big clouds are drawn through a random permutation, so that the first
    // 1/2^level of it is an even sample of the cloud (see setDetail).
    if (data.order) this.geometry.setIndex(new BufferAttribute(data.order, 1));
    this.geometry.computeBoundingSphere();
    this.geometry.computeBoundingBox();
    this.material = new PointsMaterial({
      size: pointSize,
      vertexColors: true,
      sizeAttenuation: true,
      map: discTexture(),
      alphaTest: 0.5,
      clippingPlanes: clipping,
    });
    this.points = new Points(this.geometry, this.material);
    this.points.name = "cloud";
    this.mode = data.colours ? "rgb" : data.classColours ? "class" : "height";
    this.setMode(this.mode);
  }

  get hasVisibility(): boolean {
    return this.visibility !== null;
  }

  get visibilityData(): VisibilityData | null {
    return this.visibility;
  }

  availableModes(): CloudColourMode[] {
    const modes: CloudColourMode[] = [];
    if (this.data.colours) modes.push("rgb");
    if (this.data.classColours) modes.push("class");
    if (this.data.segmentColours) modes.push("segment");
    if (this.visibility) modes.push("visibility");
    if (this.visibility?.firstColours) modes.push("first");
    if (this.clusters) modes.push("cluster");
    modes.push("height");
    return modes;
  }

  has(mode: CloudColourMode): boolean {
    return this.availableModes().includes(mode);
  }

  private colours(mode: CloudColourMode): Uint8Array | null {
    switch (mode) {
      case "rgb":
        return this.data.colours;
      case "class":
        return this.data.classColours;
      case "segment":
        return this.data.segmentColours;
      case "visibility":
        return this.visibility?.colours ?? null;
      case "first":
        return this.visibility?.firstColours ?? null;
      case "cluster":
        return this.clusters;
      case "height":
        return heightColours(this.data, this.extent);
    }
  }

  /** Switches the colouring; false (and no change) if the cloud lacks it. */
  setMode(mode: CloudColourMode): boolean {
    let attribute = this.attributes.get(mode);
    if (attribute === undefined) {
      const colours = this.colours(mode);
      if (colours === null) return false;
      attribute = new BufferAttribute(colours, 3, true);
      this.attributes.set(mode, attribute);
    }
    this.geometry.setAttribute("color", attribute);
    this.mode = mode;
    return true;
  }

  /** The names of the viewpoints a visibility's first-viewpoint numbers count (from 1). */
  visibilityNames: string[] = [];
  /** Their colours, where known (firstViewpointColour). */
  visibilityColours: Rgb[] = [];

  setVisibility(visibility: VisibilityData, names: string[] = [], colours: Rgb[] = []): void {
    if (visibility.count !== this.data.count) {
      throw new Error(
        `visibility: ${visibility.count} counts for a cloud of ${this.data.count} points`,
      );
    }
    // The decoder painted the first viewpoints in the numbered colours; the
    // viewpoints' own (their markers') replace them.
    this.visibility =
      colours.length > 0 && visibility.firstStation !== null
        ? { ...visibility, firstColours: paintFirstViewpoint(visibility.firstStation, colours) }
        : visibility;
    this.visibilityNames = names;
    this.visibilityColours = colours;
    this.attributes.delete("visibility");
    this.attributes.delete("first");
  }

  /** Levels of detail available: level k draws 1/2^k of the points. */
  get detailLevels(): number {
    if (!this.data.order) return 0;
    // Down to about 2,000 points, never fewer than 1/256 of the cloud: software
    // rendering (no GPU) can need that to orbit a 100k-point scan smoothly.
    return Math.min(8, Math.max(0, Math.floor(Math.log2(this.data.count / 2_000))));
  }

  setDetail(level: number): void {
    const count = level <= 0 ? Infinity : Math.ceil(this.data.count / 2 ** level);
    this.geometry.setDrawRange(0, count);
  }

  /** Per-point colours of the region-growing clusters (region_growing_occlusion). */
  setClusters(colours: Uint8Array): void {
    if (colours.length !== this.data.count * 3) {
      throw new Error(`point_clusters: ${colours.length / 3} values for ${this.data.count} points`);
    }
    this.clusters = colours;
    this.attributes.delete("cluster");
  }

  /** Runs `fn` with every point drawn (picking must see the whole cloud, whatever the level). */
  withFullDetail<T>(fn: () => T): T {
    const range = { ...this.geometry.drawRange };
    this.geometry.setDrawRange(0, Infinity);
    try {
      return fn();
    } finally {
      this.geometry.setDrawRange(range.start, range.count);
    }
  }

  setPointSize(size: number): void {
    this.material.size = size;
  }

  dispose(): void {
    this.geometry.dispose();
    this.material.dispose();
  }
}
