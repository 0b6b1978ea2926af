// The Plan tab: the plan's settings (their defaults, ranges and docs from the
// server's declaration of the `plan` job in hello), Run, the live station
// switch and its count, and the result card (coverage, the curve, the
// stations in order).

import { css, stationColour } from "../decode/colour_maps";
import type { PlanResult } from "../plan_report";
import { declaredChoice } from "../settings_defaults";
import type { ChoiceDeclaration } from "../settings_defaults";
import { coverageChart } from "./coverage_chart";
import { outOfReachFacts, planQuestion, refinementRows, refinementSummary } from "./plan_figures";
import { BUTTON_PRIMARY, BUTTON_SMALL, INPUT, clear, h } from "./dom";
import { fixed, integer, percent } from "./format";
import { card, facts, headline, table, warnings } from "./results_panel";

/** The scanner's limits among them: the live station traces with these too. */
export const PLAN_LIMIT_FIELDS = [
  "max_range",
  "max_incidence",
  "min_elevation",
  "max_elevation",
] as const;
/** The plan keys the tab offers (the rest take the server's defaults). */
export const PLAN_FIELDS = [
  "stations",
  "target_coverage",
  "spacing",
  "height",
  ...PLAN_LIMIT_FIELDS,
] as const;
export type PlanField = (typeof PLAN_FIELDS)[number];

export interface FieldDeclaration {
  key: PlanField;
  /** The server's default, null when it has none (stations: the other question) or it is auto. */
  default: number | null;
  /**
   * The server chooses the value when none is sent (spacing: about 1,000
   * positions over the floor plan): the blank field says "auto".
   */
  auto: boolean;
  min: number | null;
  max: number | null;
  unit: string;
  doc: string;
}

/**
 * The plan's up axis, a choice (the floor the candidates stand on and the
 * horizontal the elevation limits are measured from): its default and
 * choices come only from hello. Camera-frame data (y down) needs "-y".
 */
export type UpDeclaration = Omit<ChoiceDeclaration, "key">;

/** The on/off keys the tab offers as boxes (a box left at the server's default sends nothing). */
export const PLAN_FLAGS = ["refine"] as const;
export type PlanFlag = (typeof PLAN_FLAGS)[number];

export interface FlagDeclaration {
  default: boolean;
  doc: string;
}

/** The tab's boxes as `hello` declares the `plan` job's boolean keys; none for a key it lacks. */
export function planFlagDeclarations(keys: unknown): Map<PlanFlag, FlagDeclaration> {
  const out = new Map<PlanFlag, FlagDeclaration>();
  const plan = (keys as Record<string, unknown> | null)?.plan as
    Record<string, Record<string, unknown> | undefined> | undefined;
  for (const key of PLAN_FLAGS) {
    const k = plan?.[key];
    if (typeof k?.default !== "boolean") continue;
    out.set(key, { default: k.default, doc: typeof k.doc === "string" ? k.doc : "" });
  }
  return out;
}

/** The choice keys the tab offers as drop-downs (their default: the server's, not sent). */
export type PlanChoiceKey = "up" | "out_of_reach";

/** A choice key as `hello` declares it for the `plan` job; null when it does not. */
export function planChoiceDeclaration(keys: unknown, key: PlanChoiceKey): UpDeclaration | null {
  const plan = (keys as Record<string, unknown> | null)?.plan as
    Record<string, unknown> | undefined;
  const choice = declaredChoice(plan?.[key]);
  return choice === null ? null : { ...choice, doc: choice.doc ?? "" };
}

/** The `up` key as `hello` declares it for the `plan` job; null when it does not. */
export function planUpDeclaration(keys: unknown): UpDeclaration | null {
  return planChoiceDeclaration(keys, "up");
}

/** The tab's fields as `hello` declares the `plan` job's keys; null for a key it does not declare. */
export function planDeclarations(keys: unknown): Map<PlanField, FieldDeclaration> {
  const out = new Map<PlanField, FieldDeclaration>();
  const plan = (keys as Record<string, unknown> | null)?.plan;
  if (typeof plan !== "object" || plan === null) return out;
  const num = (v: unknown) => (typeof v === "number" && Number.isFinite(v) ? v : null);
  for (const key of PLAN_FIELDS) {
    const k = (plan as Record<string, Record<string, unknown> | undefined>)[key];
    if (typeof k !== "object" || k === null) continue;
    out.set(key, {
      key,
      default: num(k.default),
      auto: k.auto === true,
      min: num(k.min),
      max: num(k.max),
      unit: typeof k.unit === "string" ? k.unit : "",
      doc: typeof k.doc === "string" ? k.doc : "",
    });
  }
  return out;
}

/**
 * The params of a plan from the tab's fields (their text): only what the user
 * set and what differs from the server's default, as the cloud jobs do, so
 * an untouched tab plans as `occlusion plan SCENE` would. `stations` and
 * `target_coverage` are the two questions: a number of stations wins.
 * `up` ("" for the server's default) is sent when it differs from `up`'s
 * declared default. Throws an Error naming a field whose text is not a
 * number, or an up axis the server does not offer.
 */
export function planJobParams(
  fields: Partial<Record<PlanField | PlanChoiceKey | PlanFlag, string>>,
  declarations: Map<PlanField, FieldDeclaration>,
  up: UpDeclaration | null = null,
  outOfReach: UpDeclaration | null = null,
  flags: Map<PlanFlag, FlagDeclaration> = new Map(),
): Record<string, unknown> {
  const params: Record<string, unknown> = {};
  // A box's field is "true" or "false"; sent only where it differs from a declared default.
  for (const [key, declared] of flags) {
    const value = fields[key];
    if (value !== "true" && value !== "false") continue;
    if ((value === "true") !== declared.default) params[key] = value === "true";
  }
  const choices: [PlanChoiceKey, UpDeclaration | null][] = [
    ["up", up],
    ["out_of_reach", outOfReach],
  ];
  for (const [key, declared] of choices) {
    const value = fields[key] ?? "";
    if (value === "") continue;
    if (declared === null || !declared.choices.includes(value)) {
      throw new Error(
        `${key}: '${value}' is not one of ${declared?.choices.join(", ") ?? "(none offered)"}`,
      );
    }
    if (value !== declared.default) params[key] = value;
  }
  for (const key of PLAN_FIELDS) {
    const text = (fields[key] ?? "").trim();
    if (text === "") continue;
    const value = Number(text);
    if (!Number.isFinite(value)) throw new Error(`${key}: '${text}' is not a number`);
    if (value === declarations.get(key)?.default) continue;
    params[key] = key === "stations" ? Math.round(value) : value;
  }
  if ("stations" in params) delete params.target_coverage;
  return params;
}

/**
 * The scanner limits of a plan's params (what planJobParams gave): the
 * live station sends them with each position, so it sees what that plan
 * counts as seen (`station_view` takes the plan's own limit keys).
 */
export function planLimitParams(params: Record<string, unknown>): Record<string, unknown> {
  const limits: Record<string, unknown> = {};
  for (const key of PLAN_LIMIT_FIELDS) if (key in params) limits[key] = params[key];
  if ("up" in params) limits.up = params.up;
  return limits;
}

export interface PlanPanelActions {
  run(): void;
  toggleLive(): void;
}

export class PlanPanel {
  private readonly inputs = new Map<PlanField, HTMLInputElement>();
  private readonly selects = new Map<PlanChoiceKey, HTMLSelectElement>();
  private readonly form: HTMLElement;
  private readonly liveButton: HTMLButtonElement;
  private readonly liveText: HTMLElement;
  readonly results: HTMLElement;
  declarations = new Map<PlanField, FieldDeclaration>();
  up: UpDeclaration | null = null;
  outOfReach: UpDeclaration | null = null;
  flags = new Map<PlanFlag, FlagDeclaration>();
  private readonly boxes = new Map<PlanFlag, HTMLInputElement>();

  constructor(container: HTMLElement, actions: PlanPanelActions) {
    this.form = h("div", { class: "grid grid-cols-2 gap-2 text-xs", testid: "plan-form" });
    const run = h("button", {
      class: BUTTON_PRIMARY,
      text: "Plan stations",
      testid: "plan-run",
      title: "Where to put scanner stations: the plan job on this scene",
      on: { click: () => actions.run() },
    });
    this.liveButton = h("button", {
      class: BUTTON_SMALL,
      text: "Live station: off",
      testid: "plan-live",
      title:
        "Drag a station (or any viewpoint marker) and see the points it sees, traced on the server",
      on: { click: () => actions.toggleLive() },
    });
    this.liveText = h("span", {
      class: "text-xs tabular-nums text-slate-300",
      testid: "live-count",
    });
    this.results = h("div", { class: "space-y-3" });
    container.append(
      h("div", { class: "space-y-2" }, [
        this.form,
        h("div", { class: "flex flex-wrap items-center gap-2" }, [run, this.liveButton]),
        this.liveText,
      ]),
      this.results,
    );
    this.declare(new Map());
  }

  /** Builds the fields from the server's declarations (blank: the server's default). */
  declare(
    declarations: Map<PlanField, FieldDeclaration>,
    up: UpDeclaration | null = null,
    outOfReach: UpDeclaration | null = null,
    flags: Map<PlanFlag, FlagDeclaration> = new Map(),
  ): void {
    this.declarations = declarations;
    this.up = up;
    this.outOfReach = outOfReach;
    this.flags = flags;
    clear(this.form);
    this.inputs.clear();
    this.selects.clear();
    this.boxes.clear();
    for (const key of PLAN_FIELDS) {
      const d = declarations.get(key);
      const input = h("input", {
        class: INPUT,
        testid: `plan-${key}`,
        title: d?.doc ?? "",
        attrs: {
          type: "number",
          placeholder: d?.auto ? "auto" : (d?.default ?? null) !== null ? String(d!.default) : "—",
          ...(d?.min !== null && d?.min !== undefined ? { min: String(d.min) } : {}),
          ...(d?.max !== null && d?.max !== undefined ? { max: String(d.max) } : {}),
          step: "any",
        },
      });
      this.inputs.set(key, input);
      const label = key.replace("_", " ") + (d?.unit ? ` (${d.unit})` : "");
      this.form.append(
        h("label", { class: "flex flex-col gap-0.5 text-slate-400", title: d?.doc ?? "" }, [
          label,
          input,
        ]),
      );
    }
    this.choice("up", "up axis", up);
    this.choice("out_of_reach", "target out of reach", outOfReach);
    for (const [key, declared] of flags) {
      const box = h("input", {
        testid: `plan-${key}`,
        title: declared.doc,
        attrs: { type: "checkbox", ...(declared.default ? { checked: "" } : {}) },
      });
      this.boxes.set(key, box);
      this.form.append(
        h("label", { class: "flex items-center gap-1 text-slate-400", title: declared.doc }, [
          box,
          key,
        ]),
      );
    }
  }

  /** A drop-down of the server's choices for `key`, "default" first (not sent); none undeclared. */
  private choice(key: PlanChoiceKey, label: string, declared: UpDeclaration | null): void {
    if (declared === null) return;
    const options = [
      h("option", { text: `default (${declared.default || "server's"})`, attrs: { value: "" } }),
      ...declared.choices.map((c) => h("option", { text: c, attrs: { value: c } })),
    ];
    const select = h(
      "select",
      { class: INPUT, testid: `plan-${key.replace(/_/g, "-")}`, title: declared.doc },
      options,
    );
    this.selects.set(key, select);
    this.form.append(
      h("label", { class: "flex flex-col gap-0.5 text-slate-400", title: declared.doc }, [
        label,
        select,
      ]),
    );
  }

  fields(): Partial<Record<PlanField | PlanChoiceKey | PlanFlag, string>> {
    const out: Partial<Record<PlanField | PlanChoiceKey | PlanFlag, string>> = {};
    for (const [key, input] of this.inputs) out[key] = input.value;
    for (const [key, select] of this.selects) out[key] = select.value;
    for (const [key, box] of this.boxes) out[key] = String(box.checked);
    return out;
  }

  setLive(on: boolean, text: string, visible?: number): void {
    this.liveButton.textContent = on ? "Live station: on" : "Live station: off";
    this.liveButton.setAttribute("aria-pressed", String(on));
    this.liveText.textContent = text;
    if (visible === undefined) delete this.liveText.dataset.value;
    else this.liveText.dataset.value = String(visible);
  }

  show(result: PlanResult, coveredBy: number[] | null, seconds: number | null): void {
    clear(this.results);
    this.results.append(planCard(result, coveredBy, seconds));
  }
}

export function planCard(
  result: PlanResult,
  coveredBy: number[] | null,
  seconds: number | null,
): HTMLElement {
  const rows = result.stations.map((s) => {
    const swatch = h("span", {
      class: "mr-1 inline-block h-2.5 w-2.5 rounded-full align-middle",
      style: { background: css(stationColour(s.rank)) },
    });
    return [
      h("span", {}, [swatch, `${s.rank}. ${s.name}${s.existing ? " (placed)" : ""}`]),
      s.position.map((v) => fixed(v, 2)).join(", "),
      percent(s.gain, 1),
      percent(s.coverage, 1),
      ...(coveredBy ? [integer(coveredBy[s.rank] ?? 0)] : []),
    ];
  });
  const candidates = result.candidates;
  const rejected = Object.entries(candidates.rejected)
    .filter(([, n]) => n > 0)
    .map(([why, n]) => `${n} ${why}`)
    .join(", ");
  return card(
    "Scan plan",
    [
      headline("Coverage", percent(result.coverage, 1), "plan-coverage", result.coverage),
      facts([
        ["Question", planQuestion(result)],
        ...outOfReachFacts(result),
        ["Stations", String(result.stations.length)],
        [
          "Candidates",
          `${candidates.positions.length}${rejected ? ` (refused: ${rejected})` : ""}`,
        ],
        ...(candidates.spacing !== null
          ? ([
              [
                "Grid spacing",
                `${fixed(candidates.spacing, 3)}${candidates.spacingAuto ? " (auto)" : ""}`,
              ],
            ] as [string, string][])
          : []),
        ["Targets", result.targets],
        ...(seconds !== null ? ([["Time", `${seconds.toFixed(2)} s`]] as [string, string][]) : []),
      ]),
      h("div", { class: "mt-2 text-xs text-slate-400", text: "Coverage after each station" }),
      h("div", { class: "mt-1" }, [coverageChart(result.curve, result.targetCoverage)]),
      table(
        ["Station", "Position", "Adds", "Coverage", ...(coveredBy ? ["First sees"] : [])],
        rows,
        "plan-stations",
        true,
        [0, 1],
      ),
      refinementBlock(result),
      result.guarantee
        ? h("p", { class: "mt-2 text-[11px] text-slate-400", text: result.guarantee })
        : null,
      h("p", {
        class: "mt-1 text-[11px] text-slate-500",
        text:
          "Squares on the floor: each candidate's gain left (the ramp's top adds most). " +
          "Click one to place a station there and plan again.",
      }),
      warnings(result.warnings),
    ],
    "plan-card",
  );
}

/** The refinement's coverage before and after, and the stations it moved; null without one. */
function refinementBlock(result: PlanResult): HTMLElement | null {
  const summary = refinementSummary(result);
  if (summary === null) return null;
  const rows = refinementRows(result);
  return h("div", { class: "mt-2", testid: "plan-refinement" }, [
    h("div", { class: "text-xs text-slate-400", text: `Refinement: ${summary}` }),
    rows.length
      ? table(["Rank", "From", "To", "Moved", "Adds"], rows, "plan-refinement-moves", true, [1, 2])
      : null,
  ]);
}
