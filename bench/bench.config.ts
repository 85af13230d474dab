// `npm run bench`: the benchmark runs as one long Playwright test so it shares the test
// suite's browser (pinned SwiftShader Chromium) and Vite server. BENCH_SMOKE=1 runs one
// configuration for two frames (part of `npm test`, so the bench cannot rot).
import { defineConfig } from '@playwright/test';

// The smoke run (in `npm test`) serves on a port of its own, so that `npm test` and a full `npm run bench` run side by side
// (each its own Vite; with one port the second to start found it taken and failed).
const PORT = Number(process.env.BENCH_PORT ?? (process.env.BENCH_SMOKE ? 5185 : 5184));

export default defineConfig({
  testDir: '.',
  testMatch: process.env.BENCH_ONLY ? [process.env.BENCH_ONLY] : ['bench.spec.ts', 'scenes.spec.ts', 'projection.spec.ts', 'parse.spec.ts', 'many.spec.ts', 'software.spec.ts', 'rough.spec.ts', 'gltf.spec.ts', 'pbr.spec.ts', 'refine.spec.ts'],
  outputDir: '../test-results/bench',
  workers: 1,
  retries: 0,
  timeout: 80 * 60_000,
  reporter: 'list',
  use: { baseURL: `http://127.0.0.1:${PORT}`, viewport: { width: 1400, height: 900 }, deviceScaleFactor: 1 },
  webServer: {
    command: `npx vite --port ${PORT} --strictPort`,
    cwd: '..', // the project root, which Vite serves
    url: `http://127.0.0.1:${PORT}/bench/page.html`,
    reuseExistingServer: !process.env.CI,
    timeout: 60_000,
    stdout: 'ignore',
    stderr: 'pipe',
  },
});
