// The study's scatter plot: one chosen measure (x) against mIoU (y), one dot
// per run or evaluated scene, as an SVG. A series never mixes measures: the
// chooser lists the measures the points have, and only points with the chosen
// one are drawn. Axes zoom to the data; hovering a dot names its run.

import type { StudyPoint } from "../results";
import { MEASURES } from "../study_measures";
import type { MeasureId } from "../study_measures";
import { h } from "./dom";
import { percent } from "./format";

const SVG = "http://www.w3.org/2000/svg";

function svg<K extends keyof SVGElementTagNameMap>(
  tag: K,
  attrs: Record<string, string | number>,
  text?: string,
): SVGElementTagNameMap[K] {
  const element = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs)) element.setAttribute(k, String(v));
  if (text !== undefined) element.textContent = text;
  return element;
}

/** Least-squares line y = a + b x (null for fewer than 2 distinct x). */
export function fitLine(xy: [number, number][]): { a: number; b: number } | null {
  const n = xy.length;
  if (n < 2) return null;
  const mx = xy.reduce((s, p) => s + p[0], 0) / n;
  const my = xy.reduce((s, p) => s + p[1], 0) / n;
  let sxx = 0;
  let sxy = 0;
  for (const [x, y] of xy) {
    sxx += (x - mx) ** 2;
    sxy += (x - mx) * (y - my);
  }
  if (sxx === 0) return null;
  const b = sxy / sxx;
  return { a: my - b * mx, b };
}

/**
 * An axis range around the data: round ticks (1, 2, 2.5 or 5 × 10^k apart,
 * about four of them) that enclose [lo, hi], kept inside [0, 1] (fractions).
 */
export function niceRange(lo: number, hi: number): { min: number; max: number; step: number } {
  let span = hi - lo;
  if (!(span > 0)) span = Math.max(Math.abs(hi) * 0.2, 0.02);
  const raw = span / 4;
  const power = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 2.5, 5, 10].map((m) => m * power).find((s) => s >= raw)!;
  const round = (v: number) => Number(v.toPrecision(12)); // 0.6, not 0.6000000000000001
  const min = round(Math.max(0, Math.floor((lo - span * 0.05) / step) * step));
  const max = round(Math.min(1, Math.ceil((hi + span * 0.05) / step) * step));
  return { min, max: max > min ? max : min + step, step };
}

/** The measures present in the points, in MEASURES order. */
export function measuresPresent(points: StudyPoint[]): MeasureId[] {
  return (Object.keys(MEASURES) as MeasureId[]).filter((m) =>
    points.some((p) => p.measures[m] !== undefined),
  );
}

const SERIES = {
  study: { label: "server study", fill: "#38bdf8", stroke: "#0c4a6e", line: "#f59e0b" },
  session: { label: "this session", fill: "#a3e635", stroke: "#365314", line: "#84cc16" },
} as const;

export function scatterPlot(
  points: StudyPoint[],
  wanted: MeasureId | null,
  onMeasure: (m: MeasureId) => void,
): HTMLElement {
  const present = measuresPresent(points);
  const measure = wanted && present.includes(wanted) ? wanted : (present[0] ?? null);
  const own = measure
    ? points.filter((p) => p.measures[measure] !== undefined)
    : ([] as StudyPoint[]);
  const xy = own.map((p) => [p.measures[measure!]!, p.miou] as [number, number]);
  const width = 340;
  const height = 250;
  const m = { left: 44, right: 12, top: 12, bottom: 38 };
  const xr = niceRange(Math.min(...xy.map((p) => p[0]), 1), Math.max(...xy.map((p) => p[0]), 0));
  const yr = niceRange(Math.min(...xy.map((p) => p[1]), 1), Math.max(...xy.map((p) => p[1]), 0));
  const x = (v: number) => m.left + ((v - xr.min) / (xr.max - xr.min)) * (width - m.left - m.right);
  const y = (v: number) =>
    height - m.bottom - ((v - yr.min) / (yr.max - yr.min)) * (height - m.top - m.bottom);
  const root = svg("svg", {
    viewBox: `0 0 ${width} ${height}`,
    class: "w-full",
    "data-testid": "study-scatter",
    "data-measure": measure ?? "",
    "data-x-min": xr.min,
    "data-x-max": xr.max,
  });
  const digits = (step: number) => (step * 100 < 1 ? 1 : 0);
  for (let v = yr.min; v <= yr.max + 1e-9; v += yr.step) {
    root.append(
      svg("line", { x1: m.left, x2: width - m.right, y1: y(v), y2: y(v), stroke: "#1e293b" }),
      svg(
        "text",
        { x: m.left - 6, y: y(v) + 3, fill: "#94a3b8", "font-size": 9, "text-anchor": "end" },
        percent(v, digits(yr.step)),
      ),
    );
  }
  for (let v = xr.min; v <= xr.max + 1e-9; v += xr.step) {
    root.append(
      svg(
        "text",
        {
          x: x(v),
          y: height - m.bottom + 13,
          fill: "#94a3b8",
          "font-size": 9,
          "text-anchor": "middle",
        },
        percent(v, digits(xr.step)),
      ),
    );
  }
  root.append(
    svg(
      "text",
      {
        x: (m.left + width - m.right) / 2,
        y: height - 6,
        fill: "#cbd5e1",
        "font-size": 10,
        "text-anchor": "middle",
      },
      measure ? MEASURES[measure].label : "no measure yet",
    ),
    svg(
      "text",
      {
        x: 12,
        y: height / 2,
        fill: "#cbd5e1",
        "font-size": 10,
        "text-anchor": "middle",
        transform: `rotate(-90 12 ${height / 2})`,
      },
      "mIoU",
    ),
  );
  const hover = h("p", {
    class: "min-h-[1rem] text-xs tabular-nums text-slate-300",
    testid: "study-hover",
  });
  const trends: string[] = [];
  for (const name of ["study", "session"] as const) {
    const s = SERIES[name];
    const mine = own.filter((p) => p.series === name);
    const line = fitLine(mine.map((p) => [p.measures[measure!]!, p.miou]));
    if (line) {
      const clampY = (v: number) => y(Math.min(yr.max, Math.max(yr.min, v)));
      root.append(
        svg("line", {
          x1: x(xr.min),
          y1: clampY(line.a + line.b * xr.min),
          x2: x(xr.max),
          y2: clampY(line.a + line.b * xr.max),
          stroke: s.line,
          "stroke-dasharray": "4 3",
          "stroke-width": 1.2,
        }),
      );
      trends.push(
        `${s.label}: mIoU ${line.b >= 0 ? "+" : "−"}${Math.abs(line.b).toFixed(2)} per unit`,
      );
    }
    for (const p of mine) {
      const v = p.measures[measure!]!;
      const text = `${p.label}: ${MEASURES[measure!].label} ${percent(v, 2)}, mIoU ${percent(p.miou)}`;
      const dot = svg("circle", {
        cx: x(v),
        cy: y(p.miou),
        r: 4.5,
        fill: s.fill,
        stroke: s.stroke,
        "data-series": name,
        "data-label": p.label,
      });
      dot.append(svg("title", {}, text));
      dot.addEventListener("mouseenter", () => (hover.textContent = text));
      dot.addEventListener("mouseleave", () => (hover.textContent = ""));
      root.append(dot);
    }
  }
  const chooser = h("select", {
    class: "w-full rounded-md bg-slate-900 px-2 py-1 text-xs text-slate-100 ring-1 ring-slate-700",
    testid: "study-measure",
    attrs: { "aria-label": "measure on the x axis" },
    on: { change: () => onMeasure(chooser.value as MeasureId) },
  });
  for (const id of present) {
    const option = h("option", { text: MEASURES[id].label, attrs: { value: id } });
    option.selected = id === measure;
    chooser.append(option);
  }
  const series = (["study", "session"] as const).filter((n) => own.some((p) => p.series === n));
  return h("div", {}, [
    present.length > 1
      ? h("label", { class: "mb-1 block text-xs text-slate-400" }, ["x axis", chooser])
      : null,
    root as unknown as HTMLElement,
    hover,
    series.length > 1
      ? h(
          "div",
          { class: "mt-1 flex gap-3 text-xs text-slate-400" },
          series.map((n) =>
            h("span", { class: "flex items-center gap-1" }, [
              h("span", {
                class: "inline-block h-2 w-2 rounded-full",
                style: { background: SERIES[n].fill },
              }),
              SERIES[n].label,
            ]),
          ),
        )
      : null,
    measure
      ? h("p", {
          class: "mt-1 text-xs text-slate-400",
          testid: "study-definition",
          text: MEASURES[measure].definition,
        })
      : null,
    h("p", {
      class: "mt-1 text-xs text-slate-500",
      text: own.length
        ? `${own.length} point${own.length > 1 ? "s" : ""}${trends.length ? `; trend, ${trends.join("; ")}` : ""}`
        : "No points yet.",
    }),
  ]);
}
