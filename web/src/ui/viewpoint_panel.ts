// The viewpoints as a list a person can edit: each marker's colour, name and
// x, y, z as numbers (typed values move the marker; dragging it updates
// them), on/off, "look from here", remove, and a warning when it stands
// outside the occupied space or inside an object; "Add" puts a new one at
// the centre of the view.

import type { Vec3 } from "../decode/types";
import type { DefaultViewpoints } from "../results";
import { BUTTON_SMALL, clear, h } from "./dom";

export interface ViewpointRow {
  name: string;
  label: string;
  colour: string;
  position: Vec3;
  enabled: boolean;
  warning: string | null;
}

export interface ViewpointActions {
  move(name: string, position: Vec3): void;
  enable(name: string, on: boolean): void;
  lookFrom(name: string): void;
  remove(name: string): void;
  add(): void;
}

const AXES = ["x", "y", "z"] as const;

/**
 * What the panel says above the list: what reading the file found (load's
 * `warnings`, which -poc and -fscan give first among theirs), where the
 * viewpoints come from and the job's warnings about them.
 */
export interface DefaultsNote {
  reading: string[];
  text: string | null;
  warnings: string[];
}

/**
 * The note (null when there is nothing to say): the reading warnings whatever
 * the markers, since they are about the file; and for a cloud's -poc defaults,
 * while the markers are still the defaults, the job's warnings about them,
 * which the CLI gives for the same defaults (e.g. that the data disagree with up).
 */
export function defaultsNote(
  defaults: DefaultViewpoints | undefined,
  atDefaults: boolean,
  reading: readonly string[] = [],
): DefaultsNote | null {
  if (!defaults) return reading.length ? { reading: [...reading], text: null, warnings: [] } : null;
  return atDefaults
    ? {
        reading: [...reading],
        text: `-poc's default viewpoints (${defaults.viewpoint_source}): the CLI's with none given`,
        warnings: defaults.warnings,
      }
    : {
        reading: [...reading],
        text: `changed from -poc's defaults (${defaults.viewpoint_source}); Reset positions puts them back`,
        warnings: [],
      };
}

export class ViewpointPanel {
  private readonly list = h("div", { class: "space-y-2", testid: "viewpoint-list" });
  private readonly note = h("div", { class: "mb-2 text-[11px] leading-snug text-slate-400" });
  private shape = "";

  constructor(
    container: HTMLElement,
    private readonly actions: ViewpointActions,
  ) {
    container.append(
      this.note,
      this.list,
      h("button", {
        class: `${BUTTON_SMALL} mt-2`,
        text: "+ Add viewpoint",
        testid: "viewpoint-add",
        title: "A new viewpoint at the centre of the view",
        on: { click: () => actions.add() },
      }),
    );
  }

  /** Shows the rows and the note; inputs being typed in keep their text. */
  render(rows: ViewpointRow[], note: DefaultsNote | null = null): void {
    clear(this.note);
    if (note) {
      this.note.append(
        ...note.reading.map((w) =>
          h("p", { class: "text-amber-300", text: `⚠ ${w}`, testid: "load-warning" }),
        ),
        ...(note.text === null ? [] : [h("p", { text: note.text, testid: "viewpoint-defaults" })]),
        ...note.warnings.map((w) =>
          h("p", { class: "text-amber-300", text: `⚠ ${w}`, testid: "viewpoint-defaults-warning" }),
        ),
      );
    }
    const shape = rows.map((r) => `${r.name}:${r.enabled}`).join(",");
    if (shape !== this.shape) {
      this.shape = shape;
      clear(this.list);
      for (const row of rows) this.list.append(this.row(row));
    }
    for (const row of rows) {
      const element = this.list.querySelector<HTMLElement>(`[data-viewpoint="${row.name}"]`);
      if (!element) continue;
      element.querySelectorAll<HTMLInputElement>("input[data-axis]").forEach((input) => {
        if (document.activeElement === input) return;
        input.value = row.position[Number(input.dataset.axis)]!.toFixed(3);
      });
      const warning = element.querySelector<HTMLElement>("[data-testid=viewpoint-warning]")!;
      warning.textContent = row.warning ? `⚠ ${row.warning}` : "";
      warning.classList.toggle("hidden", !row.warning);
    }
  }

  private row(row: ViewpointRow): HTMLElement {
    const inputs = AXES.map((axis, a) =>
      h("input", {
        class:
          "w-full min-w-0 rounded bg-slate-900 px-1 py-0.5 text-right text-xs tabular-nums " +
          "text-slate-100 ring-1 ring-slate-700 focus:outline-none focus:ring-sky-500",
        testid: `viewpoint-${axis}`,
        attrs: {
          type: "number",
          step: "0.05",
          "data-axis": String(a),
          "aria-label": `${row.label} ${axis}`,
          value: row.position[a]!.toFixed(3),
        },
        on: {
          change: () => {
            const values = inputs.map((i) => Number(i.value));
            if (values.every((v) => Number.isFinite(v)))
              this.actions.move(row.name, values as Vec3);
          },
        },
      }),
    );
    const enabled = h("input", {
      attrs: { type: "checkbox", "aria-label": `use ${row.label}` },
      testid: "viewpoint-enabled",
      on: { change: () => this.actions.enable(row.name, enabled.checked) },
    });
    enabled.checked = row.enabled;
    return h(
      "div",
      {
        class: `rounded border border-slate-800 p-1.5 ${row.enabled ? "" : "opacity-50"}`,
        testid: "viewpoint-row",
        attrs: { "data-viewpoint": row.name },
      },
      [
        h("div", { class: "flex items-center gap-1.5 text-xs" }, [
          enabled,
          h("span", {
            class: "inline-block h-2.5 w-2.5 shrink-0 rounded-full",
            style: { background: row.colour },
          }),
          h("span", { class: "min-w-0 flex-1 text-slate-200", text: row.label }),
          h("button", {
            class: BUTTON_SMALL,
            text: "Look",
            title: `Put the camera at ${row.label}`,
            testid: "viewpoint-look",
            on: { click: () => this.actions.lookFrom(row.name) },
          }),
          h("button", {
            class: `${BUTTON_SMALL} px-1.5`,
            text: "×",
            title: `Remove ${row.label}`,
            testid: "viewpoint-remove",
            on: { click: () => this.actions.remove(row.name) },
          }),
        ]),
        h("div", { class: "mt-1 grid grid-cols-3 gap-1" }, inputs),
        h("p", {
          class: "mt-1 hidden text-[11px] leading-snug text-amber-300",
          testid: "viewpoint-warning",
        }),
      ],
    );
  }
}
