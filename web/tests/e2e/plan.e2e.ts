// Scan planning in the viewer against the real server, in headless Chromium:
// two rooms joined by no door (a closed wall between them), Plan for the best
// two stations (one in each room is the known answer), the heat map, numbered
// stations and the coverage curve drawn; then the live station: dragged from
// one room to the other its visible count changes, and a burst of positions
// is traced latest-first, not queued.

import type { Browser, Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, test } from "vitest";
import { join } from "node:path";
import { runCli, screenshot, stopAll } from "./harness";
import type { SentRequest, Server } from "./harness";
import { openTwoRooms } from "./two_rooms";

let server: Server;
let browser: Browser;
let page: Page;
let problems: string[];
let sent: SentRequest[];

const liveCount = async () =>
  Number(await page.locator("[data-testid=live-count]").getAttribute("data-value"));

/** Moves a marker as a gizmo drag does (the same event the live station follows). */
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

describe("scan planning (e2e)", () => {
  beforeAll(async () => {
    ({ server, browser, page, problems, sent } = await openTwoRooms("two_rooms.ply"));
  });

  afterAll(async () => {
    await stopAll(browser, server);
  });

  test("Plan draws the heat map, one numbered station in each room and the curve", async () => {
    await page.locator("[data-testid=tab-plan]").click();
    // Its fields start from the server's declarations of the plan keys.
    // spacing's default is the server's choice (auto), said as such, never a number.
    const spacing = page.locator("[data-testid=plan-spacing]");
    expect(await spacing.getAttribute("placeholder")).toBe("auto");
    await page.locator("[data-testid=plan-stations]").fill("2");
    await page.locator("[data-testid=btn-plan]").click();
    const card = page.locator("[data-testid=plan-card]");
    await card.waitFor({ state: "visible", timeout: 90_000 });
    const request = [...sent].reverse().find((r) => r.command === "plan")!;
    expect(request.params.stations).toBe(2);
    expect(request.params.spacing).toBeUndefined(); // left to the server's default
    // The up axis offers the server's choices and, left alone, is not sent.
    const up = page.locator("[data-testid=plan-up] option");
    expect(await up.allTextContents()).toEqual([
      "default (+z)",
      "+x",
      "-x",
      "+y",
      "-y",
      "+z",
      "-z",
    ]);
    expect(request.params.up).toBeUndefined();
    // So does what to aim at for a target out of reach.
    expect(await page.locator("[data-testid=plan-out-of-reach] option").allTextContents()).toEqual([
      "default (most)",
      "most",
      "share",
    ]);
    expect(request.params.out_of_reach).toBeUndefined();
    // refine is on by default: its box is ticked and, left so, not sent.
    expect(await page.locator("[data-testid=plan-refine]").isChecked()).toBe(true);
    expect(request.params.refine).toBeUndefined();

    const coverage = Number(
      await card.locator("[data-testid=plan-coverage]").getAttribute("data-value"),
    );
    expect(coverage).toBeGreaterThan(0.9);
    const rows = card.locator("[data-testid=plan-stations] tbody tr");
    await expect.poll(() => rows.count()).toBe(2);
    expect(await card.locator("[data-testid=plan-curve] circle").count()).toBe(2);
    const state = await page.evaluate(() => {
      const app = (window as any).__occlusion.app;
      const markers = [...app.ctx.markers.markers.values()];
      return {
        squares: app.plan.layer.shown,
        stations: markers.map((m: any) => ({
          x: m.object.position.x,
          badge: m.object.children.some((c: any) => c.userData.badge === true),
        })),
      };
    });
    expect(state.squares).toBeGreaterThan(10);
    expect(state.stations).toHaveLength(2);
    expect(state.stations.every((s) => s.badge)).toBe(true);
    // The known answer: one station on each side of the wall.
    expect(state.stations.map((s) => s.x < 4).sort()).toEqual([false, true]);

    // The CLI's plan of the same file with the same question: the card shows its
    // automatic grid and its refinement's figures (refine is on by default).
    const cli = await runCli(
      ["plan", join(server.dataDir, "two_rooms.ply"), "--stations", "2", "--json", "-q"],
      240_000,
    );
    const grid = cli.candidates as { spacing: number; spacing_auto: boolean };
    expect(grid.spacing_auto).toBe(true);
    expect(await card.textContent()).toContain(`${grid.spacing.toFixed(3)} (auto)`);
    const refinement = cli.refinement as {
      coverage_before: number;
      coverage_after: number;
      stations: { moves: number; moved: number }[];
    };
    expect(refinement).not.toBeNull();
    const pct = (x: number) => `${(100 * x).toFixed(2)}%`;
    const shown = card.locator("[data-testid=plan-refinement]");
    expect(await shown.textContent()).toContain(
      `${pct(refinement.coverage_before)} → ${pct(refinement.coverage_after)}`,
    );
    const moved = refinement.stations.filter((s) => s.moves > 0);
    expect(await shown.locator("[data-testid=plan-refinement-moves] tbody tr").count()).toBe(
      moved.length,
    );
    expect(
      await shown
        .locator("[data-testid=plan-refinement-moves] tbody tr td:nth-child(4)")
        .allTextContents(),
    ).toEqual(moved.map((s) => s.moved.toFixed(3)));
    // The CLI prints 15 significant digits, the server 17: equal to within rounding.
    const shownCoverage = Number(
      await card.locator("[data-testid=plan-coverage]").getAttribute("data-value"),
    );
    expect(Math.abs(shownCoverage - (cli.coverage as number))).toBeLessThanOrEqual(1e-12);
    await screenshot(page, "plan-two-rooms");
  });

  test("the live station's visible count follows it from room to room", async () => {
    await page.locator("[data-testid=tab-plan]").click();
    await page.locator("[data-testid=plan-live]").click();
    // The live station is the selected marker (a planned station, or the first viewpoint).
    const station = await page.evaluate(
      () => (window as any).__occlusion.app.ctx.markers.selection as string,
    );
    expect(station).toBeTruthy();
    await expect.poll(liveCount, { timeout: 60_000 }).toBeGreaterThan(0);
    await drag(station, [2, 2, 1.5]);
    await expect
      .poll(() => page.evaluate(() => (window as any).__occlusion.app.plan.lastLive?.visible), {
        timeout: 30_000,
      })
      .toBeGreaterThan(0);
    await expect
      .poll(() => page.evaluate(() => (window as any).__occlusion.app.plan.live.busy))
      .toBe(false);
    const inA = await liveCount();
    await drag(station, [7, 2, 1.5]);
    await expect.poll(liveCount, { timeout: 30_000 }).not.toBe(inA);
    const inB = await liveCount();
    // Room B is larger: more of the cloud is in sight from it.
    expect(inB).toBeGreaterThan(inA);
    const legend = await page.locator("[data-testid=legend]").textContent();
    expect(legend?.length ?? 0).toBeGreaterThan(0);
    await screenshot(page, "plan-live-station");

    // A burst of positions: traced latest-first, ending where the marker ends.
    await expect
      .poll(() => page.evaluate(() => (window as any).__occlusion.app.plan.live.busy))
      .toBe(false);
    const before = sent.filter((r) => r.command === "station_view").length;
    await page.evaluate((name) => {
      const markers = (window as any).__occlusion.app.ctx.markers;
      markers.select(name);
      for (let k = 0; k <= 20; ++k) {
        markers.setPosition(name, k < 20 ? [6 + 0.05 * k, 2, 1.5] : [2, 2, 1.5]);
        markers.gizmo.dispatchEvent({ type: "objectChange" });
      }
    }, station);
    await expect.poll(liveCount, { timeout: 30_000 }).toBe(inA);
    await expect
      .poll(() => page.evaluate(() => (window as any).__occlusion.app.plan.live.busy))
      .toBe(false);
    const traced = sent.filter((r) => r.command === "station_view").length - before;
    // The first position at once, then only the last one: the 19 between were replaced.
    expect(traced).toBe(2);
    const last = [...sent].reverse().find((r) => r.command === "station_view")!;
    expect(last.params.position).toEqual([2, 2, 1.5]);
    const latency = await page.evaluate(() => (window as any).__occlusion.app.plan.lastLive);
    console.log(`live station: ${JSON.stringify(latency)}, ${traced} of 21 positions traced`);
    expect(problems).toEqual([]);
  });
});
