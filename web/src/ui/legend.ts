// Bottom-left legend: class names and colours, segment count, the discrete
// visibility scale (seen by k viewpoints) or a continuous colour bar.

import {
  css,
  classColour,
  firstViewpointColour,
  rampCss,
  visibilityColour,
} from "../decode/colour_maps";
import type { Rgb } from "../decode/colour_maps";
import { clear, h } from "./dom";
import { integer, percent } from "./format";

export type LegendContent =
  | { kind: "none" }
  | { kind: "classes"; names: string[]; counts: number[]; unlabelled: number }
  | { kind: "segments"; count: number; label: string; noun: string }
  | { kind: "visibility"; histogram: number[]; max: number }
  /**
   * counts[k]: points first seen by viewpoint k (from 1, names[k - 1], in
   * firstViewpointColour(k, colours)); counts[0] by none.
   */
  | { kind: "first"; names: string[]; colours: Rgb[]; counts: number[] }
  | { kind: "colourbar"; title: string; min: number; max: number; mean?: number }
  | { kind: "text"; text: string };

export class Legend {
  constructor(private readonly container: HTMLElement) {}

  show(content: LegendContent): void {
    clear(this.container);
    this.container.classList.toggle("hidden", content.kind === "none");
    const box = h("div", {
      class:
        "pointer-events-auto max-h-[45vh] overflow-auto rounded-lg border border-slate-700 " +
        "bg-slate-900/90 p-3 text-xs shadow-xl",
      testid: "legend",
    });
    const swatch = (rgb: [number, number, number]) =>
      h("span", {
        class: "inline-block h-3 w-3 shrink-0 rounded-sm ring-1 ring-black/40",
        style: { background: css(rgb) },
      });
    switch (content.kind) {
      case "none":
        return;
      case "classes": {
        box.append(
          h("div", { class: "mb-1.5 font-semibold text-slate-200", text: "Semantic class" }),
        );
        content.names.forEach((name, i) => {
          const n = content.counts[i] ?? 0;
          if (n === 0) return;
          box.append(
            h("div", { class: "flex items-center gap-2 py-0.5", testid: "legend-class" }, [
              swatch(classColour(name, i)),
              h("span", { class: "flex-1", text: name }),
              h("span", { class: "tabular-nums text-slate-400", text: integer(n) }),
            ]),
          );
        });
        if (content.unlabelled > 0) {
          box.append(
            h("div", { class: "flex items-center gap-2 py-0.5" }, [
              swatch(classColour(undefined, -1)),
              h("span", { class: "flex-1", text: "unlabelled" }),
              h("span", {
                class: "tabular-nums text-slate-400",
                text: integer(content.unlabelled),
              }),
            ]),
          );
        }
        break;
      }
      case "segments":
        box.append(
          h("div", { class: "font-semibold text-slate-200", text: content.label }),
          h("div", {
            class: "text-slate-400",
            text: `${integer(content.count)} ${content.noun}, one colour each`,
          }),
        );
        break;
      case "visibility": {
        const total = content.histogram.reduce((a, b) => a + b, 0) || 1;
        box.append(
          h("div", { class: "mb-1.5 font-semibold text-slate-200", text: "Seen by viewpoints" }),
        );
        content.histogram.forEach((n, k) => {
          box.append(
            h("div", { class: "flex items-center gap-2 py-0.5" }, [
              swatch(visibilityColour(k, content.max)),
              h("span", { class: "flex-1", text: k === 0 ? "0 (unseen)" : `${k}` }),
              h("span", {
                class: "tabular-nums text-slate-400",
                text: `${integer(n)} · ${percent(n / total)}`,
              }),
            ]),
          );
        });
        break;
      }
      case "first": {
        const total = content.counts.reduce((a, b) => a + b, 0) || 1;
        box.append(
          h("div", {
            class: "mb-1.5 font-semibold text-slate-200",
            text: "First viewpoint that sees it",
          }),
        );
        content.counts.forEach((n, k) => {
          const name = k === 0 ? "none (unseen)" : (content.names[k - 1] ?? `#${k}`);
          box.append(
            h("div", { class: "flex items-center gap-2 py-0.5", testid: "legend-first" }, [
              swatch(firstViewpointColour(k, content.colours)),
              h("span", { class: "flex-1", text: name }),
              h("span", {
                class: "tabular-nums text-slate-400",
                text: `${integer(n)} · ${percent(n / total)}`,
              }),
            ]),
          );
        });
        break;
      }
      case "colourbar":
        box.append(
          h("div", { class: "mb-1.5 font-semibold text-slate-200", text: content.title }),
          h("div", {
            class: "h-3 w-56 rounded-sm ring-1 ring-black/40",
            style: { background: rampCss() },
            testid: "colour-bar",
          }),
          h("div", { class: "mt-1 flex w-56 justify-between tabular-nums text-slate-400" }, [
            h("span", { text: content.min.toFixed(2) }),
            content.mean !== undefined
              ? h("span", { text: `mean per face ${content.mean.toFixed(2)}` })
              : null,
            h("span", { text: content.max.toFixed(2) }),
          ]),
        );
        break;
      case "text":
        box.append(h("div", { class: "text-slate-300", text: content.text }));
        break;
    }
    this.container.append(box);
  }
}
