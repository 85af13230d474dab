// Garbage collections counted around a loop: how the tests see allocation in code a frame runs.
import { PerformanceObserver, performance } from 'node:perf_hooks';

/**
 * Under StrykerJS (vitest.stryker.config.ts sets GPS_MUTATION_RUN): every function is instrumented
 * with coverage counters that allocate, so the allocation tests skip there; `npx vitest run` runs them.
 */
export const instrumented = process.env.GPS_MUTATION_RUN === '1';

/**
 * Runs `body` and counts the garbage collections that started while it ran (node's 'gc'
 * performance entries, delivered after it). Collections in the wait for that delivery — the
 * test runner's own messages — are not the body's and are not counted. `body` runs once before,
 * uncounted: compiling it allocates (feedback vectors, optimized code), which a frame loop pays
 * once, and on a young generation left nearly full by earlier tests that alone once started a
 * collection in a fresh clone's run (1, where a loop allocating 32 bytes a call starts dozens).
 */
export async function collections(body: () => void): Promise<number> {
  body();
  let count = 0, start = Infinity, end = Infinity;
  const observer = new PerformanceObserver((list) => {
    for (const e of list.getEntries()) if (e.startTime >= start && e.startTime <= end) count++;
  });
  observer.observe({ entryTypes: ['gc'] });
  start = performance.now();
  body();
  end = performance.now();
  await new Promise((r) => setTimeout(r, 50));
  observer.disconnect();
  return count;
}
