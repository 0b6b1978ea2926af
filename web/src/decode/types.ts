// What the decode worker hands back: arrays ready to become BufferGeometry
// attributes, plus the few figures the UI needs (bounds, counts, ranges).

export type Vec3 = [number, number, number];

export interface Bounds {
  min: Vec3;
  max: Vec3;
}

export interface CloudData {
  kind: "cloud";
  count: number;
  positions: Float32Array;
  bounds: Bounds;
  /** RGB 0..255 per point, or null when the file has none. */
  colours: Uint8Array | null;
  labels: Int32Array | null;
  instances: Int32Array | null;
  /** Per-point RGB by semantic class (labels index `classNames`). */
  classColours: Uint8Array | null;
  /** Per-point RGB by instance (segment) id. */
  segmentColours: Uint8Array | null;
  /**
   * For big clouds, a random permutation of the point indices: drawing its
   * first k entries shows an even 1/(N/k) sample (level of detail while
   * the camera moves). Null for clouds small enough to draw whole.
   */
  order: Uint32Array | null;
  classNames: string[];
  /** Points per class index; `unlabelled` counts label −1 or out of range. */
  classCounts: number[];
  unlabelled: number;
  segments: number;
}

export interface MeshData {
  kind: "mesh";
  faces: number;
  vertices: number;
  /** Non-indexed: 3 vertices per face, so each face can take its own colour. */
  positions: Float32Array;
  normals: Float32Array;
  faceGroups: Uint32Array | null;
  /** Per-vertex RGB (faces × 3 vertices) by face group. */
  groupColours: Uint8Array;
  /** Group names (OBJ g/o); empty for meshes estimated from clouds. */
  groups: string[];
  /** Distinct face groups. */
  groupCount: number;
  bounds: Bounds;
}

export interface FaceFractionData {
  kind: "face_fraction";
  faces: number;
  fraction: Float32Array;
  /** Per-vertex RGB (faces × 3 vertices) on the ramp. */
  colours: Uint8Array;
  min: number;
  max: number;
  mean: number;
}

export interface VisibilityData {
  kind: "visibility";
  count: number;
  visibleCount: Uint16Array;
  colours: Uint8Array;
  /** Colour scale top: the number of viewpoints (or the largest count). */
  max: number;
  /** histogram[k] = points seen by k viewpoints. */
  histogram: number[];
  /**
   * -fscan's covered_by: the number (from 1, in the report's viewpoints) of
   * the first viewpoint that sees each point, −1 none; null when not sent
   * (the live station's single view).
   */
  firstStation: Int32Array | null;
  /** Per-point RGB by that viewpoint (stationColour), unseen red; null with it. */
  firstColours: Uint8Array | null;
}

/** plan: per target (a cloud's point, a mesh's sample), the first station that sees it. */
export interface CoveredByData {
  kind: "covered_by";
  count: number;
  /** The rank (from 1) of the first station that sees the target, −1 none. */
  rank: Int32Array;
  /** Per-target RGB: the station's colour (stationColour), unseen red. */
  colours: Uint8Array;
  /** covered[k] = targets first covered by station k (k from 1); covered[0] = by none. */
  covered: number[];
}

export interface EscapeData {
  kind: "escapes";
  /** Unit directions (x y z …) of each viewpoint's occlusion rays, by item. */
  directions: Float32Array[];
  total: number;
}

/**
 * region_growing_occlusion (the estimated mesh, its visible fractions, the
 * points' clusters) and extract_polygons (the planes as a mesh, the clusters;
 * no fractions).
 */
export interface RegionGrowingData {
  kind: "region_growing";
  mesh: MeshData;
  fraction: FaceFractionData | null;
  /** Per input point: its cluster (= the mesh's group), −1 none. */
  clusters: Int32Array | null;
  /** Per-point RGB, the same colour as the cluster's mesh group. */
  clusterColours: Uint8Array | null;
}

export type Decoded =
  | CloudData
  | MeshData
  | FaceFractionData
  | VisibilityData
  | EscapeData
  | RegionGrowingData
  | CoveredByData;

/** Context the result gives the assembler (class names, number of viewpoints). */
export interface AssembleContext {
  classNames?: string[];
  groups?: string[];
  viewpoints?: number;
}

/** The arrays of a decoded value, to transfer (not copy) across postMessage. */
export function transferables(value: Decoded | null): ArrayBuffer[] {
  if (value === null) return [];
  const arrays: (ArrayBufferView | null)[] = [];
  switch (value.kind) {
    case "cloud":
      arrays.push(
        value.positions,
        value.colours,
        value.labels,
        value.instances,
        value.classColours,
        value.segmentColours,
        value.order,
      );
      break;
    case "mesh":
      arrays.push(value.positions, value.normals, value.faceGroups, value.groupColours);
      break;
    case "face_fraction":
      arrays.push(value.fraction, value.colours);
      break;
    case "visibility":
      arrays.push(value.visibleCount, value.colours, value.firstStation, value.firstColours);
      break;
    case "escapes":
      arrays.push(...value.directions);
      break;
    case "covered_by":
      arrays.push(value.rank, value.colours);
      break;
    case "region_growing":
      return [
        ...new Set([
          ...transferables(value.mesh),
          ...transferables(value.fraction ?? null),
          ...[value.clusters, value.clusterColours].flatMap((a) =>
            a !== null && a.buffer instanceof ArrayBuffer ? [a.buffer] : [],
          ),
        ]),
      ];
  }
  const buffers = new Set<ArrayBuffer>();
  for (const a of arrays) if (a !== null && a.buffer instanceof ArrayBuffer) buffers.add(a.buffer);
  return [...buffers];
}

/** Bytes held by a decoded value (for the cache-size figure). */
export function byteSize(value: Decoded | null): number {
  if (value === null) return 0;
  const buffers = transferables(value);
  return buffers.reduce((sum, b) => sum + b.byteLength, 0);
}
