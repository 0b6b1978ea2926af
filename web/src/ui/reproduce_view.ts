// Beside a result: the command line and the Python call that print the same
// figures (the server writes both from the keys the job ran with, its
// `reproduce`), to run in the server's data directory, where the paths the
// viewer sends are rooted.

import type { JobReport } from "../results";
import { h } from "./dom";

function line(label: string, text: string, testid: string): HTMLElement {
  return h("div", { class: "mt-1" }, [
    h("div", { class: "text-[11px] text-slate-500", text: label }),
    h("code", {
      class:
        "block select-all break-all rounded bg-slate-900 px-1.5 py-1 text-[11px] text-slate-200",
      text,
      testid,
    }),
  ]);
}

/** The block, or null for a report without `reproduce` (an older server). */
export function reproduceBlock(report: JobReport): HTMLElement | null {
  const reproduce = report.reproduce;
  if (!reproduce || typeof reproduce.cli !== "string") return null;
  return h("details", { class: "mt-3", testid: "reproduce" }, [
    h("summary", {
      class: "cursor-pointer text-xs text-slate-400",
      text: "Same figures from the CLI or Python (in the server's data directory)",
    }),
    line("command line", reproduce.cli, "reproduce-cli"),
    line("Python (import occlusion)", reproduce.python, "reproduce-python"),
  ]);
}
