// Re-judges the static mutants a Stryker report calls Survived, by hand: each one written into its
// file, the given unit tests run plainly (Vitest), the file restored.
//   node scripts/stryker-static.mjs reports/mutation/<scope>/mutation.json --tests "tests/unit/a.test.ts,…" [--ignored]
// --ignored: the static mutants `--ignoreStatic` left out (status Ignored) are judged too.
// Why: Stryker 9.6's Vitest runner switches a mutant on when its covering test starts; a static
// mutant (a module's constant: a table, a Set of names) was evaluated at import, before that, so it
// "survives" whatever the tests assert (stryker-js issues #6144, #6209). The README's scores count
// the mutants this script finds killed as killed, and says so.
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';

const args = process.argv.slice(2);
const report = args[0];
const t = args.indexOf('--tests');
const tests = t >= 0 ? args[t + 1].split(',').filter(Boolean) : [];
const judged = (m) => m.static && (m.status === 'Survived' || (args.includes('--ignored') && m.status === 'Ignored' && /ignoreStatic/.test(m.statusReason ?? '')));
if (!report || !tests.length) {
  console.error('usage: node scripts/stryker-static.mjs <mutation.json> --tests "a.test.ts,b.test.ts"');
  process.exit(2);
}

/** Offset of a report position (1-based line and column) in `text`. */
function offset(text, { line, column }) {
  let at = 0;
  for (let l = 1; l < line; l++) at = text.indexOf('\n', at) + 1;
  return at + column - 1;
}

const vitest = () => spawnSync('npx', ['vitest', 'run', '--reporter=dot', ...tests], { encoding: 'utf8', env: { ...process.env, GPS_MUTATION_RUN: '1' } });
const { files } = JSON.parse(fs.readFileSync(report, 'utf8'));
for (const [name, file] of Object.entries(files)) {
  if (fs.readFileSync(name, 'utf8') !== file.source) {
    console.error(`${name} differs from the report's copy: re-run Stryker first (or restore the file)`);
    process.exit(2);
  }
}
if (vitest().status !== 0) {
  console.error('the tests fail without any mutant: nothing to judge by');
  process.exit(1);
}
let killed = 0, survived = 0;
for (const [name, file] of Object.entries(files)) {
  const original = file.source;
  // Interrupted, the file is restored before leaving.
  const restore = () => { fs.writeFileSync(name, original); process.exit(130); };
  process.once('SIGINT', restore).once('SIGTERM', restore);
  for (const m of file.mutants.filter(judged)) {
    const from = offset(original, m.location.start), to = offset(original, m.location.end);
    fs.writeFileSync(name, original.slice(0, from) + m.replacement + original.slice(to));
    try {
      const dead = vitest().status !== 0;
      if (dead) killed++;
      else survived++;
      console.log(`${dead ? 'killed  ' : 'SURVIVED'} ${name}:${m.location.start.line} ${m.mutatorName} ${JSON.stringify(m.replacement).slice(0, 50)}`);
    } finally {
      fs.writeFileSync(name, original);
    }
  }
  process.removeListener('SIGINT', restore).removeListener('SIGTERM', restore);
}
console.log(`static mutants judged by hand: ${killed} killed by the tests, ${survived} survived`);
