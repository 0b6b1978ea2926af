// One answer whatever the door (issue 41): on a real scan (room_scan1.pcd, no
// stations: -poc's grid of 9 on the robust frame, with the CLI's up warning),
// an E57 file (its scan's station), and a laser station's gridded scan (from
// `occlusion simulate`: rays outside its window), a project of four scans in
// four formats with their poses (its scans' stations), the viewer places the CLI's
// default viewpoints, warns as the CLI does (never at a station), and its
// -poc and -fscan figures from the defaults are the CLI's with nothing given,
// the command line its card shows and the Python call; the level's counts add
// up. Figures in web/test-artifacts/defaults.json.

import { mkdirSync, writeFileSync } from "node:fs";
import { join } from "node:path";
import type { Browser, Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, test } from "vitest";
import {
  ARTIFACTS,
  launchBrowser,
  openPage,
  prepareData,
  runCli,
  runCommandLine,
  runPythonCall,
  screenshot,
  startServer,
  stopAll,
} from "./harness";
import type { Server } from "./harness";

type V = [number, number, number];
type Report = Record<string, unknown>;

const SIMULATED = "sim/sample_room.sim.ply";
const SCENES = [
  "pcl/room_scan1.pcd",
  "e57/bunnyInt32.e57",
  SIMULATED,
  // Four scans in four formats with their poses: the stations where the poses put them.
  "projects/mixed.project.json",
];

let server: Server;
let browser: Browser;
let page: Page;
let problems: string[];
const figures: Record<string, unknown> = {};

const card = (id: string, testid: string) =>
  page.locator(`[data-testid=${id}] [data-testid=${testid}]`).first();

async function show(path: string): Promise<void> {
  await page.goto(`${server.url}/?scene=${path}`, { waitUntil: "load" });
  await page.locator("[data-testid=connection][data-state=online]").waitFor();
  await expect
    .poll(() => page.locator("[data-testid=status-scene]").textContent(), { timeout: 60_000 })
    .toContain(path);
  await page.locator("[data-testid=viewpoint-defaults]").waitFor({ timeout: 30_000 });
}

/** The markers as the viewer holds them, in the file's frame (what jobs and reports use). */
function markers(): Promise<{ label: string; position: V; warning: string }[]> {
  return page.evaluate(() => {
    const ctx = (window as any).__occlusion.app.ctx;
    return [...ctx.markers.markers.values()].map((m: any) => ({
      label: m.label as string,
      position: ctx.view.frame.toFile(m.object.position.toArray()) as V,
      warning:
        document.querySelector(
          `[data-testid=viewpoint-row][data-viewpoint="${m.name}"] [data-testid=viewpoint-warning]`,
        )?.textContent ?? "",
    }));
  });
}

/** The same figure: the CLI prints 15 significant digits, the server's JSON all 17. */
function expectSame(a: unknown, b: unknown): void {
  expect(typeof a).toBe("number");
  expect(Math.abs((a as number) - (b as number))).toBeLessThanOrEqual(1e-12);
}

function expectAddsUp(report: Report): void {
  const n = (key: string) => report[key] as number;
  expect(n("hits") + n("through_openings") + n("occlusion_rays") + n("outside_view_rays")).toBe(
    n("rays"),
  );
  expect(n("rays_in_view")).toBe(n("rays") - n("outside_view_rays"));
  expect(n("occlusion_level")).toBeCloseTo(n("occlusion_rays") / n("rays_in_view"), 14);
}

describe("the viewer's defaults are the CLI's (e2e)", () => {
  beforeAll(async () => {
    const data = prepareData();
    // A laser station's gridded scan of the sample room, as the simulator writes it.
    await runCli(
      [
        "simulate",
        join(data, "sample_room.obj"),
        "--station",
        "2,2,1.5",
        "--azimuth-step",
        "0.5",
        "--elevation-step",
        "0.5",
      ].concat(["--out", join(data, "sim"), "--json", "-q"]),
    );
    server = await startServer(data);
    browser = await launchBrowser();
    ({ page, problems } = await openPage(browser, `${server.url}/`));
  });

  afterAll(async () => {
    mkdirSync(ARTIFACTS, { recursive: true });
    writeFileSync(join(ARTIFACTS, "defaults.json"), JSON.stringify(figures, null, 2) + "\n");
    await stopAll(browser, server);
  });

  for (const path of SCENES) {
    test(`${path}: the same viewpoints, warnings and figures as the CLI`, async () => {
      await show(path);
      const file = join(server.dataDir, path);
      const [poc, scan] = await Promise.all([
        runCli(["-poc", file, "--json", "-q"], 240_000),
        runCli(["-fscan", file, "--json", "-q"], 240_000),
      ]);
      // The markers are -poc's viewpoints, by name and position.
      const shown = await markers();
      const expected = poc.viewpoints as { name: string; position: V }[];
      expect(shown.map((m) => m.label)).toEqual(expected.map((v) => v.name));
      shown.forEach((m, i) =>
        m.position.forEach((x, a) => expect(x).toBeCloseTo(expected[i]!.position[a]!, 6)),
      );
      if (path.startsWith("projects/")) {
        // Its four scans' stations, where their poses put them (files/projects/SOURCES.md).
        const byHand: V[] = [
          [5, 4, 6],
          [2, 0, 0],
          [0, 7, 0.5],
          [0, 3, 0],
        ];
        expect(shown.length).toBe(4);
        shown.forEach((m, i) =>
          m.position.forEach((x, a) => expect(x).toBeCloseTo(byHand[i]![a]!, 6)),
        );
      }
      // A viewpoint is warned about where the CLI warns about it, and only there.
      const cliWarnings = (poc.warnings as string[]).join("\n");
      shown.forEach((m, i) =>
        expect(m.warning.includes("outside the occupied space")).toBe(
          cliWarnings.includes(`viewpoint ${expected[i]!.name} at`),
        ),
      );
      // The job's warnings about its defaults (e.g. up) are the CLI's.
      for (const warning of await page
        .locator("[data-testid=viewpoint-defaults-warning]")
        .allTextContents()) {
        expect(poc.warnings as string[]).toContain(warning.replace(/^⚠ /, ""));
      }
      await page.locator("[data-testid=btn-compute]").click();
      await card("occlusion-card", "occlusion-level").waitFor({ timeout: 240_000 });
      await card("scan-card", "visible-fraction").waitFor({ timeout: 240_000 });
      await expect
        .poll(() => page.locator("[data-testid=job]").count(), { timeout: 60_000 })
        .toBe(0);
      await screenshot(page, `defaults-${path.replace(/\W+/g, "-")}`);
      const viewer = {
        occlusion_level: Number(
          await card("occlusion-card", "occlusion-level").getAttribute("data-value"),
        ),
        level_counts: await card("occlusion-card", "level-counts").textContent(),
        visible_fraction: Number(
          await card("scan-card", "visible-fraction").getAttribute("data-value"),
        ),
      };
      // The commands the cards show, run in the data directory, and the Python call.
      const shownPoc = await runCommandLine(
        (await card("occlusion-card", "reproduce-cli").textContent())!,
        server.dataDir,
        240_000,
      );
      const shownScan = await runCommandLine(
        (await card("scan-card", "reproduce-cli").textContent())!,
        server.dataDir,
        240_000,
      );
      const python = runPythonCall(
        (await card("occlusion-card", "reproduce-python").textContent())!,
        server.dataDir,
        240_000,
      );
      figures[path] = {
        viewer,
        cli: {
          occlusion_level: poc.occlusion_level,
          level_counts: poc.level_counts,
          visible_fraction: scan.visible_fraction,
          warnings: poc.warnings,
        },
      };
      expectSame(viewer.occlusion_level, poc.occlusion_level);
      expect(viewer.level_counts).toBe(poc.level_counts);
      expectSame(viewer.visible_fraction, scan.visible_fraction);
      expectSame(shownPoc.occlusion_level, poc.occlusion_level);
      expect(shownPoc.level_counts).toBe(poc.level_counts);
      expectSame(shownScan.visible_fraction, scan.visible_fraction);
      if (python) {
        const report = await python;
        expectSame(report.occlusion_level, poc.occlusion_level);
        expect(report.level_counts).toBe(poc.level_counts);
      }
      expectAddsUp(poc);
      for (const v of poc.viewpoints as Report[]) expectAddsUp(v);
      if (path === SIMULATED) {
        // From its own station the scanner's blind cones are outside the view, and said so.
        expect(poc.outside_view_rays as number).toBeGreaterThan(0);
        expect(viewer.level_counts).toContain("outside the field of view of station");
      }
    });
  }

  test("no uncaught errors in the page", () => {
    expect(problems.filter((p) => !/GPU stall|Failed to load resource/.test(p))).toEqual([]);
  });
});
