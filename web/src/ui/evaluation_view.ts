// Evaluation tables: mIoU and accuracies, per-class IoU / F1 / precision /
// recall, and the confusion matrix as a heat map (rows: ground truth,
// columns: prediction, the last column the points left without one).

import { averagedLine, classRow, mappingLine } from "../evaluation_table";
import type { EvaluationReport } from "../results";
import { num } from "../results";
import { h } from "./dom";
import { integer, percent } from "./format";
import { reproduceBlock } from "./reproduce_view";
import { card, facts, headline, table, warnings } from "./results_panel";

/** Heat colour of a row share in [0, 1]: dark slate to sky blue, red off the diagonal. */
export function heat(share: number, diagonal: boolean): string {
  const t = Math.sqrt(Math.min(1, Math.max(0, share)));
  if (diagonal) return `rgba(14, 165, 233, ${0.08 + 0.85 * t})`;
  return `rgba(239, 68, 68, ${share > 0 ? 0.12 + 0.8 * t : 0})`;
}

export function confusionHeatmap(report: EvaluationReport): HTMLElement {
  const { names, rows } = report.confusion;
  const cell = "px-1.5 py-1 text-right tabular-nums";
  const header = h("tr", {}, [
    h("th", { class: "px-1.5 py-1 text-left text-slate-500", text: "truth \\ pred." }),
    ...names.map((n) =>
      h("th", {
        class: "px-1 py-1 align-bottom font-medium text-slate-400",
        text: n,
        style: { writingMode: "vertical-rl", transform: "rotate(180deg)" },
      }),
    ),
    h("th", {
      class: "px-1 py-1 align-bottom font-medium text-slate-500",
      text: "none",
      title: "no prediction (a miss)",
      style: { writingMode: "vertical-rl", transform: "rotate(180deg)" },
    }),
  ]);
  const body = rows.map((row, r) => {
    const total = row.reduce((a, b) => a + b, 0);
    return h("tr", { class: "border-t border-slate-800/60" }, [
      h("th", {
        class: "whitespace-nowrap px-1.5 py-1 text-left font-medium text-slate-300",
        text: names[r] ?? "",
      }),
      ...row.map((count, c) => {
        const share = total ? count / total : 0;
        return h("td", {
          class: cell,
          text: count ? integer(count) : "·",
          title: `${names[r]} → ${names[c] ?? "none"}: ${integer(count)} (${percent(share)} of the row)`,
          style: { background: heat(share, c === r) },
        });
      }),
    ]);
  });
  return h("div", { class: "overflow-x-auto" }, [
    h("table", { class: "text-[11px]", testid: "confusion-matrix" }, [
      h("thead", {}, [header]),
      h("tbody", {}, body),
    ]),
  ]);
}

export function evaluationCards(report: EvaluationReport): HTMLElement[] {
  const miou = report.miou ?? undefined;
  const classes = report.classes ?? [];
  const scene = report.scenes?.[0];
  const mapping = mappingLine(report);
  const summary = card(
    "Segmentation evaluation (-eval)",
    [
      headline("mIoU", percent(miou), "miou", miou),
      facts([
        ["overall accuracy", percent(report.overall_accuracy ?? undefined)],
        ["mean class accuracy", percent(report.mean_class_accuracy ?? undefined)],
        ["points", integer(num(report.points))],
        ["classes with support", integer(num(report.classes_with_support))],
        ["means average", averagedLine(report) ?? "—"],
        ["ground truth", scene?.ground_truth ?? "—"],
        ["prediction", scene?.prediction ?? "—"],
      ]),
      mapping
        ? h("p", { class: "mt-2 text-xs text-slate-300", text: mapping, testid: "eval-mapping" })
        : null,
      warnings(report.warnings),
      reproduceBlock(report),
    ],
    "evaluation-summary",
  );
  const perClass = card("Per class", [
    table(
      [
        "class",
        { label: "IoU", title: "intersection over union" },
        { label: "F1", title: "F1 score" },
        { label: "prec.", title: "precision" },
        "recall",
        { label: "support", title: "ground-truth points of the class" },
        { label: "mean", title: "whether mIoU and mean class accuracy average the class" },
      ],
      classes.map(classRow),
      "eval-table",
      true,
    ),
  ]);
  const matrix = card("Confusion matrix (row-normalised colour)", [confusionHeatmap(report)]);
  return [summary, perClass, matrix];
}
