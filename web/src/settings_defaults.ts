// Every computation setting the viewer offers, declared once: the job key it
// sets, its default, range, step, unit and what it means. The GUI panel,
// the evaluate dialog and the jobs read these and nothing else.
//
// Today the declarations are the viewer's own copy of the server's defaults.
// When `hello` publishes each command's key declarations (issue 11), call
// `adoptServerKeys(hello)`: a key the server declares overrides the default,
// range and doc here (same names), and the viewer follows the server.

export interface SettingDeclaration {
  /** The job parameter (the JSON config key). */
  key: string;
  default: number;
  min: number;
  max: number;
  step: number;
  unit: string;
  doc: string;
}

export type SettingName =
  | "raysPerViewpoint"
  | "pointRadius"
  | "samplesPerUnitArea"
  | "maxDistance"
  | "minClusterSize"
  | "maxClusterSize";

export const SETTINGS: Record<SettingName, SettingDeclaration> = {
  raysPerViewpoint: {
    key: "num_rays_per_vp",
    default: 20000,
    min: 1000,
    max: 200000,
    step: 1000,
    unit: "rays",
    doc: "Rays cast from each viewpoint (-poc).",
  },
  pointRadius: {
    key: "point_radius",
    default: 0.06,
    min: 0.005,
    max: 0.3,
    step: 0.001,
    unit: "m",
    doc: "Radius of the sphere that stands for each point when rays are traced.",
  },
  samplesPerUnitArea: {
    key: "samples_per_unit_area",
    default: 20,
    min: 1,
    max: 200,
    step: 1,
    unit: "1/m²",
    doc: "Surface samples per square metre of mesh (-moc, -rgoc).",
  },
  maxDistance: {
    key: "max_distance",
    default: 0.05,
    min: 0,
    max: 1,
    step: 0.01,
    unit: "m",
    doc: "Evaluate: a prediction point further than this from the ground truth is not matched.",
  },
  minClusterSize: {
    key: "min_cluster_size",
    default: 100,
    min: 1,
    max: 100000,
    step: 1,
    unit: "points",
    doc: "Region growing: smaller regions are dropped (-rgoc, Extract Polygons).",
  },
  maxClusterSize: {
    key: "max_cluster_size",
    default: 100000,
    min: 100,
    max: 10000000,
    step: 100,
    unit: "points",
    doc: "Region growing: larger regions are dropped (-rgoc, Extract Polygons).",
  },
};

/** Declarations as `hello` may carry them (issue 11): per command, per key. */
interface ServerKey {
  default?: unknown;
  min?: unknown;
  max?: unknown;
  doc?: unknown;
  unit?: unknown;
}

/**
 * Takes defaults, ranges and docs from the server's key declarations where it
 * has them (`hello.keys[command][key]` or `hello.commands[command].keys[key]`);
 * returns the names that changed.
 */
export function adoptServerKeys(hello: Record<string, unknown>): SettingName[] {
  const found = new Map<string, ServerKey>();
  const collect = (keys: unknown) => {
    if (typeof keys !== "object" || keys === null) return;
    for (const [k, v] of Object.entries(keys)) {
      if (typeof v === "object" && v !== null && !found.has(k)) found.set(k, v as ServerKey);
    }
  };
  const perCommand = (source: unknown, inner: boolean) => {
    if (typeof source !== "object" || source === null) return;
    for (const c of Object.values(source)) collect(inner ? (c as { keys?: unknown })?.keys : c);
  };
  perCommand(hello.keys, false);
  perCommand(hello.commands, true);
  const changed: SettingName[] = [];
  for (const [name, d] of Object.entries(SETTINGS) as [SettingName, SettingDeclaration][]) {
    const k = found.get(d.key);
    if (!k) continue;
    const num = (v: unknown) => (typeof v === "number" && Number.isFinite(v) ? v : undefined);
    d.default = num(k.default) ?? d.default;
    d.min = num(k.min) ?? d.min;
    d.max = num(k.max) ?? d.max;
    if (typeof k.doc === "string") d.doc = k.doc;
    if (typeof k.unit === "string") d.unit = k.unit;
    changed.push(name);
  }
  return changed;
}

/** How many escape rays per viewpoint are drawn at most, and above how many in all they start hidden. */
export const RAY_DISPLAY = { perViewpoint: 400, hiddenAbove: 3000 };
