// The results side panel: tabs for occlusion figures, evaluation tables and
// the study's scatter plot.

import { clear, h } from "./dom";

export type ResultsTab = "occlusion" | "evaluation" | "study" | "plan";

const TITLES: Record<ResultsTab, string> = {
  occlusion: "Occlusion",
  evaluation: "Evaluation",
  study: "Study",
  plan: "Plan",
};

export class ResultsPanel {
  readonly bodies = new Map<ResultsTab, HTMLElement>();
  /** Each scene's occlusion results, kept while another scene is shown. */
  private readonly byScene = new Map<string, Node[]>();
  private scene = "";
  private readonly buttons = new Map<ResultsTab, HTMLButtonElement>();

  constructor(container: HTMLElement) {
    const tabs = h("div", { class: "flex gap-1 border-b border-slate-800 px-3 pt-2" });
    const bodies = h("div", { class: "min-h-0 flex-1 overflow-auto p-3" });
    for (const tab of Object.keys(TITLES) as ResultsTab[]) {
      const button = h("button", {
        class: "rounded-t-md px-3 py-1.5 text-sm font-medium",
        text: TITLES[tab],
        testid: `tab-${tab}`,
        on: { click: () => this.show(tab) },
      });
      this.buttons.set(tab, button);
      tabs.append(button);
      const body = h("div", { class: "hidden space-y-4", testid: `results-${tab}` }, [
        h("p", { class: "text-sm text-slate-500", text: placeholder(tab) }),
      ]);
      this.bodies.set(tab, body);
      bodies.append(body);
    }
    container.append(tabs, bodies);
    this.show("occlusion");
  }

  show(tab: ResultsTab): void {
    for (const [name, body] of this.bodies) body.classList.toggle("hidden", name !== tab);
    for (const [name, button] of this.buttons) {
      const on = name === tab;
      button.className =
        "rounded-t-md px-3 py-1.5 text-sm font-medium " +
        (on ? "bg-slate-800 text-white" : "text-slate-400 hover:text-slate-200");
    }
  }

  /** Replaces a tab's content and (unless `focus` is false) brings it to the front. */
  set(tab: ResultsTab, content: HTMLElement[], focus = true): void {
    const body = this.bodies.get(tab)!;
    clear(body);
    body.append(...content);
    if (focus) this.show(tab);
  }

  /**
   * Puts a result card (by kind, `key`) on top of a tab. The card it
   * supersedes is kept below, under "Earlier results", to compare with (its
   * test ids prefixed "earlier-": the current card alone answers to them).
   */
  setCard(tab: ResultsTab, key: string, card: HTMLElement): void {
    const body = this.bodies.get(tab)!;
    body.querySelector(":scope > p")?.remove();
    card.dataset.card = key;
    card.dataset.time = new Date().toLocaleTimeString("en-GB");
    const old = body.querySelector<HTMLElement>(`:scope > [data-card="${key}"]`);
    if (old) {
      old.remove();
      this.keepEarlier(body, old);
    }
    body.prepend(card); // the newest result on top
    this.show(tab);
  }

  private keepEarlier(body: HTMLElement, card: HTMLElement): void {
    for (const e of [card, ...card.querySelectorAll<HTMLElement>("[data-testid]")]) {
      if (e.dataset.testid) e.dataset.testid = `earlier-${e.dataset.testid}`;
    }
    card.classList.add("opacity-80");
    card.prepend(
      h("div", { class: "mb-1 text-[11px] text-slate-500", text: `computed ${card.dataset.time}` }),
    );
    let earlier = body.querySelector<HTMLDetailsElement>(":scope > details[data-earlier]");
    if (!earlier) {
      earlier = h("details", { class: "space-y-2", testid: "earlier-results" }, [
        h("summary", { class: "cursor-pointer text-xs text-slate-400" }),
      ]);
      earlier.dataset.earlier = "";
      body.append(earlier);
    }
    earlier.querySelector("summary")!.after(card); // newest earlier result first
    const n = earlier.children.length - 1;
    earlier.querySelector("summary")!.textContent =
      `Earlier results on this scene (${n}), to compare`;
  }

  /** Shows `path`'s occlusion results, keeping those of the scene shown until now. */
  switchScene(path: string): void {
    const body = this.bodies.get("occlusion")!;
    if (this.scene) this.byScene.set(this.scene, [...body.childNodes]);
    this.scene = path;
    clear(body);
    const kept = this.byScene.get(path);
    if (kept && kept.length) body.append(...kept);
    else body.append(h("p", { class: "text-sm text-slate-500", text: placeholder("occlusion") }));
  }

  clearTab(tab: ResultsTab): void {
    const body = this.bodies.get(tab)!;
    clear(body);
    body.append(h("p", { class: "text-sm text-slate-500", text: placeholder(tab) }));
  }
}

function placeholder(tab: ResultsTab): string {
  switch (tab) {
    case "occlusion":
      return "Load a scene and press Compute Occlusion.";
    case "evaluation":
      return "Press Evaluate to compare a segmentation with the ground truth.";
    case "study":
      return "Each evaluation after an occlusion computation adds a point (occlusion, mIoU).";
    case "plan":
      return "Where to put the scanner: press Plan stations.";
  }
}

export function card(
  title: string,
  children: (HTMLElement | null)[],
  testid?: string,
): HTMLElement {
  return h(
    "section",
    {
      class: "rounded-lg border border-slate-800 bg-slate-900/60 p-3",
      ...(testid ? { testid } : {}),
    },
    [
      h("h3", {
        class: "mb-2 text-xs font-semibold uppercase tracking-wide text-slate-400",
        text: title,
      }),
      ...children,
    ],
  );
}

export function headline(label: string, value: string, testid: string, raw?: number): HTMLElement {
  const figure = h("div", {
    class: "text-3xl font-semibold tabular-nums text-white",
    text: value,
    testid,
  });
  if (raw !== undefined) figure.dataset.value = String(raw);
  return h("div", { class: "mb-2" }, [
    h("div", { class: "text-xs text-slate-400", text: label }),
    figure,
  ]);
}

export function facts(pairs: [string, string][]): HTMLElement {
  return h(
    "dl",
    { class: "grid grid-cols-2 gap-x-3 gap-y-0.5 text-xs" },
    pairs.flatMap(([k, v]) => [
      h("dt", { class: "text-slate-400", text: k }),
      h("dd", { class: "text-right tabular-nums text-slate-200", text: v }),
    ]),
  );
}

/** A column heading, optionally abbreviated with the full wording as its tooltip. */
export type Heading = string | { label: string; title: string };

/**
 * A table of figures. `dense` (tighter cells, a smaller font, no wrapping) is for
 * tables with many numeric columns that must fit the panel's width; the columns
 * listed in `wrap` (names, coordinates) may still wrap, so that the table
 * narrows to the panel instead of pushing its last columns out of view.
 */
export function table(
  head: Heading[],
  rows: (string | HTMLElement)[][],
  testid?: string,
  dense = false,
  wrap: readonly number[] = [],
): HTMLElement {
  const cell = (i: number) =>
    !dense ? "px-1.5 py-1" : wrap.includes(i) ? "px-1 py-1" : "whitespace-nowrap px-1 py-1";
  return h("div", { class: "overflow-x-auto" }, [
    h(
      "table",
      {
        class: `w-full ${dense ? "text-[11px]" : "text-xs"} tabular-nums`,
        ...(testid ? { testid } : {}),
      },
      [
        h("thead", {}, [
          h(
            "tr",
            { class: "text-left text-slate-400" },
            head.map((c, i) => {
              const { label, title } = typeof c === "string" ? { label: c, title: "" } : c;
              return h("th", {
                class: `${cell(i)} font-medium ${i ? "text-right" : ""} ${title ? "cursor-help" : ""}`,
                text: label,
                title,
              });
            }),
          ),
        ]),
        h(
          "tbody",
          {},
          rows.map((row) =>
            h(
              "tr",
              { class: "border-t border-slate-800" },
              row.map((c, i) =>
                h("td", { class: `${cell(i)} ${i ? "text-right" : "text-slate-200"}` }, [c]),
              ),
            ),
          ),
        ),
      ],
    ),
  ]);
}

export function warnings(list: unknown): HTMLElement | null {
  if (!Array.isArray(list) || list.length === 0) return null;
  return h(
    "ul",
    { class: "mt-2 space-y-1 text-xs text-amber-300", testid: "result-warnings" },
    list.map((w) => h("li", { text: `⚠ ${String(w)}` })),
  );
}
