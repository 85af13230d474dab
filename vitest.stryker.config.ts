// The unit tests' config (vitest.config.ts) as StrykerJS runs it: Stryker's instrumented code, with
// its coverage per test, runs slower, so a test gets more time before it counts as failed (a mutant
// that loops is still caught by Stryker's own timeout, from the unmutated run's times).
import { mergeConfig } from 'vitest/config';
import base from './vitest.config';

export default mergeConfig(base, { test: { testTimeout: 30_000 } });
