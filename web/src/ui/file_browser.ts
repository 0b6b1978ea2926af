// The server's data directory, one folder at a time (list_files): folders to
// open, scenes to load, openings files to use, S3DIS folders to reconstruct.

import { BUTTON_SMALL, clear, h } from "./dom";
import { bytes } from "./format";
import { icon } from "./icons";

export interface FileEntry {
  name: string;
  path: string;
  type: "file" | "directory";
  kind: string;
  size?: number;
  mtime?: number;
}

export interface FileActions {
  list(dir: string): Promise<{ entries: FileEntry[]; truncated: boolean }>;
  load(entry: FileEntry, event: MouseEvent): void;
  useAsOpenings(entry: FileEntry): void;
  reconstruct(entry: FileEntry): void;
}

const LOADABLE = new Set(["mesh", "cloud", "text", "s3dis_room", "s3dis_area"]);

export class FileBrowser {
  private dir = "";
  private entries: FileEntry[] = [];
  private truncated = false;
  private readonly crumbs = h("div", { class: "flex flex-wrap items-center gap-1 text-xs" });
  private readonly list = h("ul", { class: "space-y-0.5", testid: "file-list" });
  /** Every file path seen, for path suggestions (evaluate dialog). */
  readonly known = new Set<string>();

  constructor(
    container: HTMLElement,
    private readonly actions: FileActions,
    private readonly onError: (error: unknown) => void,
  ) {
    const refresh = h("button", {
      class: BUTTON_SMALL,
      text: "↻",
      title: "Refresh",
      testid: "files-refresh",
      on: { click: () => void this.show(this.dir) },
    });
    container.append(
      h("div", { class: "mb-2 flex items-center justify-between gap-2" }, [this.crumbs, refresh]),
      this.list,
    );
  }

  get listing(): FileEntry[] {
    return this.entries;
  }

  get current(): string {
    return this.dir;
  }

  find(path: string): FileEntry | undefined {
    return this.entries.find((e) => e.path === path);
  }

  async show(dir: string): Promise<void> {
    try {
      const { entries, truncated } = await this.actions.list(dir);
      this.dir = dir;
      this.entries = entries;
      this.truncated = truncated;
      for (const e of entries) this.known.add(e.path);
      this.render();
    } catch (error) {
      this.onError(error);
    }
  }

  private render(): void {
    clear(this.crumbs);
    const parts = this.dir ? this.dir.split("/") : [];
    const crumb = (label: string, path: string) =>
      h("button", {
        class: "rounded px-1 text-sky-300 hover:bg-slate-800",
        text: label,
        on: { click: () => void this.show(path) },
      });
    this.crumbs.append(crumb("data", ""));
    parts.forEach((part, i) => {
      this.crumbs.append(h("span", { class: "text-slate-600", text: "/" }));
      this.crumbs.append(crumb(part, parts.slice(0, i + 1).join("/")));
    });

    clear(this.list);
    if (this.entries.length === 0) {
      this.list.append(h("li", { class: "px-2 py-1 text-xs text-slate-500", text: "(empty)" }));
    }
    for (const entry of this.entries) this.list.append(this.row(entry));
    if (this.truncated) {
      this.list.append(
        h("li", {
          class: "px-2 py-1 text-xs text-amber-300",
          text: `Only the first ${this.entries.length.toLocaleString("en-US")} entries are listed.`,
        }),
      );
    }
  }

  private row(entry: FileEntry): HTMLElement {
    const isFolder = entry.type === "directory";
    const loadable = LOADABLE.has(entry.kind);
    const browseOnly = isFolder && !loadable;
    const name = h(
      "button",
      {
        class:
          "flex min-w-0 flex-1 items-center gap-2 rounded px-2 py-1 text-left text-sm " +
          (loadable || browseOnly ? "hover:bg-slate-800" : "cursor-default text-slate-500"),
        title: browseOnly ? `Open ${entry.path}` : loadable ? `Load ${entry.path}` : entry.path,
        testid: "file-entry",
        attrs: { "data-path": entry.path, "data-kind": entry.kind },
        on: {
          click: (event) => {
            if (browseOnly) void this.show(entry.path);
            else if (loadable) this.actions.load(entry, event);
          },
        },
      },
      [
        h("span", { class: entry.type === "directory" ? "text-amber-300/80" : "text-sky-300/80" }, [
          icon(entry.kind),
        ]),
        h("span", { class: "truncate", text: entry.name }),
        entry.size !== undefined
          ? h("span", { class: "ml-auto shrink-0 text-xs text-slate-500", text: bytes(entry.size) })
          : null,
      ],
    );
    const extra: HTMLElement[] = [];
    if (isFolder && loadable) {
      extra.push(
        h("button", {
          class: BUTTON_SMALL,
          text: "›",
          title: `Browse ${entry.path}`,
          on: { click: () => void this.show(entry.path) },
        }),
        h("button", {
          class: BUTTON_SMALL,
          text: "recon",
          title: "Reconstruct into one labelled cloud (-recon) and show it",
          on: { click: () => this.actions.reconstruct(entry) },
        }),
      );
    }
    if (entry.kind === "text") {
      extra.push(
        h("button", {
          class: BUTTON_SMALL,
          text: "openings",
          title: "Use as the openings (window/door polygons) file of the next computation",
          testid: "use-openings",
          on: { click: () => this.actions.useAsOpenings(entry) },
        }),
      );
    }
    return h("li", { class: "flex items-center gap-1" }, [name, ...extra]);
  }
}
