// The point picker's panel: start picking, the picked points, undo/clear,
// where to save the opening, and which openings file the next computation uses.

import type { Vec3 } from "../decode/types";
import { BUTTON_SMALL, INPUT, clear, h } from "./dom";
import { point } from "./format";

export interface OpeningActions {
  togglePicking(on: boolean): void;
  undo(): void;
  clear(): void;
  save(path: string): void;
  useOpenings(path: string): void;
}

export class OpeningPanel {
  private picking = false;
  private readonly toggle: HTMLButtonElement;
  private readonly list = h("ol", {
    class: "max-h-32 space-y-0.5 overflow-auto text-xs tabular-nums text-slate-300",
    testid: "picked-points",
  });
  private readonly saveButton: HTMLButtonElement;
  readonly savePath: HTMLInputElement;
  private readonly openings = h("div", {
    class: "min-w-0 flex-1 break-all text-xs text-slate-400",
    testid: "openings-file",
  });
  private openingsPath = "";
  /** Called with the openings file now in use ("" for none): the app draws its openings. */
  onOpeningsChange: (path: string) => void = () => undefined;
  private readonly problem = h("p", {
    class: "mt-1 hidden text-xs text-red-300",
    testid: "opening-problem",
  });

  constructor(
    container: HTMLElement,
    private readonly actions: OpeningActions,
  ) {
    this.toggle = h("button", {
      class: BUTTON_SMALL,
      text: "Pick opening",
      testid: "pick-toggle",
      title: "Click points on a window or door boundary, in order (P)",
      on: { click: () => this.setPicking(!this.picking) },
    });
    this.saveButton = h("button", {
      class: `${BUTTON_SMALL} shrink-0 whitespace-nowrap py-1`,
      text: "Save opening",
      testid: "save-opening",
      on: { click: () => this.actions.save(this.savePath.value.trim()) },
    });
    this.savePath = h("input", {
      class: `${INPUT} min-w-0 flex-1 text-xs`,
      testid: "opening-path",
      attrs: { value: "openings/openings.txt", "aria-label": "openings file to save to" },
    });
    const clearOpenings = h("button", {
      class: "text-xs text-slate-500 hover:text-slate-300",
      text: "×",
      title: "Compute without openings",
      on: { click: () => this.actions.useOpenings("") },
    });
    container.append(
      h("div", { class: "flex flex-wrap gap-1" }, [
        this.toggle,
        h("button", {
          class: BUTTON_SMALL,
          text: "Undo",
          testid: "pick-undo",
          on: { click: () => actions.undo() },
        }),
        h("button", { class: BUTTON_SMALL, text: "Clear", on: { click: () => actions.clear() } }),
      ]),
      h("div", { class: "mt-2" }, [this.list]),
      h("div", { class: "mt-2 flex items-center gap-1" }, [this.savePath, this.saveButton]),
      this.problem,
      h("div", { class: "mt-2 flex items-center gap-1" }, [this.openings, clearOpenings]),
    );
    this.setPoints([]);
    this.setOpenings("");
  }

  get isPicking(): boolean {
    return this.picking;
  }

  setPicking(on: boolean): void {
    this.picking = on;
    this.toggle.textContent = on ? "Picking… (click points)" : "Pick opening";
    this.toggle.classList.toggle("ring-amber-400", on);
    this.toggle.classList.toggle("text-amber-200", on);
    this.actions.togglePicking(on);
  }

  setPoints(points: Vec3[]): void {
    clear(this.list);
    points.forEach((p, i) => this.list.append(h("li", { text: `${i + 1}. ${point(p)}` })));
    if (points.length === 0) {
      this.list.append(h("li", { class: "text-slate-500", text: "No points picked." }));
    }
    this.saveButton.disabled = points.length < 3;
    this.saveButton.title = points.length < 3 ? "Pick at least 3 points" : "Save to the server";
  }

  setOpenings(path: string, count?: number): void {
    const changed = path !== this.openingsPath;
    this.openingsPath = path;
    const n = count === undefined ? "" : ` (${count} opening${count === 1 ? "" : "s"}, drawn)`;
    this.openings.textContent = path
      ? `next computation uses: ${path}${n}`
      : "no openings file (rays leave only through gaps)";
    this.openings.dataset.path = path;
    if (count !== undefined) this.openings.dataset.count = String(count);
    else delete this.openings.dataset.count;
    this.openings.title = this.openings.textContent;
    if (changed) this.onOpeningsChange(path);
  }

  /** Why the picked polygon cannot be saved ("" when it can). */
  setProblem(reason: string): void {
    this.problem.textContent = reason ? `Cannot save: ${reason}.` : "";
    this.problem.classList.toggle("hidden", !reason);
  }

  get openingsFile(): string {
    return this.openingsPath;
  }
}
