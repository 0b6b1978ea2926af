// Messages for the user: errors stay until dismissed (never a silent
// failure), information fades after a few seconds. They stack in the 3-D
// view's bottom-right corner, below the GUI panel and above the jobs, or, when
// the GUI leaves no room there, in the column left of it, below the stats: never
// over the GUI, the stats, the legend, the jobs or one another.

import { describeError } from "../protocol/errors";
import { h } from "./dom";

export interface Box {
  left: number;
  top: number;
  right: number;
  bottom: number;
}

/** The overlays of the 3-D view that notices keep clear of (absent or hidden: null). */
export interface Overlays {
  gui: Box | null;
  stats: Box | null;
  legend: Box | null;
  jobs: Box | null;
}

export interface NoticeArea {
  box: Box;
  /** Stacked from the bottom, right-aligned, or from the top, centred. */
  anchor: "bottom-right" | "top-centre";
}

const GAP = 8; // px, as gap-2 between notices

/** Where notices go inside `stage` given its overlays and the height they need. */
export function noticeArea(stage: Box, o: Overlays, needed: number, margin = 8): NoticeArea {
  const corner: Box = {
    left: Math.max(stage.left, o.legend?.right ?? -Infinity) + margin,
    right: stage.right - margin,
    top: Math.max(stage.top, o.gui?.bottom ?? -Infinity, o.stats?.bottom ?? -Infinity) + margin,
    bottom: (o.jobs?.top ?? stage.bottom) - margin,
  };
  if (!o.gui || corner.bottom - corner.top >= needed)
    return { box: corner, anchor: "bottom-right" };
  const column: Box = {
    left: stage.left + margin,
    right: o.gui.left - margin,
    top: Math.max(stage.top, o.stats?.bottom ?? -Infinity) + margin,
    bottom: (o.legend?.top ?? o.jobs?.top ?? stage.bottom) - margin,
  };
  const tallest = column.bottom - column.top > corner.bottom - corner.top;
  return column.bottom - column.top >= needed || tallest
    ? { box: column, anchor: "top-centre" }
    : { box: corner, anchor: "bottom-right" };
}

export interface NoticeBounds {
  stage: HTMLElement;
  gui?: HTMLElement;
  stats?: HTMLElement;
  legend?: HTMLElement;
  jobs?: HTMLElement;
}

function boxOf(element: HTMLElement | undefined): Box | null {
  if (!element) return null;
  const r = element.getBoundingClientRect();
  return r.width > 0 && r.height > 0 ? r : null;
}

export class Notices {
  constructor(
    private readonly container: HTMLElement,
    private readonly bounds?: NoticeBounds,
  ) {
    if (!bounds) return;
    // A fixed layer (above dialogs) whose box is kept to the free part of the view.
    container.className = "pointer-events-none fixed z-50 flex flex-col gap-2";
    const layout = () => this.layout();
    window.addEventListener("resize", layout);
    if (typeof ResizeObserver !== "undefined") {
      const observer = new ResizeObserver(layout);
      for (const e of [bounds.stage, bounds.gui, bounds.stats, bounds.legend, bounds.jobs]) {
        if (e) observer.observe(e);
      }
    }
    this.layout();
  }

  /** Places the notice layer in the free part of the 3-D view. */
  layout(): void {
    const b = this.bounds;
    if (!b) return;
    const stage = b.stage.getBoundingClientRect();
    const notices = Array.from(this.container.children) as HTMLElement[];
    const needed =
      notices.reduce((sum, n) => sum + n.offsetHeight, 0) + GAP * Math.max(0, notices.length - 1);
    const { box, anchor } = noticeArea(
      stage,
      { gui: boxOf(b.gui), stats: boxOf(b.stats), legend: boxOf(b.legend), jobs: boxOf(b.jobs) },
      needed,
    );
    Object.assign(this.container.style, {
      left: `${box.left}px`,
      top: `${box.top}px`,
      width: `${Math.max(0, box.right - box.left)}px`,
      height: `${Math.max(0, box.bottom - box.top)}px`,
      justifyContent: anchor === "bottom-right" ? "flex-end" : "flex-start",
      alignItems: anchor === "bottom-right" ? "flex-end" : "center",
    });
  }

  private add(notice: HTMLElement): void {
    this.container.append(notice);
    this.layout();
  }

  private remove(notice: HTMLElement): void {
    notice.remove();
    this.layout();
  }

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
    close.addEventListener("click", () => this.remove(notice));
    this.add(notice);
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
    this.add(notice);
    setTimeout(() => this.remove(notice), timeoutMs);
    return notice;
  }
}
