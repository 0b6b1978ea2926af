// The viewer on a real-like scan (tests/e2e/real_scan.ts: stray points far
// outside the room, no colour): framing on the robust extent, viewpoint
// editing, escape rays (count, colours, clipping), refusing an invalid
// opening, no element overflowing its panel at 1280×800 and 1920×1080, and
// frame time with level of detail. Screenshots in web/test-artifacts/.

import { existsSync, mkdirSync, writeFileSync } from "node:fs";
import { join } from "node:path";
import type { Browser, Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, test } from "vitest";
import {
  ARTIFACTS,
  canvasForeground,
  launchBrowser,
  layoutProblems,
  openPage,
  prepareData,
  screenshot,
  startServer,
  stopAll,
} from "./harness";
import type { Server } from "./harness";
import { ROOM, writeRealLikeScan } from "./real_scan";

const PATH = "real/room_scan.ply";

let server: Server;
let browser: Browser;
let page: Page;
let problems: string[];
let points = 0;
const figures: Record<string, unknown> = {};

type V = [number, number, number];
const app = () => page.evaluate(() => (window as any).__occlusion.app !== undefined);
const markerPosition = (name: string) =>
  page.evaluate((n) => (window as any).__occlusion.app.ctx.markers.position(n) as V, name);
const row = (name: string) => page.locator(`[data-testid=viewpoint-row][data-viewpoint="${name}"]`);
/** The markers of -poc's default grid of 9, as the viewer names them. */
const NAMES = Array.from({ length: 9 }, (_, k) => `default${k + 1}`);

describe("a real-like scan: stray points, no colour (e2e)", () => {
  beforeAll(async () => {
    const data = prepareData();
    points = writeRealLikeScan(join(data, PATH));
    server = await startServer(data);
    browser = await launchBrowser();
    ({ page, problems } = await openPage(browser, `${server.url}/?scene=${PATH}`));
    await page.locator("[data-testid=connection][data-state=online]").waitFor();
    expect(await app()).toBe(true);
  });

  afterAll(async () => {
    mkdirSync(ARTIFACTS, { recursive: true });
    writeFileSync(join(ARTIFACTS, "real-scan.json"), JSON.stringify(figures, null, 2) + "\n");
    console.log(`real scan: ${JSON.stringify(figures, null, 2)}`);
    await stopAll(browser, server);
  });

  test("frames the room, not the stray points; -poc's default viewpoints inside the room", async () => {
    await expect
      .poll(() => page.locator("[data-testid=status-scene]").textContent(), { timeout: 30_000 })
      .toContain(`${points.toLocaleString("en-US")} points`);
    const view = await page.evaluate(() => {
      const ctx = (window as any).__occlusion.app.ctx;
      return {
        extent: ctx.view.info.extent as { min: V; max: V },
        full: ctx.view.cloud.data.bounds as { min: V; max: V },
        target: ctx.viewer.controls.target.toArray() as V,
        distance: ctx.viewer.camera.position.distanceTo(ctx.viewer.controls.target) as number,
      };
    });
    // The strays reach tens of metres; the framed box is the room's, within 20 cm.
    expect(view.full.max[0] - view.full.min[0]).toBeGreaterThan(40);
    for (let a = 0; a < 3; ++a) {
      expect(Math.abs(view.extent.min[a]! - ROOM.min[a]!)).toBeLessThan(0.2);
      expect(Math.abs(view.extent.max[a]! - ROOM.max[a]!)).toBeLessThan(0.2);
      expect(Math.abs(view.target[a]! - (ROOM.min[a]! + ROOM.max[a]!) / 2)).toBeLessThan(0.2);
    }
    expect(view.distance).toBeLessThan(20); // the room's diagonal is 8.4 m
    // The server's defaults (-poc's grid of 9 at mid-height), as the CLI places them.
    expect(NAMES.length).toBe(9);
    for (const name of NAMES) {
      const p = await markerPosition(name);
      p.forEach((x, a) => {
        expect(x).toBeGreaterThan(ROOM.min[a]!);
        expect(x).toBeLessThan(ROOM.max[a]!);
      });
      expect(Math.abs(p[2] - 1.5)).toBeLessThan(0.1);
    }
    // The grid's middle one: the room's centre (6/2, 5/2, 3/2), within the quantiles' noise.
    const centre = await markerPosition("default5");
    [3, 2.5, 1.5].forEach((c, a) => expect(Math.abs(centre[a]! - c)).toBeLessThan(0.1));
    // Seen from outside, the near walls are cut away (the x and y slabs on the camera's side).
    const cut = () =>
      page.evaluate(() =>
        (window as any).__occlusion.app.ctx.viewer.wallPlanes.map((p: any) => p.constant as number),
      );
    expect((await cut()).every((c: number) => Number.isFinite(c))).toBe(true);
    const { foreground, total } = await canvasForeground(page, "real-01-framed-canvas");
    expect(foreground / total).toBeGreaterThan(0.15);
    await screenshot(page, "real-01-framed");
    // No colour in the file: Original Cloud says so instead of doing nothing.
    await page.locator("[data-testid=btn-original]").click();
    await page.locator("[data-testid=notice-info]", { hasText: "no colour" }).waitFor();
  });

  test("viewpoints: typed coordinates, add, remove, look from, warnings", async () => {
    await expect.poll(() => page.locator("[data-testid=viewpoint-row]").count()).toBe(9);
    // Typing x, y, z moves the marker exactly there.
    const inputs = row("default5").locator("input[data-axis]");
    await inputs.nth(0).fill("2.25");
    await inputs.nth(1).fill("1.75");
    await inputs.nth(2).fill("1.2");
    await inputs.nth(2).press("Enter");
    await inputs.nth(2).blur();
    expect(await markerPosition("default5")).toEqual([2.25, 1.75, 1.2]);
    await expect
      .poll(() => row("default5").locator("[data-testid=viewpoint-warning]").isVisible())
      .toBe(false);
    // Outside the room: warned.
    await inputs.nth(0).fill("9");
    await inputs.nth(0).press("Enter");
    await expect
      .poll(() => row("default5").locator("[data-testid=viewpoint-warning]").textContent())
      .toContain("outside the occupied space");
    // Inside an object: on a scanned point of the table top (z 0.75 m), to the millimetre.
    // Of the points at that height, the one nearest the table's centre (3, 2): walls have points at
    // 0.75 m too, and which comes first depends on the reader's point order.
    const onTable = await page.evaluate(() => {
      const d = (window as any).__occlusion.app.ctx.view.cloud.data;
      let best = [3, 2, 0.75];
      let bestDistance = Infinity;
      for (let i = 0; i < d.count; ++i) {
        if (Math.abs(d.positions[i * 3 + 2] - 0.75) >= 1e-4) continue;
        const distance = Math.hypot(d.positions[i * 3] - 3, d.positions[i * 3 + 1] - 2);
        if (distance < bestDistance) {
          bestDistance = distance;
          best = [d.positions[i * 3], d.positions[i * 3 + 1], 0.75];
        }
      }
      return best as number[];
    });
    await inputs.nth(0).fill(onTable[0]!.toFixed(3));
    await inputs.nth(1).fill(onTable[1]!.toFixed(3));
    await inputs.nth(2).fill("0.751");
    await inputs.nth(2).press("Enter");
    await expect
      .poll(() => row("default5").locator("[data-testid=viewpoint-warning]").textContent())
      .toContain("inside an object");
    await inputs.nth(2).fill("1.5");
    await inputs.nth(2).press("Enter");
    await expect
      .poll(() => row("default5").locator("[data-testid=viewpoint-warning]").isVisible())
      .toBe(false);
    // Add one, then remove it.
    await page.locator("[data-testid=viewpoint-add]").click();
    await expect.poll(() => page.locator("[data-testid=viewpoint-row]").count()).toBe(10);
    await screenshot(page, "real-02-viewpoint-added");
    await page
      .locator("[data-testid=viewpoint-row]")
      .nth(9)
      .locator("[data-testid=viewpoint-remove]")
      .click();
    await expect.poll(() => page.locator("[data-testid=viewpoint-row]").count()).toBe(9);
    // Look from the last viewpoint: the camera stands on it.
    await row("default9").locator("[data-testid=viewpoint-look]").click();
    const eye = await page.evaluate(
      () => (window as any).__occlusion.app.ctx.viewer.camera.position.toArray() as V,
    );
    const max = await markerPosition("default9");
    eye.forEach((x, a) => expect(x).toBeCloseTo(max[a]!, 6));
    // From inside the room nothing is cut.
    await page.evaluate(() => (window as any).__occlusion.app.ctx.viewer.nextFrame());
    const planes = await page.evaluate(() =>
      (window as any).__occlusion.app.ctx.viewer.wallPlanes.map((p: any) => p.constant as number),
    );
    expect(planes).toEqual([Infinity, Infinity]);
    await screenshot(page, "real-02-look-from-max");
    // Back to the overview.
    await page.evaluate(() => {
      const ctx = (window as any).__occlusion.app.ctx;
      ctx.viewer.frame(ctx.view.info.extent);
    });
  });

  test("escape rays: a sample per viewpoint, clipped to the room, in their markers' colours", async () => {
    await page.locator("[data-testid=btn-compute]").click();
    const level = page.locator("[data-testid=occlusion-card] [data-testid=occlusion-level]");
    await level.waitFor({ timeout: 90_000 });
    const rays = await page.evaluate(() => {
      const ctx = (window as any).__occlusion.app.ctx;
      const set = ctx.rays.summary;
      const lines = ctx.viewer.overlays.getObjectByName("escape-rays");
      const p = lines.geometry.getAttribute("position").array as Float32Array;
      return {
        count: ctx.rays.count as number,
        drawn: set.drawn as number[],
        total: set.total as number[],
        visible: ctx.rays.visible as boolean,
        colours: ctx.rays.segmentColours() as V[],
        markers: [...ctx.markers.markers.keys()].map((n) => ctx.markers.colour(n) as V),
        positions: Array.from(p),
        extent: ctx.view.info.extent,
      };
    });
    const { perViewpoint: limit, hiddenAbove } = await page.evaluate(
      () => (window as any).__occlusion.rayDisplay,
    );
    figures.escapes = { total: rays.total, drawn: rays.drawn };
    expect(rays.total.reduce((a, b) => a + b, 0)).toBeGreaterThan(0); // the window and door leak
    expect(rays.count).toBe(rays.drawn.reduce((a, b) => a + b, 0));
    rays.drawn.forEach((d, v) => expect(d).toBeLessThanOrEqual(Math.min(limit, rays.total[v]!)));
    // Segment colours: viewpoint v's rays in viewpoint v's marker colour.
    let k = 0;
    rays.drawn.forEach((d, v) => {
      for (let i = 0; i < d; ++i, ++k) {
        rays.colours[k]!.forEach((c, a) => expect(c).toBeCloseTo(rays.markers[v]![a]!, 5));
      }
    });
    // Every end inside the robust box (clipped where the ray leaves it).
    for (let i = 0; i < rays.positions.length; i += 3) {
      for (let a = 0; a < 3; ++a) {
        expect(rays.positions[i + a]!).toBeGreaterThanOrEqual(rays.extent.min[a] - 1e-3);
        expect(rays.positions[i + a]!).toBeLessThanOrEqual(rays.extent.max[a] + 1e-3);
      }
    }
    // Shown when few, hidden when many; a key in the same colours either way.
    const escaped = rays.total.reduce((a, b) => a + b, 0);
    expect(rays.visible).toBe(escaped <= hiddenAbove);
    expect(await page.locator("[data-testid=rays-legend-row]").count()).toBe(9);
    await screenshot(page, "real-03-escape-rays");
    // A later job replaces the result: its rays go.
    if (
      await page.evaluate(() =>
        (window as any).__occlusion.app.ctx.client.available("extract_polygons"),
      )
    ) {
      await page.locator("[data-testid=btn-polygons]").click();
      await page.locator("[data-testid=polygons-card]").waitFor({ timeout: 90_000 });
      expect(await page.evaluate(() => (window as any).__occlusion.app.ctx.rays.count)).toBe(0);
      await expect.poll(() => page.locator("[data-testid=rays-legend]").count()).toBe(0);
    }
  });

  test("an opening that crosses itself is refused with the reason, and nothing is written", async () => {
    await page.evaluate(() => {
      const ctx = (window as any).__occlusion.app.ctx;
      // A bow tie on the far wall (y = 5): corners in the wrong order.
      for (const p of [
        [2, 5, 1],
        [4, 5, 2],
        [4, 5, 1],
        [2, 5, 2],
      ])
        ctx.polygons.add(p);
      ctx.openings.setPoints(ctx.polygons.points);
    });
    await page.locator("[data-testid=save-opening]").click();
    await page.locator("[data-testid=notice-error]", { hasText: "crosses itself" }).waitFor();
    expect(await page.locator("[data-testid=opening-problem]").textContent()).toContain(
      "crosses itself",
    );
    expect(existsSync(join(server.dataDir, "openings", "room_scan.txt"))).toBe(false);
    await screenshot(page, "real-04-invalid-opening");
    await page.evaluate(() => (window as any).__occlusion.app.openingFlow.clear());
  });

  for (const [width, height] of [
    [1280, 800],
    [1920, 1080],
  ] as const) {
    test(`nothing overflows its panel at ${width}×${height}`, async () => {
      await page.setViewportSize({ width, height });
      await page.evaluate(
        () => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))),
      );
      await screenshot(page, `real-05-layout-${width}x${height}`);
      expect(await layoutProblems(page)).toEqual([]);
      // The check sees a table wider than its panel (as the confusion matrix was).
      await page.evaluate(() => {
        const wide = document.createElement("div");
        wide.id = "too-wide";
        wide.style.width = "2000px";
        wide.textContent = "wide";
        document.querySelector("[data-testid=results-occlusion]")!.append(wide);
      });
      expect((await layoutProblems(page)).join("\n")).toContain("results › div");
      await page.evaluate(() => document.getElementById("too-wide")!.remove());
    });
  }

  test("frame time drives the level of detail while orbiting; slow frame rates are shown", async () => {
    await page.setViewportSize({ width: 1400, height: 860 });
    // The cloud, as loaded (Extract Polygons showed its planes instead).
    await page.evaluate(() => {
      const ctx = (window as any).__occlusion.app.ctx;
      ctx.gui.set("showCloud", true);
      ctx.gui.set("showMesh", false);
      ctx.view.apply("showCloud");
      ctx.view.apply("showMesh");
    });
    type Orbit = { fps: number; frames: number; pointsDrawn: number };
    const orbit = (ms: number, fullDetail: boolean) =>
      page.evaluate(([t, full]) => (window as any).__occlusion.orbit(t, full) as Promise<Orbit>, [
        ms,
        fullDetail,
      ] as const);
    const full = await orbit(3000, true);
    const fullFrameMs = await page.evaluate(() => (window as any).__occlusion.movingFrameMs);
    await orbit(1500, false);
    const adaptive = await orbit(3000, false);
    const adaptiveFrameMs = await page.evaluate(() => (window as any).__occlusion.movingFrameMs);
    const shownFps = await page.evaluate(() => (window as any).__occlusion.app.stats.lastFps);
    figures.orbit = {
      points,
      fullDetail: { fps: Number(full.fps.toFixed(1)), frameMs: Math.round(fullFrameMs) },
      levelOfDetail: {
        fps: Number(adaptive.fps.toFixed(1)),
        frameMs: Math.round(adaptiveFrameMs),
        pointsDrawn: adaptive.pointsDrawn,
      },
      statsPanelFps: Number(shownFps.toFixed(1)),
    };
    expect(full.frames).toBeGreaterThan(1);
    // The stats panel shows the measured rate, however slow.
    expect(shownFps).toBeGreaterThan(0);
    // Frames slower than the 40 ms target at full detail: fewer points drawn, faster frames.
    if (fullFrameMs > 60) {
      expect(adaptive.pointsDrawn).toBeLessThan(points);
      expect(adaptive.fps).toBeGreaterThan(full.fps);
    }
    await screenshot(page, "real-06-orbited");
  });

  test("no uncaught errors in the page", () => {
    // The refused opening is reported as an error notice (also logged): expected.
    expect(
      problems.filter((p) => !/Failed to load resource|Cannot save the opening/.test(p)),
    ).toEqual([]);
  });
});
