// StrykerJS on some folders of src/ only: `npm run test:mutations:folder -- math [frame …] [stryker flags]`.
// Runs `stryker run --mutate "src/math/**/*.ts,src/frame/**/*.ts"`; stryker.config.mjs names the
// scope from that (reports/mutation/math+frame/: reports and the incremental file of that scope).
// From the first word starting with "-" on, the words go to Stryker as they are: --force re-tests
// every mutant; --testFiles "tests/unit/a.test.ts,…" runs only those tests (the folder's own tests:
// much faster than every test that imports the folder, and stricter).
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';

const args = process.argv.slice(2);
const firstFlag = args.findIndex((a) => a.startsWith('-'));
const folders = firstFlag < 0 ? args : args.slice(0, firstFlag);
const flags = firstFlag < 0 ? [] : args.slice(firstFlag);
if (!folders.length) {
  console.error('usage: npm run test:mutations:folder -- <folder of src/> [more folders] [stryker flags]');
  process.exit(2);
}
for (const f of folders) {
  if (!/^[\w-]+(\/[\w-]+)*$/.test(f) || !fs.statSync(`src/${f}`, { throwIfNoEntry: false })?.isDirectory()) {
    console.error(`no folder src/${f}`);
    process.exit(2);
  }
}
const mutate = folders.map((f) => `src/${f}/**/*.ts`).join(',');
const run = spawnSync('npx', ['stryker', 'run', '--mutate', mutate, ...flags], { stdio: 'inherit' });
process.exit(run.status ?? 1);
