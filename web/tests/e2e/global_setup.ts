// Once per e2e run: start test-artifacts/ afresh, so every screenshot and
// perf.json in it comes from this run.

import { mkdirSync, rmSync } from "node:fs";
import { ARTIFACTS } from "./paths";

export default function setup(): void {
  rmSync(ARTIFACTS, { recursive: true, force: true });
  mkdirSync(ARTIFACTS, { recursive: true });
}
