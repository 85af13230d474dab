import { defineConfig } from 'vitest/config';

export default defineConfig({
  test: {
    include: ['tests/unit/**/*.test.ts'],
    environment: 'node',
    // The unit tests judge results, never speed (the bench does that): a render that takes 4 s
    // alone took more than vitest's default 5 s with a mutation run beside it. A hang still fails.
    testTimeout: 60_000,
  },
});
