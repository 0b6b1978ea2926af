import { defineConfig } from "vitest/config";

// `npm run dev` proxies the WebSocket to a running `occlusion serve`
// (OCCLUSION_SERVER, default 127.0.0.1:8080); `npm run build` writes dist/,
// which `occlusion serve --web web/dist` serves itself.
const server = process.env.OCCLUSION_SERVER ?? "127.0.0.1:8080";

export default defineConfig({
  base: "./",
  build: {
    outDir: "dist",
    target: "es2022",
    chunkSizeWarningLimit: 1500,
    sourcemap: true,
  },
  worker: { format: "es" },
  server: {
    proxy: { "/ws": { target: `ws://${server}`, ws: true } },
  },
  test: {
    include: ["tests/unit/**/*.test.ts"],
    environment: "node",
    testTimeout: 10_000,
  },
});
