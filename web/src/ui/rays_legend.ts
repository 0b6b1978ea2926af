// The escape rays' key (top right of the view): one line per viewpoint in
// its marker's colour, with the rays drawn out of the escapes it had, and
// what a ray means.

import { clear, h } from "./dom";
import { integer } from "./format";

export interface RayKeyRow {
  label: string;
  colour: string;
  drawn: number;
  total: number;
}

export function renderRayKey(
  container: HTMLElement,
  rows: RayKeyRow[] | null,
  shown: boolean,
): void {
  clear(container);
  container.classList.toggle("hidden", rows === null);
  if (rows === null) return;
  const total = rows.reduce((n, r) => n + r.total, 0);
  container.append(
    h(
      "div",
      {
        class:
          "max-w-[16rem] rounded-lg border border-slate-700 bg-slate-900/90 p-2 text-xs shadow-xl",
        testid: "rays-legend",
      },
      [
        h("div", { class: "font-semibold text-slate-200", text: "Escape rays (-poc)" }),
        h("p", {
          class: "mb-1 text-[11px] leading-snug text-slate-400",
          text:
            "Rays that left the scene through gaps (or openings) without hitting a point, " +
            "drawn to where they leave the scene's box.",
        }),
        ...rows.map((r) =>
          h("div", { class: "flex items-center gap-2 py-0.5", testid: "rays-legend-row" }, [
            h("span", {
              class: "inline-block h-0.5 w-4 shrink-0",
              style: { background: r.colour },
            }),
            h("span", { class: "flex-1 text-slate-200", text: r.label }),
            h("span", {
              class: "tabular-nums text-slate-400",
              text:
                r.drawn < r.total ? `${integer(r.drawn)} of ${integer(r.total)}` : integer(r.total),
            }),
          ]),
        ),
        h("p", {
          class: "mt-1 text-[11px] text-slate-500",
          text: shown
            ? "Hide them in Controls › Viewpoints."
            : `Hidden (${integer(total)} escapes): show them in Controls › Viewpoints.`,
        }),
      ],
    ),
  );
}
