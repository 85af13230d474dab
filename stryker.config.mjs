// StrykerJS: the generated-mutation check of the unit tests (README, "Mutation testing").
// Each mutant is one small change to src/ (an operator, a constant, a condition); the unit tests
// that cover it run against it, and a mutant that none of them fails on "survived".
//
//   npm run test:mutations                    every file of src/ (long: see the README)
//   npm run test:mutations:folder -- math     one folder of src/ (or several: math frame)
//   npx stryker run --mutate "src/math/**/*.ts"   the same by hand (any files; --force: no reuse)
//
// Incremental: each run stores its results and the next run re-tests only the mutants whose code
// or covering tests changed (`--force` re-runs everything). One file per scope, since a run keeps
// only the files it mutated: reports/mutation/<scope>/ (all, math, math+frame, …) holds its incremental file and reports.
// reports/ is gitignored: the results are per machine, not part of the repository.
//
// No TypeScript checker: @stryker-mutator/typescript-checker loads the JavaScript compiler API
// (TypeScript ≤ 6 under the name `typescript`), which TypeScript 7, this project's compiler, no
// longer has. A mutant that breaks the types therefore runs like any other (Vitest strips the
// types); such a mutant that survives is marked by hand in the code with a reason.
const scope = cliScope() ?? 'all';

/** The scope of a `--mutate` given on the command line ("src/math/**\/*.ts" → "math"), if any. */
function cliScope() {
  const argv = process.argv;
  const i = argv.findIndex((a) => a === '--mutate' || a === '-m' || a.startsWith('--mutate='));
  if (i < 0) return undefined;
  const value = argv[i].startsWith('--mutate=') ? argv[i].slice('--mutate='.length) : argv[i + 1] ?? '';
  const name = value
    .split(',')
    .map((p) => p.replace(/^!?src\//, '').replace(/(\/?\*\*)?\/?\*\.ts$|\.ts(:.*)?$/, ''))
    .join('+')
    .replace(/[^\w.+-]+/g, '-');
  return name || undefined;
}
const out = `reports/mutation/${scope}`;

/** @type {import('@stryker-mutator/api/core').PartialStrykerOptions} */
export default {
  mutate: ['src/**/*.ts'],
  testRunner: 'vitest',
  vitest: { configFile: 'vitest.stryker.config.ts', related: true },
  coverageAnalysis: 'perTest',
  // Stryker copies tsconfig.json into its sandbox rewritten (only for `extends`/`references` that
  // point outside it: this project has none) with TypeScript's JavaScript API, which TypeScript 7
  // lacks ("parseConfigFileTextToJson is not a function"). No such file: the copy is left as it is.
  tsconfigFile: 'tsconfig.stryker-leaves-as-is.json',
  // Two cores, shared with other work: one test runner at a time.
  concurrency: 1,
  // The unmutated, instrumented run of every test that imports the mutated files took 4.5 minutes
  // for src/math on a busy 2-core machine, near Stryker's default limit of 5; src/ as a whole runs more.
  dryRunTimeoutMinutes: 30,
  incremental: true,
  incrementalFile: `${out}/stryker-incremental.json`,
  reporters: ['html', 'clear-text', 'json', 'progress'],
  htmlReporter: { fileName: `${out}/mutation.html` },
  jsonReporter: { fileName: `${out}/mutation.json` },
  clearTextReporter: { allowEmojis: false, logTests: false, maxTestsToLog: 0 },
  thresholds: { high: 85, low: 70, break: null },
  // Build and browser-test outputs (gitignored, possibly large): not needed by the unit tests.
  ignorePatterns: ['/dist', '/dist-bench', '/test-results', '/playwright-report', '/bench/.cache', '/scratch'],
  tempDirName: '.stryker-tmp',
};
