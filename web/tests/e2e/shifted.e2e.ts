// A cloud in UTM coordinates in the viewer, against the real server and CLI
// in headless Chromium. The readers store a cloud whose first point lies
// 1000 units or more out relative to a global shift (its coordinates rounded
// to 100: here [500000, 5400000, 0]); the viewer draws the small local
// positions and must add the shift to every position it sends and subtract
// it from every position it is sent (src/file_frame.ts). Checked: the live
// station placed in the viewer answers what `occlusion scan` answers for the
// same place given in the file's frame; the plan's limits go with the live
// station; a plan's stations are drawn in the rooms, not 5400 km away.

import { execFile } from "node:child_process";
import { promisify } from "node:util";
import type { Browser, Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, test } from "vitest";
import { SERVER_BIN, screenshot, stopAll } from "./harness";
import type { SentRequest, Server } from "./harness";
import { openTwoRooms } from "./two_rooms";

const SHIFT = [500000, 5400000, 0];

let server: Server;
let browser: Browser;
let page: Page;
let problems: string[];
let sent: SentRequest[];
let scene: string;

const liveCount = async () =>
  Number(await page.locator("[data-testid=live-count]").getAttribute("data-value"));

const liveIdle = () =>
  expect
    .poll(() => page.evaluate(() => (window as any).__occlusion.app.plan.live.busy), {
      timeout: 60_000,
    })
    .toBe(false);

/** Moves the live station (the selected marker) to a scene position, as a gizmo drag does. */
async function drag(name: string, position: number[]): Promise<void> {
  await page.evaluate(
    ([marker, p]) => {
      const markers = (window as any).__occlusion.app.ctx.markers;
      markers.select(marker);
      markers.setPosition(marker, p);
      markers.gizmo.dispatchEvent({ type: "objectChange" });
    },
    [name, position] as const,
  );
}

/** The last station_view request once its answer is on screen, and that answer's count. */
async function settledLive(): Promise<{ params: Record<string, unknown>; count: number }> {
  await liveIdle();
  const request = [...sent].reverse().find((r) => r.command === "station_view")!;
  await expect
    .poll(() => page.evaluate(() => (window as any).__occlusion.app.plan.lastLive?.visible))
    .toBeGreaterThan(0);
  return { params: request.params, count: await liveCount() };
}

/** `occlusion scan` on the file from one viewpoint, with the model keys the viewer sent. */
async function cliScan(viewpoint: number[], model: Record<string, unknown>): Promise<number> {
  const flags = Object.entries(model).flatMap(([key, value]) => [
    `--${key.replace(/_/g, "-")}`,
    String(value),
  ]);
  const { stdout } = await promisify(execFile)(
    SERVER_BIN,
    ["scan", scene, "--viewpoint", viewpoint.join(","), ...flags, "--json", "-q"],
    { timeout: 60_000 },
  );
  return Number(JSON.parse(stdout).visible_points);
}

describe("a cloud with a global shift (e2e)", () => {
  beforeAll(async () => {
    ({ scene, server, browser, page, problems, sent } = await openTwoRooms("utm_rooms.ply", SHIFT));
  });

  afterAll(async () => {
    await stopAll(browser, server);
  });

  test("the scene is drawn in its local frame and the viewpoint list shows the file's", async () => {
    const state = await page.evaluate(() => {
      const app = (window as any).__occlusion.app;
      const view = app.ctx.view;
      return {
        shift: view.info.frame.shift,
        bounds: view.cloud.data.bounds,
        markers: [...app.ctx.markers.markers.values()].map((m: any) => m.object.position.toArray()),
      };
    });
    expect(state.shift).toEqual(SHIFT);
    // float32 positions near the origin: the rooms span 10 x 4 x 3.
    expect(state.bounds.min[0]).toBeGreaterThan(-0.01);
    expect(state.bounds.max[0]).toBeLessThan(10.01);
    expect(state.bounds.max[1]).toBeLessThan(4.01);
    for (const p of state.markers) {
      expect(p[0]).toBeGreaterThan(-0.01);
      expect(p[0]).toBeLessThan(10.01);
    }
    const x = Number(await page.locator("[data-testid=viewpoint-x]").first().inputValue());
    const y = Number(await page.locator("[data-testid=viewpoint-y]").first().inputValue());
    expect(x - SHIFT[0]!).toBeCloseTo(state.markers[0][0], 2);
    expect(y - SHIFT[1]!).toBeCloseTo(state.markers[0][1], 2);
  });

  test("the live station sends the file's frame and answers as the CLI there", async () => {
    await page.locator("[data-testid=tab-plan]").click();
    await page.locator("[data-testid=plan-live]").click();
    const station = await page.evaluate(
      () => (window as any).__occlusion.app.ctx.markers.selection as string,
    );
    expect(station).toBeTruthy();
    await liveIdle();
    await drag(station, [2, 2, 1.5]);
    const inA = await settledLive();
    expect(inA.params.position).toEqual([500002, 5400002, 1.5]);
    const { path: _path, position: _position, ...model } = inA.params;
    expect(await cliScan([500002, 5400002, 1.5], model)).toBe(inA.count);

    await drag(station, [7.25, 1.5, 1.2]);
    await expect.poll(liveCount, { timeout: 30_000 }).not.toBe(inA.count);
    const inB = await settledLive();
    expect(inB.params.position).toEqual([500007.25, 5400001.5, 1.2]);
    expect(await cliScan([500007.25, 5400001.5, 1.2], model)).toBe(inB.count);
    // The larger room B shows more of the cloud.
    expect(inB.count).toBeGreaterThan(inA.count);
    await screenshot(page, "shifted-live-station");
  });

  test("the live station traces with the plan's limits: nothing beyond max_range", async () => {
    await page.locator("[data-testid=tab-plan]").click();
    const station = await page.evaluate(
      () => (window as any).__occlusion.app.ctx.markers.selection as string,
    );
    await drag(station, [7, 2, 1.5]);
    const open = await settledLive();
    expect(open.params.max_range).toBeUndefined();
    await page.locator("[data-testid=plan-max_range]").fill("2");
    await drag(station, [7, 2, 1.5 + 1e-6]);
    await expect.poll(liveCount, { timeout: 30_000 }).not.toBe(open.count);
    const near = await settledLive();
    expect(near.params.max_range).toBe(2);
    expect(near.count).toBeLessThan(open.count);
    // By hand, on the points drawn: every point seen lies within 2 of the station.
    const farthest = await page.evaluate(() => {
      const cloud = (window as any).__occlusion.app.ctx.view.cloud;
      const p = cloud.data.positions as Float32Array;
      const seen = cloud.visibilityData.visibleCount as Uint16Array;
      let far = 0;
      for (let i = 0; i < seen.length; ++i) {
        if (!seen[i]) continue;
        const d = Math.hypot(p[3 * i]! - 7, p[3 * i + 1]! - 2, p[3 * i + 2]! - 1.5);
        far = Math.max(far, d);
      }
      return far;
    });
    expect(farthest).toBeLessThanOrEqual(2 + 1e-4);
    expect(farthest).toBeGreaterThan(1.5); // the floor and ceiling around it are in range
    await page.locator("[data-testid=plan-max_range]").fill("");
  });

  test("a plan's stations stand in the two rooms, where the file's frame puts them", async () => {
    await page.locator("[data-testid=tab-plan]").click();
    await page.locator("[data-testid=plan-stations]").fill("2");
    await page.locator("[data-testid=btn-plan]").click();
    await page.locator("[data-testid=plan-card]").waitFor({ state: "visible", timeout: 90_000 });
    const state = await page.evaluate(() => {
      const app = (window as any).__occlusion.app;
      return {
        planned: app.plan.result.stations.map((s: any) => s.position),
        markers: [...app.ctx.markers.markers.values()].map((m: any) => m.object.position.toArray()),
        squares: app.plan.layer.shown,
      };
    });
    expect(state.squares).toBeGreaterThan(10);
    expect(state.markers).toHaveLength(2);
    // The report's positions are the file's; the markers stand at them minus the shift.
    state.planned.forEach((p: number[], i: number) => {
      expect(p[0]).toBeGreaterThan(SHIFT[0]!);
      for (let a = 0; a < 3; ++a) expect(state.markers[i][a]).toBeCloseTo(p[a]! - SHIFT[a]!, 4);
    });
    // The known answer: one station on each side of the wall.
    expect(state.markers.map((m: number[]) => m[0]! < 4).sort()).toEqual([false, true]);
    const request = [...sent].reverse().find((r) => r.command === "plan")!;
    expect(request.params.max_range).toBeUndefined();
  });

  test("with a plan on screen, the live station takes that plan's limits", async () => {
    await page.locator("[data-testid=tab-plan]").click();
    const station = await page.evaluate(
      () => (window as any).__occlusion.app.ctx.markers.selection as string,
    );
    // A field typed after planning does not change what the plan on screen counted.
    await page.locator("[data-testid=plan-max_range]").fill("2.5");
    await drag(station ?? "station1", [7, 2, 1.25]);
    expect((await settledLive()).params.max_range).toBeUndefined();
    // Planned with it, it goes with every live position.
    await page.evaluate(() => {
      (window as any).__planBefore = (window as any).__occlusion.app.plan.result;
    });
    await page.locator("[data-testid=btn-plan]").click();
    await expect
      .poll(() => [...sent].reverse().find((r) => r.command === "plan")?.params.max_range)
      .toBe(2.5);
    await expect
      .poll(
        () =>
          page.evaluate(
            () => (window as any).__occlusion.app.plan.result !== (window as any).__planBefore,
          ),
        { timeout: 90_000 },
      )
      .toBe(true);
    await liveIdle();
    const selected = await page.evaluate(() => {
      const markers = (window as any).__occlusion.app.ctx.markers;
      if (markers.selection === null) markers.select(markers.enabled()[0].name);
      return markers.selection as string;
    });
    await drag(selected, [7, 2, 1.3]);
    expect((await settledLive()).params.max_range).toBe(2.5);
    expect(problems).toEqual([]);
  });
});
