// Messages for the user: errors stay until dismissed (never a silent
// failure), information fades after a few seconds.

import { describeError } from "../protocol/errors";
import { h } from "./dom";

export class Notices {
  constructor(private readonly container: HTMLElement) {}

  error(title: string, detail = ""): HTMLElement {
    const close = h("button", {
      class: "ml-3 shrink-0 rounded px-1.5 text-red-200 hover:bg-red-800",
      text: "×",
      title: "Dismiss",
      attrs: { "aria-label": "Dismiss" },
    });
    const notice = h(
      "div",
      {
        class:
          "pointer-events-auto flex max-w-xl items-start rounded-lg border border-red-700 " +
          "bg-red-950/95 px-4 py-3 text-sm text-red-100 shadow-xl",
        testid: "notice-error",
        attrs: { role: "alert" },
      },
      [
        h("div", { class: "min-w-0" }, [
          h("div", { class: "font-semibold", text: title }),
          detail
            ? h("div", { class: "mt-0.5 break-words font-mono text-xs text-red-200", text: detail })
            : null,
        ]),
        close,
      ],
    );
    close.addEventListener("click", () => notice.remove());
    this.container.append(notice);
    console.error(`${title}${detail ? ` — ${detail}` : ""}`);
    return notice;
  }

  fromError(error: unknown, context?: string): HTMLElement {
    const { title, detail } = describeError(error, context);
    return this.error(title, detail);
  }

  info(text: string, kind: "info" | "success" = "info", timeoutMs = 5000): HTMLElement {
    // At most two at a time: the newest replace the oldest (errors stay).
    const shown = this.container.querySelectorAll(
      "[data-testid=notice-info], [data-testid=notice-success]",
    );
    for (let i = 0; i + 1 < shown.length; ++i) shown[i]!.remove();
    const colours =
      kind === "success"
        ? "border-emerald-700 bg-emerald-950/95 text-emerald-100"
        : "border-slate-600 bg-slate-900/95 text-slate-100";
    const notice = h("div", {
      class: `pointer-events-auto max-w-xl rounded-lg border px-4 py-2 text-sm shadow-xl ${colours}`,
      testid: `notice-${kind}`,
      text,
      attrs: { role: "status" },
    });
    this.container.append(notice);
    setTimeout(() => notice.remove(), timeoutMs);
    return notice;
  }
}
