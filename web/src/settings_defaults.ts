// Every computation setting the viewer offers, declared once: the job key it
// sets, its default, range, step, unit and what it means. The GUI panel,
// the evaluate dialog and the jobs read these and nothing else.
//
// The numbers here are the viewer's fallbacks until the server's `hello`
// arrives: `adoptServerKeys(hello)` takes each declared key's default, range,
// choices and doc (same names), and the viewer follows the server. A choice
// (CHOICES) has none of its own: its default and choices come only from hello.
// The cloud jobs send only what the user set (`cloudJobParams`), so whatever
// the user leaves alone takes the server's default.

export interface SettingDeclaration {
  /** The job parameter (the JSON config key). */
  key: string;
  /** The slider's starting value (for an `auto` key: only where the slider starts). */
  default: number;
  /**
   * The server's default is "auto" (the server chooses the value, e.g. point
   * radii from the cloud's density): the viewer sends the key only when the
   * user sets a number.
   */
  auto?: boolean;
  /** The slider's range comes from the scene (scene_view.ts), not from the declaration. */
  sceneRange?: boolean;
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
    auto: true,
    sceneRange: true,
    min: 0.005,
    max: 0.3,
    step: 0.001,
    unit: "m",
    doc: "Radius of each point's disc or sphere; auto: the server sizes them from the cloud.",
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

/** A setting with named values (a drop-down); its default and choices come from `hello`. */
export interface ChoiceDeclaration {
  key: string;
  /** The server's default; "" until `hello` declared the key. */
  default: string;
  /** The values the server takes; empty until `hello` declared the key. */
  choices: string[];
  doc: string;
}

export type ChoiceName = "primitive";

export const CHOICES: Record<ChoiceName, ChoiceDeclaration> = {
  primitive: { key: "primitive", default: "", choices: [], doc: "How each point meets rays." },
};

/**
 * A choice key as `hello` declares it (`{default, choices, doc}`): its string
 * choices, its default ("" unless one of them) and its doc (null without one);
 * null when it declares no choices.
 */
export function declaredChoice(
  k: unknown,
): { default: string; choices: string[]; doc: string | null } | null {
  if (typeof k !== "object" || k === null) return null;
  const { choices: raw, default: fallback, doc } = k as ServerKey;
  if (!Array.isArray(raw)) return null;
  const choices = raw.filter((c): c is string => typeof c === "string");
  if (choices.length === 0) return null;
  return {
    default: typeof fallback === "string" && choices.includes(fallback) ? fallback : "",
    choices,
    doc: typeof doc === "string" ? doc : null,
  };
}

/** Declarations as `hello` may carry them (issue 11): per command, per key. */
interface ServerKey {
  default?: unknown;
  min?: unknown;
  max?: unknown;
  doc?: unknown;
  unit?: unknown;
  choices?: unknown;
}

/**
 * Takes defaults, ranges, choices and docs from the server's key declarations
 * where it has them (`hello.keys[command][key]` or
 * `hello.commands[command].keys[key]`); returns the names that changed.
 */
export function adoptServerKeys(hello: Record<string, unknown>): (SettingName | ChoiceName)[] {
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
  const changed: (SettingName | ChoiceName)[] = [];
  for (const [name, d] of Object.entries(SETTINGS) as [SettingName, SettingDeclaration][]) {
    const k = found.get(d.key);
    if (!k) continue;
    const num = (v: unknown) => (typeof v === "number" && Number.isFinite(v) ? v : undefined);
    // "auto" (any string) as the default: the server chooses; a number: that number.
    d.auto = typeof k.default === "string" ? true : num(k.default) !== undefined ? false : d.auto;
    d.default = num(k.default) ?? d.default;
    if (!d.sceneRange) {
      d.min = num(k.min) ?? d.min;
      d.max = num(k.max) ?? d.max;
    }
    if (typeof k.doc === "string") d.doc = k.doc;
    if (typeof k.unit === "string") d.unit = k.unit;
    changed.push(name);
  }
  for (const [name, d] of Object.entries(CHOICES) as [ChoiceName, ChoiceDeclaration][]) {
    const choice = declaredChoice(found.get(d.key));
    if (choice === null) continue;
    d.choices = choice.choices;
    d.default = choice.default;
    if (choice.doc !== null) d.doc = choice.doc;
    changed.push(name);
  }
  return changed;
}

/** What the panel holds for the cloud jobs' point model and rays. */
export interface CloudSettings {
  raysPerViewpoint: number;
  /** Let the server size the points (send no point_radius). */
  pointRadiusAuto: boolean;
  pointRadius: number;
  /** A value of CHOICES.primitive.choices, or "" for the server's default. */
  primitive: string;
}

/**
 * The keys of the point-cloud jobs (-poc, or -fscan with `scan`) that the
 * user set: a value equal to the server's declared default is left out, the
 * point radius is sent only when "auto" is off, and the primitive only when
 * it is one the server offers and not its default. What is left out takes
 * the server's default, so the viewer and the CLI give the same answer.
 */
export function cloudJobParams(s: CloudSettings, job: "poc" | "scan"): Record<string, unknown> {
  const params: Record<string, unknown> = {};
  if (job === "poc" && s.raysPerViewpoint !== SETTINGS.raysPerViewpoint.default) {
    params[SETTINGS.raysPerViewpoint.key] = s.raysPerViewpoint;
  }
  const radius = SETTINGS.pointRadius;
  const numberSet = Number.isFinite(s.pointRadius) && s.pointRadius > 0;
  if (!s.pointRadiusAuto && numberSet && (radius.auto || s.pointRadius !== radius.default)) {
    params[radius.key] = s.pointRadius;
  }
  const primitive = CHOICES.primitive;
  if (primitive.choices.includes(s.primitive) && s.primitive !== primitive.default) {
    params[primitive.key] = s.primitive;
  }
  return params;
}

/** How many escape rays per viewpoint are drawn at most, and above how many in all they start hidden. */
export const RAY_DISPLAY = { perViewpoint: 400, hiddenAbove: 3000 };
