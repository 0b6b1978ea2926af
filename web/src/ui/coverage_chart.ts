// The plan's coverage curve as a small SVG chart: coverage (0..1, up) after
// each station (1..K, across), a dot per station in its colour, and the
// target as a dashed line when the plan had one.

import { css, stationColour } from "../decode/colour_maps";
import { percent } from "./format";

const SVG = "http://www.w3.org/2000/svg";

export interface ChartBox {
  width: number;
  height: number;
  /** Margin left of the plot (for the axis labels) and around it. */
  left: number;
  pad: number;
}

export const CHART_BOX: ChartBox = { width: 260, height: 120, left: 34, pad: 8 };

/**
 * Where each station's coverage goes in the chart: station k (from 1) of K at
 * x across the plot (one station: the middle), coverage c at y (1 at the top,
 * 0 at the bottom). Pure, for the tests.
 */
export function curvePoints(
  curve: readonly number[],
  box: ChartBox = CHART_BOX,
): [number, number][] {
  const x0 = box.left;
  const x1 = box.width - box.pad;
  const y0 = box.height - box.pad - 12; // room for the station numbers below
  const y1 = box.pad;
  const n = curve.length;
  return curve.map((c, i) => {
    const x = n === 1 ? (x0 + x1) / 2 : x0 + ((x1 - x0) * i) / (n - 1);
    const y = y0 + (y1 - y0) * Math.min(1, Math.max(0, c));
    return [Number(x.toFixed(2)), Number(y.toFixed(2))];
  });
}

function el<K extends keyof SVGElementTagNameMap>(
  tag: K,
  attrs: Record<string, string | number>,
  text?: string,
): SVGElementTagNameMap[K] {
  const e = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  if (text !== undefined) e.textContent = text;
  return e;
}

export function coverageChart(
  curve: readonly number[],
  target: number | null,
  box: ChartBox = CHART_BOX,
): SVGSVGElement {
  const svg = el("svg", {
    viewBox: `0 0 ${box.width} ${box.height}`,
    width: "100%",
    role: "img",
    "aria-label": "Coverage after each station",
    "data-testid": "plan-curve",
  });
  const points = curvePoints(curve, box);
  const [, bottom] = curvePoints([0], box)[0]!;
  const [, top] = curvePoints([1], box)[0]!;
  const right = box.width - box.pad;
  svg.append(
    el("line", { x1: box.left, y1: bottom, x2: right, y2: bottom, stroke: "#475569" }),
    el("line", { x1: box.left, y1: top, x2: box.left, y2: bottom, stroke: "#475569" }),
    el(
      "text",
      { x: box.left - 4, y: top + 4, "text-anchor": "end", fill: "#94a3b8", "font-size": 9 },
      "100%",
    ),
    el(
      "text",
      { x: box.left - 4, y: bottom, "text-anchor": "end", fill: "#94a3b8", "font-size": 9 },
      "0%",
    ),
  );
  if (target !== null) {
    const [, y] = curvePoints([target], box)[0]!;
    svg.append(
      el("line", {
        x1: box.left,
        y1: y,
        x2: right,
        y2: y,
        stroke: "#f59e0b",
        "stroke-dasharray": "4 3",
        "data-testid": "plan-curve-target",
      }),
    );
  }
  if (points.length > 1) {
    svg.append(
      el("polyline", {
        points: points.map((p) => p.join(",")).join(" "),
        fill: "none",
        stroke: "#38bdf8",
        "stroke-width": 1.5,
      }),
    );
  }
  points.forEach(([x, y], i) => {
    const dot = el("circle", { cx: x, cy: y, r: 3.5, fill: css(stationColour(i + 1)) });
    dot.append(el("title", {}, `after station ${i + 1}: ${percent(curve[i]!, 1)}`));
    svg.append(
      dot,
      el(
        "text",
        { x, y: bottom + 11, "text-anchor": "middle", fill: "#94a3b8", "font-size": 9 },
        String(i + 1),
      ),
    );
  });
  return svg;
}
