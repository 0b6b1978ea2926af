// The study's scatter plot: occlusion level (x) against mIoU (y), one dot
// per evaluated scene or viewpoint set, as an SVG.

import type { StudyPoint } from "../results";
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
export function fitLine(points: StudyPoint[]): { a: number; b: number } | null {
  const n = points.length;
  if (n < 2) return null;
  const mx = points.reduce((s, p) => s + p.occlusion, 0) / n;
  const my = points.reduce((s, p) => s + p.miou, 0) / n;
  let sxx = 0;
  let sxy = 0;
  for (const p of points) {
    sxx += (p.occlusion - mx) ** 2;
    sxy += (p.occlusion - mx) * (p.miou - my);
  }
  if (sxx === 0) return null;
  const b = sxy / sxx;
  return { a: my - b * mx, b };
}

/** The smallest of 0.04, 0.1, 0.2, 0.4, 0.6, 0.8, 1 at or above `x` (4 round ticks). */
export function niceMax(x: number): number {
  for (const m of [0.04, 0.1, 0.2, 0.4, 0.6, 0.8]) if (x <= m) return m;
  return 1;
}

export function scatterPlot(points: StudyPoint[]): HTMLElement {
  const width = 340;
  const height = 260;
  const m = { left: 44, right: 12, top: 12, bottom: 38 };
  const xMax = niceMax(Math.max(0, ...points.map((p) => p.occlusion * 1.1)));
  const x = (v: number) => m.left + (v / xMax) * (width - m.left - m.right);
  const y = (v: number) => height - m.bottom - v * (height - m.top - m.bottom);
  const root = svg("svg", {
    viewBox: `0 0 ${width} ${height}`,
    class: "w-full",
    "data-testid": "study-scatter",
  });
  for (let i = 0; i <= 4; ++i) {
    const vy = i / 4;
    root.append(
      svg("line", { x1: m.left, x2: width - m.right, y1: y(vy), y2: y(vy), stroke: "#1e293b" }),
      svg(
        "text",
        { x: m.left - 6, y: y(vy) + 3, fill: "#94a3b8", "font-size": 9, "text-anchor": "end" },
        percent(vy, 0),
      ),
    );
    const vx = (xMax * i) / 4;
    root.append(
      svg(
        "text",
        {
          x: x(vx),
          y: height - m.bottom + 13,
          fill: "#94a3b8",
          "font-size": 9,
          "text-anchor": "middle",
        },
        percent(vx, 0),
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
      "occlusion level",
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
  // Two series that measure different things (the session's scene-level
  // occlusion, the study's per-scan one): coloured apart, a trend per series.
  const series = [
    { name: "study", label: "server study", fill: "#38bdf8", stroke: "#0c4a6e", line: "#f59e0b" },
    { name: "session", label: "this session", fill: "#a3e635", stroke: "#365314", line: "#84cc16" },
  ] as const;
  const trends: string[] = [];
  for (const s of series) {
    const own = points.filter((p) => (p.series ?? "session") === s.name);
    const line = fitLine(own);
    if (line) {
      root.append(
        svg("line", {
          x1: x(0),
          y1: y(Math.min(1, Math.max(0, line.a))),
          x2: x(xMax),
          y2: y(Math.min(1, Math.max(0, line.a + line.b * xMax))),
          stroke: s.line,
          "stroke-dasharray": "4 3",
          "stroke-width": 1.2,
        }),
      );
      trends.push(
        `${s.label}: mIoU ${line.b >= 0 ? "+" : "−"}${Math.abs(line.b).toFixed(2)} per unit of occlusion`,
      );
    }
    for (const p of own) {
      const dot = svg("circle", {
        cx: x(p.occlusion),
        cy: y(p.miou),
        r: 4.5,
        fill: s.fill,
        stroke: s.stroke,
        "data-series": s.name,
      });
      dot.append(
        svg(
          "title",
          {},
          `${p.label}: occlusion ${percent(p.occlusion, 2)}, mIoU ${percent(p.miou)}`,
        ),
      );
      root.append(dot);
    }
  }
  const present = series.filter((s) => points.some((p) => (p.series ?? "session") === s.name));
  const key =
    present.length > 1
      ? h(
          "div",
          { class: "mt-1 flex gap-3 text-xs text-slate-400" },
          present.map((s) =>
            h("span", { class: "flex items-center gap-1" }, [
              h("span", {
                class: "inline-block h-2 w-2 rounded-full",
                style: { background: s.fill },
              }),
              s.label,
            ]),
          ),
        )
      : null;
  return h("div", {}, [
    root as unknown as HTMLElement,
    key,
    h("p", {
      class: "mt-1 text-xs text-slate-500",
      text: points.length
        ? `${points.length} point${points.length > 1 ? "s" : ""}${trends.length ? `; trend, ${trends.join("; ")}` : ""}`
        : "No points yet.",
    }),
  ]);
}
