// Running requests: one row each with its stage, a progress bar and Cancel.

import { h } from "./dom";

export interface JobRow {
  progress(stage: string, fraction: number): void;
  finish(): void;
}

export class JobsPanel {
  constructor(private readonly container: HTMLElement) {}

  add(label: string, cancel: (() => void) | null): JobRow {
    const stage = h("span", { class: "min-w-0 truncate text-slate-400", text: "queued" });
    const bar = h("div", {
      class: "h-full rounded bg-sky-500 transition-[width] duration-150",
      style: { width: "0%" },
      testid: "job-progress-bar",
    });
    const started = performance.now();
    const elapsed = h("span", { class: "shrink-0 tabular-nums text-slate-500", text: "0.0 s" });
    const cancelButton = cancel
      ? h("button", {
          class:
            "rounded px-2 py-0.5 text-xs font-medium text-red-200 ring-1 ring-red-800 hover:bg-red-900",
          text: "Cancel",
          testid: "job-cancel",
          on: {
            click: () => {
              cancelButton!.disabled = true;
              cancelButton!.textContent = "Cancelling…";
              cancel();
            },
          },
        })
      : null;
    const row = h(
      "div",
      {
        class:
          "pointer-events-auto w-72 rounded-lg border border-slate-700 bg-slate-900/95 p-2.5 " +
          "text-xs shadow-xl",
        testid: "job",
      },
      [
        h("div", { class: "mb-1.5 flex items-center justify-between gap-2" }, [
          h("span", { class: "truncate font-medium text-slate-100", text: label }),
          cancelButton,
        ]),
        h("div", { class: "h-1.5 overflow-hidden rounded bg-slate-700" }, [bar]),
        h("div", { class: "mt-1 flex justify-between gap-2" }, [stage, elapsed]),
      ],
    );
    this.container.append(row);
    const timer = setInterval(() => {
      elapsed.textContent = `${((performance.now() - started) / 1000).toFixed(1)} s`;
    }, 200);
    return {
      progress: (name, fraction) => {
        stage.textContent = `${name} ${Math.round(fraction * 100)}%`;
        stage.title = stage.textContent;
        bar.style.width = `${Math.round(fraction * 100)}%`;
      },
      finish: () => {
        clearInterval(timer);
        row.remove();
      },
    };
  }
}
