// The e2e scene of two rooms behind a closed wall, as an ASCII PLY: room A
// x in [0, 4], room B (larger) x in [4, 10]; y in [0, 4], z in [0, 3]; the
// wall between them at x = 4; points 0.1 apart on every surface.

import { writeFileSync } from "node:fs";
import { join } from "node:path";
import type { Browser, Page } from "playwright-core";
import { launchBrowser, openPage, prepareData, startServer } from "./harness";
import type { SentRequest, Server } from "./harness";

/**
 * The rooms moved by `shift` (the file's coordinates); with a shift, the
 * coordinates are written as doubles, which float would round (0.5 apart at
 * y = 5.4e6).
 */
export function twoRoomsPly(shift: readonly number[] = [0, 0, 0]): string {
  const points: string[] = [];
  const step = 0.1;
  const plane = (axis: number, at: number, u: [number, number], v: [number, number]) => {
    const [ua, va] = axis === 0 ? [1, 2] : axis === 1 ? [0, 2] : [0, 1];
    for (let u0 = u[0]; u0 <= u[1] + 1e-9; u0 += step) {
      for (let v0 = v[0]; v0 <= v[1] + 1e-9; v0 += step) {
        const p = [0, 0, 0];
        p[axis] = at;
        p[ua!] = u0;
        p[va!] = v0;
        points.push(p.map((x, a) => (x + shift[a]!).toFixed(3)).join(" "));
      }
    }
  };
  plane(2, 0, [0.05, 9.95], [0.05, 3.95]); // floor
  plane(2, 3, [0.05, 9.95], [0.05, 3.95]); // ceiling
  plane(1, 0, [0.05, 9.95], [0.05, 2.95]);
  plane(1, 4, [0.05, 9.95], [0.05, 2.95]);
  plane(0, 0, [0.05, 3.95], [0.05, 2.95]);
  plane(0, 10, [0.05, 3.95], [0.05, 2.95]);
  plane(0, 4, [0.05, 3.95], [0.05, 2.95]); // the wall between the rooms
  const type = shift.some((x) => x !== 0) ? "double" : "float";
  const header = [
    "ply",
    "format ascii 1.0",
    `element vertex ${points.length}`,
    `property ${type} x`,
    `property ${type} y`,
    `property ${type} z`,
    "end_header",
  ];
  return [...header, ...points].join("\n") + "\n";
}

/**
 * The rooms written as `fileName` (moved by `shift`) to a fresh data folder,
 * served, and open in a page that is online with the scene loaded.
 */
export async function openTwoRooms(fileName: string, shift?: readonly number[]) {
  const data = prepareData();
  const scene = join(data, fileName);
  writeFileSync(scene, twoRoomsPly(shift));
  const server: Server = await startServer(data);
  const browser: Browser = await launchBrowser();
  const opened: { page: Page; problems: string[]; sent: SentRequest[] } = await openPage(
    browser,
    `${server.url}/?scene=${fileName}`,
  );
  await opened.page.locator("[data-testid=connection][data-state=online]").waitFor();
  await opened.page
    .locator("[data-testid=status-scene]", { hasText: fileName })
    .waitFor({ timeout: 30_000 });
  return { scene, server, browser, ...opened };
}
