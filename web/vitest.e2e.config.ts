import { defineConfig } from "vitest/config";

// End-to-end tests: real `occlusion serve` + Debian's headless Chromium.
// One file at a time (each starts its own server and browser); every wait is
// bounded so a broken build fails instead of hanging.
export default defineConfig({
  test: {
    include: ["tests/e2e/**/*.e2e.ts"],
    globalSetup: ["tests/e2e/global_setup.ts"],
    environment: "node",
    pool: "forks",
    fileParallelism: false,
    testTimeout: 120_000,
    hookTimeout: 60_000,
    teardownTimeout: 15_000,
    reporters: ["verbose"],
  },
});
