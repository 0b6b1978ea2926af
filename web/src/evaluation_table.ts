// The -eval report's per-class table and class-mapping line as the CLI
// prints them (src/cli/evaluate_command.cpp), as strings the view lays out.
// Kept apart from the DOM so the rules are unit-tested.

import type { ClassMetrics, EvaluationReport } from "./results";
import { integer, percent } from "./ui/format";

/** The CLI's and Markdown's cell for a class without ground-truth points (kNoGroundTruth). */
export const NO_GROUND_TRUTH = "no gt";

/**
 * One row: class, IoU, F1, precision, recall, support, whether the means take it.
 * A class with support 0 has nothing to score, so its IoU and F1 read "no gt"
 * rather than a 0 that reads as a score (docs/metrics.md: "no gt" is support
 * 0); whether the means average it is the report's own `averaged`, which
 * depends on the rule (mean_over) and is not re-derived here.
 */
export function classRow(c: ClassMetrics): string[] {
  const none = c.support === 0;
  return [
    c.name,
    none ? NO_GROUND_TRUTH : percent(c.iou ?? undefined),
    none ? NO_GROUND_TRUTH : percent(c.f1 ?? undefined),
    percent(c.precision ?? undefined),
    percent(c.recall ?? undefined),
    integer(c.support),
    c.averaged === undefined ? "—" : c.averaged ? "yes" : "no",
  ];
}

/**
 * "class mapping scannet20 (20 evaluation classes): <why auto chose it>", the
 * CLI's line: the mapping file when one was given (the JSON's source), else the
 * built-in used; undefined for a report without a mapping block.
 */
export function mappingLine(report: EvaluationReport): string | undefined {
  const m = report.mapping;
  if (!m || typeof m.builtin !== "string") return undefined;
  const builtinSource = `built-in ${m.builtin}`;
  const name = m.source && m.source !== builtinSource ? m.source : m.builtin;
  const count = m.evaluation_classes?.length;
  const classes = count === undefined ? "" : ` (${count} evaluation classes)`;
  const why = m.chosen_because ? `: ${m.chosen_because}` : "";
  return `class mapping ${name}${classes}${why}`;
}

/** "N classes (mean_over rule)": what mIoU and mean class accuracy average, as the CLI says. */
export function averagedLine(report: EvaluationReport): string | undefined {
  const n = report.classes_averaged;
  if (typeof n !== "number") return undefined;
  return `${n} classes${report.mean_over ? ` (mean_over ${report.mean_over})` : ""}`;
}
