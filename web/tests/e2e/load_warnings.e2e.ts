// What reading a file found shows when the file is shown, before any job: a
// depth frame with depths beyond indoor sensors' (a raw SUN RGB-D PNG reads
// so) loads with the warning the CLI's -poc gives first on the same file, in
// the viewpoint panel's note; a frame within indoor depths shows none.

import { mkdirSync, writeFileSync } from "node:fs";
import { join } from "node:path";
import type { Browser, Page } from "playwright-core";
import { afterAll, beforeAll, describe, expect, test } from "vitest";
import { depthPng } from "./depth_png";
import {
  launchBrowser,
  openPage,
  prepareData,
  runCommandLine,
  screenshot,
  startServer,
  stopAll,
} from "./harness";
import type { Server } from "./harness";

const WIDTH = 16;
const HEIGHT = 12;

/** A frame of a wall `millimetres` in front of the camera (depth_scale 1000). */
function writeFrame(data: string, name: string, millimetres: number): string {
  mkdirSync(join(data, "frames"), { recursive: true });
  writeFileSync(
    join(data, "frames", `${name}.png`),
    depthPng(WIDTH, HEIGHT, new Array<number>(WIDTH * HEIGHT).fill(millimetres)),
  );
  const descriptor = {
    depth: `${name}.png`,
    intrinsics: { fx: 10, fy: 10, cx: 7.5, cy: 5.5 },
    depth_scale: 1000,
  };
  writeFileSync(join(data, "frames", `${name}.frame.json`), JSON.stringify(descriptor));
  return `frames/${name}.frame.json`;
}

let server: Server;
let browser: Browser;
let page: Page;
let problems: string[];
let far: string;
let near: string;

async function show(path: string): Promise<string[]> {
  await page.evaluate((p) => (window as any).__occlusion.app.loading.load(p), path);
  await page.locator("[data-testid=status-scene]", { hasText: path }).waitFor({ timeout: 30_000 });
  return (await page.locator("[data-testid=load-warning]").allTextContents()).map((w) =>
    w.replace(/^⚠ /, ""),
  );
}

describe("reading warnings (e2e)", () => {
  beforeAll(async () => {
    const data = prepareData();
    // 30 m: beyond the 20 m no indoor depth camera reaches.
    far = writeFrame(data, "far", 30000);
    near = writeFrame(data, "near", 2500);
    server = await startServer(data);
    browser = await launchBrowser();
    ({ page, problems } = await openPage(browser, server.url));
    await page.locator("[data-testid=connection][data-state=online]").waitFor();
  });

  afterAll(async () => {
    await stopAll(browser, server);
  });

  test("a frame beyond indoor depths shows the CLI's reading warning on load", async () => {
    const shown = await show(far);
    await screenshot(page, "load-warning-far-frame");
    const cli = await runCommandLine(`occlusion -poc ${far} --num-rays-per-vp 200`, server.dataDir);
    const warnings = cli.warnings as string[];
    expect(warnings.length).toBeGreaterThan(0);
    expect(shown).toEqual([warnings[0]]);
  });

  test("a frame within indoor depths shows none", async () => {
    expect(await show(near)).toEqual([]);
    expect(problems).toEqual([]);
  });
});
