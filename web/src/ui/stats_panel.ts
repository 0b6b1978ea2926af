// The seed's stats panel (top left): frame rate (blue), network latency
// (green) and cache size (red), as three stats.js graphs side by side.

import Stats from "three/examples/jsm/libs/stats.module.js";

export class StatsPanel {
  private readonly stats = new Stats();
  private readonly fps: Stats.Panel;
  private readonly latency: Stats.Panel;
  private readonly cache: Stats.Panel;
  private maxFps = 60;
  private maxLatency = 50;
  private frames = 0;
  private windowStart = performance.now();
  private lastFrame = 0;
  /** Frames per second over the last full second (0 until measured). */
  lastFps = 0;

  constructor(container: HTMLElement) {
    const dom = this.stats.dom;
    while (dom.firstChild) dom.removeChild(dom.firstChild); // drop the default FPS/MS/MB graphs
    this.fps = this.stats.addPanel(new Stats.Panel("FPS", "#60a5fa", "#0b1a33"));
    this.latency = this.stats.addPanel(new Stats.Panel("ms net", "#4ade80", "#052e16"));
    this.cache = this.stats.addPanel(new Stats.Panel("MB cache", "#f87171", "#450a0a"));
    dom.removeAttribute("style");
    dom.className = "flex gap-1 opacity-90";
    dom.dataset.testid = "stats-panel";
    for (const child of Array.from(dom.children)) (child as HTMLElement).style.display = "block";
    // stats.js cycles panels on click; keep all three visible.
    const wrapper = document.createElement("div");
    wrapper.addEventListener("click", (event) => event.stopPropagation(), true);
    wrapper.title = "Frame rate · network latency (ping) · viewer cache size";
    wrapper.append(dom);
    container.append(wrapper);
  }

  /**
   * Counts a rendered frame; the FPS graph updates about once a second. The
   * viewer renders on demand: only frames drawn while the camera moves
   * (`continuous`) are timed, so idle time is never counted as slow frames,
   * and slow ones (a second or more each, software rendering) still show.
   */
  frame(continuous = true): void {
    const now = performance.now();
    const gap = now - this.lastFrame;
    this.lastFrame = now;
    if (!continuous || gap > 10_000) {
      this.frames = 0;
      this.windowStart = now;
      return;
    }
    this.frames += 1;
    const elapsed = now - this.windowStart;
    if (elapsed >= 1000) {
      this.lastFps = (this.frames * 1000) / elapsed;
      this.maxFps = Math.max(this.maxFps, this.lastFps);
      this.fps.update(this.lastFps, this.maxFps);
      this.frames = 0;
      this.windowStart = now;
    }
  }

  setLatency(ms: number): void {
    this.maxLatency = Math.max(this.maxLatency, ms * 1.2);
    this.latency.update(ms, this.maxLatency);
  }

  setCacheBytes(bytes: number, limit: number): void {
    this.cache.update(bytes / 1048576, limit / 1048576);
  }
}
