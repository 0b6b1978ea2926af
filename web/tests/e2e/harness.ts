// The end-to-end harness: a copy of the sample data in a temporary folder,
// the real `occlusion serve` on a free port (--port 0; the port is read from
// its "listening on" line), and Debian's Chromium driven by playwright-core.
// Every wait is bounded; stop() always ends the server (SIGTERM, then SIGKILL).

import { execFile, spawn } from "node:child_process";
import type { ChildProcess } from "node:child_process";
import {
  chmodSync,
  cpSync,
  existsSync,
  mkdirSync,
  mkdtempSync,
  readdirSync,
  readFileSync,
  rmSync,
  statSync,
  writeFileSync,
} from "node:fs";
import { tmpdir } from "node:os";
import { dirname, join } from "node:path";
import { chromium } from "playwright-core";
import type { Browser, Page } from "playwright-core";
import { countForeground, decodePng } from "./png";

import { ARTIFACTS, REPO_DIR, WEB_DIR } from "./paths";

export { ARTIFACTS, REPO_DIR, WEB_DIR };
export const SERVER_BIN = process.env.OCCLUSION_BIN ?? join(REPO_DIR, "build", "occlusion");
export const CHROMIUM = process.env.CHROMIUM_PATH ?? "/usr/bin/chromium";
export const BACKGROUND: [number, number, number] = [0x0b, 0x12, 0x20];

export const CHROMIUM_ARGS = [
  "--headless",
  "--no-sandbox",
  "--disable-gpu",
  "--disable-background-networking",
  "--disable-quic",
  "--no-first-run",
  "--disable-component-update",
  "--disable-sync",
  // WebGL without a GPU: ANGLE on SwiftShader (CPU Vulkan).
  "--use-angle=swiftshader",
  "--enable-unsafe-swiftshader",
  "--ignore-gpu-blocklist",
];

export interface Server {
  url: string;
  dataDir: string;
  log: () => string;
  stop: () => Promise<void>;
}

const running = new Set<ChildProcess>();

/** `timeout` leads its own process group (it and the server): signal both at once. */
function killGroup(child: ChildProcess, signal: NodeJS.Signals): void {
  try {
    if (child.pid !== undefined) process.kill(-child.pid, signal);
  } catch {
    child.kill(signal); // already gone, or no group
  }
}

const browserPidFiles = new Set<string>();

function killAll(): void {
  for (const child of running) killGroup(child, "SIGKILL");
  for (const file of browserPidFiles) {
    try {
      process.kill(-Number(readFileSync(file, "utf8").trim()), "SIGKILL");
    } catch {
      // closed already
    }
  }
}
process.on("exit", killAll);
for (const signal of ["SIGINT", "SIGTERM", "SIGHUP"] as const) {
  process.once(signal, () => {
    killAll();
    process.exit(1);
  });
}

/** The longest a test server may live, whatever happens to this process (seconds). */
const SERVER_LIFETIME = Number(process.env.E2E_SERVER_LIFETIME ?? 300);

/** A fresh copy of files/ to serve (jobs write into DATA/out, uploads into DATA/uploads). */
export function prepareData(): string {
  const root = mkdtempSync(join(tmpdir(), "occlusion-e2e-"));
  const data = join(root, "data");
  cpSync(join(REPO_DIR, "files"), data, { recursive: true });
  return data;
}

/** The newest modification time under `path` (a file or a folder). */
function newest(path: string): number {
  const stat = statSync(path);
  if (!stat.isDirectory()) return stat.mtimeMs;
  return Math.max(stat.mtimeMs, ...readdirSync(path).map((name) => newest(join(path, name))));
}

/** Fails when web/dist is missing or older than the sources it is built from. */
function checkBuild(): void {
  const built = join(WEB_DIR, "dist", "index.html");
  if (!existsSync(built)) throw new Error("e2e: no built viewer in web/dist (run `npm run build`)");
  const sources = ["src", "index.html", "vite.config.ts", "tailwind.config.js"].map((p) =>
    join(WEB_DIR, p),
  );
  if (Math.max(...sources.map(newest)) > statSync(built).mtimeMs) {
    throw new Error("e2e: web/dist is older than web/src (run `npm run build`)");
  }
}

export async function startServer(dataDir: string, timeoutMs = 20_000): Promise<Server> {
  if (!existsSync(SERVER_BIN)) {
    throw new Error(
      `e2e: no server binary at ${SERVER_BIN} (build the project, or set OCCLUSION_BIN)`,
    );
  }
  checkBuild();
  // Under coreutils' timeout: even if this process is killed outright, the
  // server ends after SERVER_LIFETIME seconds.
  const child = spawn(
    "timeout",
    [
      "--kill-after=5",
      String(SERVER_LIFETIME),
      SERVER_BIN,
      ...["serve", "--port", "0", "--data", dataDir, "--web", join(WEB_DIR, "dist")],
      ...["--workers", "2"],
    ],
    { stdio: ["ignore", "pipe", "pipe"] },
  );
  running.add(child);
  let output = "";
  const exited = new Promise<void>((done) => child.once("exit", () => done()));
  const url = await new Promise<string>((done, fail) => {
    const timer = setTimeout(
      () => fail(new Error(`e2e: server did not start in ${timeoutMs} ms:\n${output}`)),
      timeoutMs,
    );
    const onData = (chunk: Buffer) => {
      output += chunk.toString();
      const match = /listening on (http:\/\/[^\s/]+)\//.exec(output);
      if (match) {
        clearTimeout(timer);
        done(match[1]!);
      }
    };
    child.stdout!.on("data", onData);
    child.stderr!.on("data", onData);
    child.once("exit", (code) => {
      clearTimeout(timer);
      fail(new Error(`e2e: server exited with ${code} before listening:\n${output}`));
    });
  });
  const stop = async () => {
    if (child.exitCode !== null || child.signalCode !== null) return;
    child.kill("SIGTERM"); // timeout passes it on; the server stops cleanly
    const killer = setTimeout(() => killGroup(child, "SIGKILL"), 5000);
    await exited;
    clearTimeout(killer);
    running.delete(child);
  };
  return { url, dataDir, log: () => output, stop };
}

export async function launchBrowser(): Promise<Browser> {
  if (!existsSync(CHROMIUM)) {
    throw new Error(
      `e2e: no Chromium at ${CHROMIUM} (apt-get install -y chromium, or set CHROMIUM_PATH)`,
    );
  }
  // Chromium under coreutils' timeout too, through a wrapper: if this process
  // is killed before it closes the browser, the browser still ends.
  // It also leaves its process id (that of timeout, leading the browser's
  // process group) for killAll.
  const dir = mkdtempSync(join(tmpdir(), "occlusion-e2e-chromium-"));
  const wrapper = join(dir, "chromium");
  const pidFile = join(dir, "pid");
  writeFileSync(
    wrapper,
    `#!/bin/sh\necho $$ > '${pidFile}'\n` +
      `exec timeout --kill-after=5 ${SERVER_LIFETIME} '${CHROMIUM}' "$@"\n`,
  );
  chmodSync(wrapper, 0o755);
  browserPidFiles.add(pidFile);
  const browser = await chromium.launch({
    executablePath: wrapper,
    headless: true,
    args: CHROMIUM_ARGS,
    timeout: 30_000,
  });
  browser.on("disconnected", () => {
    browserPidFiles.delete(pidFile);
    rmSync(dir, { recursive: true, force: true });
  });
  return browser;
}

/** A request the page sent over its WebSocket (docs/protocol.md). */
export interface SentRequest {
  id: number;
  command: string;
  params: Record<string, unknown>;
}

/**
 * A page that fails the test on uncaught errors; console errors are collected,
 * and so is every request the page sends (`sent`, oldest first).
 */
export async function openPage(browser: Browser, url: string) {
  const page = await browser.newPage({ viewport: { width: 1400, height: 860 } });
  page.setDefaultTimeout(30_000);
  const problems: string[] = [];
  const sent: SentRequest[] = [];
  page.on("websocket", (socket) =>
    socket.on("framesent", ({ payload }) => {
      if (typeof payload !== "string") return;
      try {
        const message = JSON.parse(payload) as Partial<SentRequest>;
        if (typeof message.command === "string") {
          sent.push({
            id: Number(message.id),
            command: message.command,
            params: message.params ?? {},
          });
        }
      } catch {
        // not JSON: the server answers that, not this test
      }
    }),
  );
  page.on("pageerror", (error) => problems.push(`pageerror: ${error.message}`));
  page.on("console", (message) => {
    if (message.type() === "error") problems.push(`console: ${message.text()}`);
  });
  await page.goto(url, { waitUntil: "load" });
  return { page, problems, sent };
}

/** Where the Python module of the server's build is (build/python beside build/occlusion). */
export const PYTHON_DIR = process.env.OCCLUSION_PYTHON_DIR ?? join(dirname(SERVER_BIN), "python");

function run(
  file: string,
  args: string[],
  options: { cwd: string; env?: NodeJS.ProcessEnv },
  timeoutMs: number,
): Promise<Record<string, unknown>> {
  return new Promise((done, fail) => {
    execFile(
      file,
      args,
      { ...options, timeout: timeoutMs, maxBuffer: 64 << 20 },
      (error, stdout, stderr) => {
        if (error) {
          fail(new Error(`e2e: ${file} ${args.join(" ")} failed: ${error.message}\n${stderr}`));
          return;
        }
        done(JSON.parse(stdout) as Record<string, unknown>);
      },
    );
  });
}

/**
 * Runs a command line the viewer shows ("occlusion -poc PATH ..." as the
 * server wrote it, shell-quoted) in `dir` with the server's binary, and
 * returns the report it prints with --json.
 */
export function runCommandLine(
  command: string,
  dir: string,
  timeoutMs = 120_000,
): Promise<Record<string, unknown>> {
  if (!command.startsWith("occlusion ")) throw new Error(`e2e: not a command line: ${command}`);
  const script = `exec "$0" ${command.slice("occlusion ".length)} --json -q`;
  return run("/bin/sh", ["-c", script, SERVER_BIN], { cwd: dir }, timeoutMs);
}

/**
 * Runs a Python call the viewer shows ("occlusion.cloud_occlusion(...)") in
 * `dir` with the build's module, and returns its report; null when the build
 * has no Python module.
 */
export function runPythonCall(
  call: string,
  dir: string,
  timeoutMs = 120_000,
): Promise<Record<string, unknown>> | null {
  if (!existsSync(PYTHON_DIR)) return null;
  const script = `import json, occlusion\nprint(json.dumps((${call}).report))`;
  const env = { ...process.env, PYTHONPATH: PYTHON_DIR };
  return run("/usr/bin/python3", ["-c", script], { cwd: dir, env }, timeoutMs);
}

/** Runs the CLI (the server's binary) and returns the report it prints with --json. */
export function runCli(args: string[], timeoutMs = 120_000): Promise<Record<string, unknown>> {
  return run(SERVER_BIN, args, { cwd: process.cwd() }, timeoutMs);
}

export async function screenshot(page: Page, name: string): Promise<string> {
  mkdirSync(ARTIFACTS, { recursive: true });
  const path = join(ARTIFACTS, `${name}.png`);
  await page.screenshot({ path });
  return path;
}

/** Non-background pixels of the 3D canvas, with the HTML overlays hidden. */
export async function canvasForeground(
  page: Page,
  name?: string,
): Promise<{ foreground: number; total: number }> {
  const overlays = "#gui, #stats, #legend, #jobs, #notices, #scene-hint";
  await page.evaluate((selector) => {
    document
      .querySelectorAll<HTMLElement>(selector)
      .forEach((e) => (e.style.visibility = "hidden"));
  }, overlays);
  // Two animation frames: the last render is on screen.
  await page.evaluate(
    () => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))),
  );
  const png = await page.locator("[data-testid=viewer-canvas]").screenshot();
  if (name) {
    mkdirSync(ARTIFACTS, { recursive: true });
    writeFileSync(join(ARTIFACTS, `${name}.png`), png);
  }
  await page.evaluate((selector) => {
    document.querySelectorAll<HTMLElement>(selector).forEach((e) => (e.style.visibility = ""));
  }, overlays);
  const image = decodePng(png);
  return { foreground: countForeground(image, BACKGROUND), total: image.width * image.height };
}

export function removeData(dataDir: string): void {
  rmSync(dirname(dataDir), { recursive: true, force: true });
}

/** After a file's tests: the browser closed, the server stopped, its data removed (each if started). */
export async function stopAll(browser?: Browser, server?: Server): Promise<void> {
  await browser?.close().catch(() => undefined);
  await server?.stop();
  if (server) removeData(server.dataDir);
}

/**
 * Elements that stick out of their panel (header, sidebar, 3-D view, results,
 * footer) or whose text is cut (an ellipsis, or a clipped lil-gui name),
 * read from the DOM: "panel › tag.class 'text' (why)".
 */
export async function layoutProblems(page: Page): Promise<string[]> {
  return page.evaluate(() => {
    const problems: string[] = [];
    const describe = (e: Element) =>
      `${e.tagName.toLowerCase()}.${String(e.className).split(" ").slice(0, 3).join(".")} ` +
      `'${(e.textContent ?? "").trim().slice(0, 40)}'`;
    const panels: [string, Element | null][] = [
      ["header", document.querySelector("header")],
      ["sidebar", document.getElementById("sidebar")],
      ["stage", document.getElementById("stage")],
      ["results", document.getElementById("results")],
      ["footer", document.querySelector("footer")],
    ];
    for (const [name, panel] of panels) {
      if (!panel) {
        problems.push(`${name}: missing`);
        continue;
      }
      const box = panel.getBoundingClientRect();
      if (box.right > window.innerWidth + 1 || box.bottom > window.innerHeight + 1) {
        problems.push(`${name}: outside the window`);
      }
      for (const e of panel.querySelectorAll("*")) {
        const r = e.getBoundingClientRect();
        if (r.width === 0 || r.height === 0) continue;
        const style = getComputedStyle(e);
        if (style.visibility === "hidden") continue;
        if (r.right > box.right + 1 || r.left < box.left - 1) {
          problems.push(
            `${name} › ${describe(e)} (sticks out ${Math.round(r.right - box.right)} px)`,
          );
        }
        const clipped = style.textOverflow === "ellipsis" || e.classList.contains("lil-name");
        if (clipped && e.scrollWidth > e.clientWidth + 1) {
          problems.push(`${name} › ${describe(e)} (text cut)`);
        }
      }
    }
    const gui = document.getElementById("gui")!.getBoundingClientRect();
    const stage = document.getElementById("stage")!.getBoundingClientRect();
    if (
      gui.left < stage.right &&
      gui.right > stage.left &&
      gui.top < stage.bottom &&
      gui.bottom > stage.top
    ) {
      problems.push("the GUI panel covers the 3-D view");
    }
    return problems;
  });
}
