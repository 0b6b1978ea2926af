// Getting scenes on screen: load a file of the data directory (or take it
// from the viewer's cache), upload the user's own, reconstruct an S3DIS
// folder; and measure each from click to first frame.

import type { Outcome } from "../api";
import type { AssembleContext, Decoded, Vec3 } from "../decode/types";
import type { LoadResult } from "../results";
import { SceneCache, cacheKey } from "../scene_cache";
import { integer, ms } from "../ui/format";
import { uploadableName } from "../ui/upload";
import type { AppContext } from "./context";

export interface LoadTiming {
  path: string;
  elements: number;
  cached: boolean;
  /** From the click to the first frame drawn (GPU finished) with the scene. */
  clickToFrameMs: number;
  serverMs: number;
  decodeMs: number;
  frameMs: number;
}

const CACHE_LIMIT = 768 * 1024 * 1024;

function decodeContext(result: LoadResult): AssembleContext {
  return { classNames: result.class_names ?? [], groups: result.groups ?? [] };
}

export class Loading {
  readonly cache = new SceneCache<LoadResult>(CACHE_LIMIT);
  readonly timings: LoadTiming[] = [];
  private token = 0;

  constructor(
    private readonly ctx: AppContext,
    private readonly onCacheChange: (bytes: number, limit: number) => void,
  ) {}

  /** Loads `path` (cache first unless `reload`), then shows it. */
  async load(
    path: string,
    options: { mtime?: number; size?: number; start?: number; reload?: boolean } = {},
  ): Promise<boolean> {
    const start = options.start ?? performance.now();
    const token = ++this.token;
    const key = cacheKey(path, options.mtime, options.size);
    if (options.reload) this.cache.forget(path);
    const cached = this.cache.get(key);
    let result: LoadResult;
    let decoded: Decoded;
    let serverMs = 0;
    let decodeMs = 0;
    if (cached) {
      result = cached.result;
      decoded = cached.decoded;
    } else {
      const outcome = await this.ctx.runner.run<LoadResult>(
        `Loading ${path}`,
        "load",
        { path },
        {
          context: decodeContext,
        },
      );
      if (outcome === null || !this.usable(outcome, path)) return false;
      result = outcome.result;
      decoded = outcome.decoded!;
      serverMs = outcome.timings.serverMs;
      decodeMs = outcome.timings.decodeMs;
      this.cache.put(key, result, decoded);
      this.onCacheChange(this.cache.bytes, this.cache.limitBytes);
    }
    if (token !== this.token) return false; // a later click won
    return this.display(path, result, decoded, { start, serverMs, decodeMs, cached: !!cached });
  }

  /** Uploads files one by one; each that reads is shown (the last stays). */
  async upload(files: File[]): Promise<void> {
    const limit = this.ctx.client.hello?.limits.max_upload_bytes ?? 256 * 1024 * 1024;
    const suffixes = this.ctx.client.hello?.upload_suffixes ?? [];
    for (const file of files) {
      // A server that does not list its readers checks the name itself.
      if (suffixes.length && !uploadableName(file.name, suffixes)) {
        this.ctx.notices.error(
          `Cannot upload ${file.name}`,
          `The server reads only ${suffixes.join(", ")} files.`,
        );
        continue;
      }
      if (file.size > limit) {
        this.ctx.notices.error(
          `Cannot upload ${file.name}`,
          `${(file.size / 1048576).toFixed(1)} MB is over the server's ${(limit / 1048576).toFixed(0)} MB limit (--max-upload-mb).`,
        );
        continue;
      }
      const start = performance.now();
      let poll: ReturnType<typeof setInterval> | undefined;
      const outcome = await this.ctx.runner.run<LoadResult>(
        `Uploading ${file.name}`,
        "upload",
        {},
        {
          upload: { name: file.name, file },
          context: decodeContext,
          onStart: (_, progress) => {
            // Until the server answers, the bar shows the bytes the socket has sent.
            poll = setInterval(() => {
              const sent = 1 - this.ctx.client.bufferedAmount / Math.max(1, file.size);
              if (sent < 1) progress("sending", Math.max(0, sent));
              else clearInterval(poll);
            }, 200);
          },
        },
      );
      clearInterval(poll);
      if (outcome === null || !this.usable(outcome, file.name)) continue;
      const path = outcome.result.path;
      this.ctx.notices.info(`Uploaded ${file.name} as ${path}`, "success");
      this.cache.forget(path);
      ++this.token;
      this.display(path, outcome.result, outcome.decoded!, {
        start,
        serverMs: outcome.timings.serverMs,
        decodeMs: outcome.timings.decodeMs,
        cached: false,
      });
      if (this.ctx.files.current === "uploads" || this.ctx.files.current === "") {
        void this.ctx.files.show(this.ctx.files.current);
      }
    }
  }

  /** Reconstructs an S3DIS room or Area (-recon) and shows the written cloud. */
  async reconstruct(path: string): Promise<void> {
    const start = performance.now();
    const outcome = await this.ctx.runner.run<
      LoadResult & { outputs?: string[]; global_shift?: Vec3 }
    >(
      `Reconstructing ${path}`,
      "reconstruct",
      { path },
      { context: () => ({ classNames: S3DIS_CLASSES }) },
    );
    if (outcome === null || outcome.decoded === null) return;
    const written = outcome.result.outputs?.[0] ?? path;
    for (const o of outcome.result.outputs ?? []) this.ctx.history.outputs.add(o);
    ++this.token;
    const result: LoadResult = {
      kind: "cloud",
      path: written,
      points: outcome.decoded.kind === "cloud" ? outcome.decoded.count : 0,
      class_names: S3DIS_CLASSES,
      // The frames are relative to the report's shift (the job's reader's).
      ...(outcome.result.global_shift ? { shift: outcome.result.global_shift } : {}),
    };
    this.display(written, result, outcome.decoded, {
      start,
      serverMs: outcome.timings.serverMs,
      decodeMs: outcome.timings.decodeMs,
      cached: false,
    });
  }

  private usable(outcome: Outcome<LoadResult>, what: string): boolean {
    const d = outcome.decoded;
    if (d === null || (d.kind !== "cloud" && d.kind !== "mesh")) {
      this.ctx.notices.error(`Loading ${what} failed`, "the server sent no geometry for it");
      return false;
    }
    return true;
  }

  private async display(
    path: string,
    result: LoadResult,
    decoded: Decoded,
    t: { start: number; serverMs: number; decodeMs: number; cached: boolean },
  ): Promise<boolean> {
    const shownAt = performance.now();
    try {
      this.ctx.view.show(path, result, decoded);
    } catch (error) {
      this.ctx.notices.fromError(error, `Showing ${path}`);
      return false;
    }
    this.afterShow(path);
    document.getElementById("scene-hint")?.replaceChildren();
    const frameAt = await this.ctx.viewer.nextFrame();
    const elements =
      decoded.kind === "cloud" ? decoded.count : decoded.kind === "mesh" ? decoded.faces : 0;
    const timing: LoadTiming = {
      path,
      elements,
      cached: t.cached,
      clickToFrameMs: frameAt - t.start,
      serverMs: t.serverMs,
      decodeMs: t.decodeMs,
      frameMs: frameAt - shownAt,
    };
    this.timings.push(timing);
    const what =
      decoded.kind === "cloud" ? `${integer(elements)} points` : `${integer(elements)} triangles`;
    this.ctx.status.scene(`${path} — ${what}`);
    this.ctx.status.timing(
      t.cached
        ? `from cache, first frame in ${ms(timing.clickToFrameMs)}`
        : `first frame ${ms(timing.clickToFrameMs)} after the click (server ${ms(t.serverMs)}, decode ${ms(t.decodeMs)}, draw ${ms(timing.frameMs)})`,
    );
    return true;
  }

  /** Per-scene defaults: openings file next to the scene, where to save picked ones. */
  private afterShow(path: string): void {
    const stem = path
      .split("/")
      .pop()!
      .replace(/\.[^.]*$/, "");
    this.ctx.openings.savePath.value = `openings/${stem}.txt`;
    let openings = "";
    const parts = path.split("/");
    for (let i = parts.length - 1; i >= 0 && !openings; --i) {
      const candidate = [...parts.slice(0, i), "openings.txt"].join("/");
      if (this.ctx.files.known.has(candidate)) openings = candidate;
    }
    if (this.ctx.history.outputs.has(`openings/${stem}.txt`)) openings = `openings/${stem}.txt`;
    // Through "" so that the openings are drawn again on the new scene even when the file is the same.
    this.ctx.openings.setOpenings("");
    this.ctx.openings.setOpenings(this.ctx.view.cloud ? openings : "");
    this.ctx.results.switchScene(path);
    for (const shown of this.ctx.sceneShown) shown(path);
  }
}

export const S3DIS_CLASSES = [
  "ceiling",
  "floor",
  "wall",
  "beam",
  "column",
  "window",
  "door",
  "table",
  "chair",
  "sofa",
  "bookcase",
  "board",
  "clutter",
];
