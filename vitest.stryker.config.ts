// The unit tests' config (vitest.config.ts) as StrykerJS runs it: Stryker's instrumented code, with
// its coverage per test, runs slower (the reference's rough-glass test took over 30 s in the
// unmutated run on a busy 2-core machine), so a test gets 2 minutes before it counts as failed;
// a mutant that loops is still caught by Stryker's own timeout, from the unmutated run's times.
// STRYKER_TESTS (comma-separated globs) narrows the suite to those files: a folder's own tests
// (scripts/stryker-folder.mjs --tests). Stryker then sees them as the whole suite, so a static
// mutant (module-level code) still runs in a fresh module — which Stryker's --testFiles does not do.
import { defineConfig } from 'vitest/config';
import base from './vitest.config';

const only = process.env.STRYKER_TESTS?.split(',').filter(Boolean);

export default defineConfig({
  ...base,
  test: {
    ...base.test,
    testTimeout: 120_000,
    // Instrumented code allocates (coverage counters): the allocation tests skip (helpers/collections.ts).
    env: { GPS_MUTATION_RUN: '1' },
    ...(only?.length ? { include: only } : {}),
  },
});
