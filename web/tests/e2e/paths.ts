// Where things are, for the e2e tests (no side effects: global setup imports it).

import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";

export const WEB_DIR = resolve(dirname(fileURLToPath(import.meta.url)), "../..");
export const REPO_DIR = resolve(WEB_DIR, "..");
export const ARTIFACTS = join(WEB_DIR, "test-artifacts");
