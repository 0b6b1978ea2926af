// window.__occlusion: what the end-to-end tests read (load timings, frames
// rendered) and do (orbit for a while and report the frame rate). Also handy
// for measuring by hand in a browser console.

import { RAY_DISPLAY } from "../settings_defaults";
import type { AppContext } from "./context";
import type { Loading } from "./loading";

export function exposeForTests(app: unknown, ctx: AppContext, loading: Loading): void {
  const viewer = ctx.viewer;
  const hooks = {
    app,
    /** One entry per scene shown: click → first frame, and its parts. */
    get timings() {
      return loading.timings;
    },
    get framesRendered() {
      return viewer.framesRendered;
    },
    /** The last interval between two frames drawn in motion (ms), and the level of detail used. */
    get movingFrameMs() {
      return viewer.movingFrameMs;
    },
    /** How many escape rays are drawn per viewpoint, and above how many they start hidden. */
    rayDisplay: RAY_DISPLAY,
    get detailLevel() {
      return viewer.detailLevel;
    },
    /**
     * Orbits (OrbitControls auto-rotate) for `ms` and reports the frame rate
     * and the points drawn per frame at the end (level of detail), or at full
     * detail throughout with `fullDetail`.
     */
    orbit: async (ms: number, fullDetail = false) => {
      const start = performance.now();
      const before = viewer.framesRendered;
      viewer.lodEnabled = !fullDetail;
      viewer.controls.autoRotate = true;
      viewer.controls.autoRotateSpeed = 6;
      await new Promise((resolve) => setTimeout(resolve, ms));
      const level = viewer.detailLevel;
      viewer.controls.autoRotate = false;
      viewer.lodEnabled = true;
      const elapsed = performance.now() - start;
      const frames = viewer.framesRendered - before;
      const points = ctx.view.cloud?.data.count ?? 0;
      return {
        frames,
        ms: elapsed,
        fps: (frames * 1000) / elapsed,
        pointsDrawn: Math.ceil(points / 2 ** level),
      };
    },
  };
  (window as unknown as { __occlusion: typeof hooks }).__occlusion = hooks;
}
