// Per-station answers in the viewer (issue 42): a scan of the sample room
// from two stations (`occlusion simulate`) loads with its two stations as
// markers; Compute's -fscan card lists each station (by the file's names)
// with the share it sees and the share only it sees, the CLI's figures, and
// the points can be coloured by the first station that sees them. Unticking
// a station leaves it out of the stations -fscan runs from: one viewpoint is
// sent, the card lists one station, and the points only the other station
// saw are now seen by none.

import { join } from "node:path";
import type { Browser, Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, test } from "vitest";
import {
  launchBrowser,
  openPage,
  prepareData,
  runCli,
  screenshot,
  startServer,
  stopAll,
} from "./harness";
import type { SentRequest, Server } from "./harness";
import { percent } from "../../src/ui/format";

type Report = Record<string, unknown>;
type Viewpoint = { name: string; visible_fraction: number; only_fraction: number };

const SCENE = "two_stations/sample_room.sim.ply";

let server: Server;
let browser: Browser;
let page: Page;
let problems: string[];
let sent: SentRequest[];

const scanCard = (testid: string) =>
  page.locator(`[data-testid=scan-card] [data-testid=${testid}]`).first();

/** The station table's rows: station, sees, only it (the last two rows: several, none). */
async function stationRows(): Promise<string[][]> {
  return page
    .locator("[data-testid=scan-card] [data-testid=scan-stations-table] tbody tr")
    .evaluateAll((rows) =>
      rows.map((r) => [...r.querySelectorAll("td")].map((c) => c.textContent?.trim() ?? "")),
    );
}

/** Compute, and wait until its scan has been sent and every job has ended. */
async function computeAndWait(): Promise<void> {
  const scans = () => sent.filter((r) => r.command === "scan").length;
  const before = scans();
  await page.locator("[data-testid=btn-compute]").click();
  await expect.poll(scans, { timeout: 30_000 }).toBe(before + 1);
  await expect.poll(() => page.locator("[data-testid=job]").count(), { timeout: 120_000 }).toBe(0);
  await scanCard("visible-fraction").waitFor({ timeout: 120_000 });
}

describe("per-station answers and station toggles (e2e)", () => {
  beforeAll(async () => {
    const data = prepareData();
    await runCli(
      [
        "simulate",
        join(data, "sample_room.obj"),
        "--station",
        "2,2,1.5",
        "--station",
        "6,4,1.2",
        "--azimuth-step",
        "1",
        "--elevation-step",
        "1",
      ].concat(["--out", join(data, "two_stations"), "--json", "-q"]),
    );
    server = await startServer(data);
    browser = await launchBrowser();
    ({ page, problems, sent } = await openPage(browser, `${server.url}/`));
  });

  afterAll(async () => {
    await stopAll(browser, server);
  });

  test("two stations: the table, the colours by first station, one station unticked", async () => {
    await page.goto(`${server.url}/?scene=${SCENE}`, { waitUntil: "load" });
    await page.locator("[data-testid=connection][data-state=online]").waitFor();
    await page.locator("[data-testid=viewpoint-defaults]").waitFor({ timeout: 60_000 });
    const file = join(server.dataDir, SCENE);
    const cli = await runCli(["-fscan", file, "--json", "-q"], 240_000);
    const stations = cli.viewpoints as Viewpoint[];
    expect(cli.viewpoint_source).toBe("stations of the file");
    expect(stations.length).toBe(2);
    // The markers are the file's two stations, by name.
    const labels = await page
      .locator("[data-testid=viewpoint-row]")
      .evaluateAll((rows) => rows.map((r) => r.textContent ?? ""));
    expect(labels.length).toBe(2);
    stations.forEach((s, i) => expect(labels[i]).toContain(s.name));

    await computeAndWait();
    const rows = await stationRows();
    expect(rows.length).toBe(4);
    stations.forEach((s, i) => {
      expect(rows[i]).toEqual([s.name, percent(s.visible_fraction), percent(s.only_fraction)]);
    });
    expect(rows[2]![2]).toBe(percent(cli.seen_by_several_fraction as number));
    expect(rows[3]![2]).toBe(percent(cli.seen_by_none_fraction as number));
    // The figures add up, and each station alone sees part of the room.
    const only = stations.map((s) => s.only_fraction);
    expect(
      only[0]! +
        only[1]! +
        (cli.seen_by_several_fraction as number) +
        (cli.seen_by_none_fraction as number),
    ).toBeCloseTo(1, 12);
    for (const o of only) expect(o).toBeGreaterThan(0.01);

    // Colour by the first station: the legend names the stations with the CLI's counts.
    const legend = await page.evaluate(() => {
      const ctx = (window as any).__occlusion.app.ctx;
      const ok = ctx.view.setColour("first");
      const rows = [...document.querySelectorAll("[data-testid=legend-first]")].map(
        (r) => r.textContent ?? "",
      );
      return { ok, rows };
    });
    expect(legend.ok).toBe(true);
    expect(legend.rows.length).toBe(3);
    expect(legend.rows[0]).toContain("none");
    stations.forEach((s, i) => expect(legend.rows[i + 1]).toContain(s.name));
    // One station, one colour: its marker's is the colour of its legend row,
    // of its row in the scan's table and of the points it is the first to see.
    const worn = await page.evaluate(() => {
      const ctx = (window as any).__occlusion.app.ctx;
      const rgb = (c: number[]) => `rgb(${c.map((v) => Math.round(v * 255)).join(", ")})`;
      const markers = ctx.markers.enabled().map((m: any) => rgb(ctx.markers.colour(m.name)));
      const background = (e: Element) => getComputedStyle(e).backgroundColor;
      const legendRows = [...document.querySelectorAll("[data-testid=legend-first]")];
      const legend = legendRows.slice(1).map((r) => background(r.firstElementChild!));
      const table = [...document.querySelectorAll("[data-testid=scan-station-colour]")].map(
        background,
      );
      // The first point each station is the first to see, in the cloud's "first" colours.
      const visibility = ctx.view.cloud.visibilityData;
      const points = [1, 2].map((k) => {
        const i = visibility.firstStation.indexOf(k);
        return rgb([...visibility.firstColours.slice(3 * i, 3 * i + 3)].map((v) => v / 255));
      });
      return { markers, legend, table, points };
    });
    expect(new Set(worn.markers).size).toBe(2);
    expect(worn.legend).toEqual(worn.markers);
    expect(worn.table).toEqual(worn.markers);
    expect(worn.points).toEqual(worn.markers);
    await screenshot(page, "stations-first");

    // Untick the second station: -fscan runs from the first alone.
    const scansBefore = sent.filter((r) => r.command === "scan").length;
    await page
      .locator("[data-testid=viewpoint-row]")
      .nth(1)
      .locator("[data-testid=viewpoint-enabled]")
      .uncheck();
    await computeAndWait();
    const scans = sent.filter((r) => r.command === "scan");
    expect(scans.length).toBe(scansBefore + 1);
    const last = scans[scans.length - 1]!.params as Report;
    expect((last.viewpoints as number[][]).length).toBe(1);
    const one = await stationRows();
    expect(one.length).toBe(3);
    expect(one[0]![0]).toBe(stations[0]!.name);
    // The first station keeps its marker's colour with the second unticked.
    const kept = await page.evaluate(() => {
      const ctx = (window as any).__occlusion.app.ctx;
      const name = ctx.markers.enabled()[0].name;
      const marker = ctx.markers.colour(name).map((v: number) => Math.round(v * 255));
      const dot = document.querySelector("[data-testid=scan-station-colour]")!;
      return { marker: `rgb(${marker.join(", ")})`, table: getComputedStyle(dot).backgroundColor };
    });
    expect(kept.table).toBe(kept.marker);
    // Alone, the first station sees what it saw and only it sees all of that.
    expect(one[0]![1]).toBe(percent(stations[0]!.visible_fraction));
    expect(one[0]![2]).toBe(percent(stations[0]!.visible_fraction));
    expect(one[2]![2]).toBe(percent(1 - stations[0]!.visible_fraction));
  });

  test("no uncaught errors in the page", () => {
    expect(problems.filter((p) => !/GPU stall|Failed to load resource/.test(p))).toEqual([]);
  });
});
