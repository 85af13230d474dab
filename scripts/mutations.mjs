// The browser's mutation check (`npm run test:mutations:browser`): the hand-written mutations that
// StrykerJS (`npm run test:mutations`, stryker.config.mjs) cannot reach. Stryker mutates src/**/*.ts
// and runs the unit tests; what is left here is what only a browser sees or what lies outside
// src/: the GLSL of shaders/, the WebGL passes, the element in a page (DOM, events, workers, lazy
// chunks), scripts/ and the build. Each entry says why in its `why`, required (the run stops at
// load without one); a mutation the unit tests alone catch in src/ belongs to Stryker, not here.
//
// Each mutation (scripts/mutations/*.mjs) breaks one pass on purpose in a temporary copy of the
// repository and runs the tests meant to catch it. A mutation is "caught" when at least one of
// those tests fails, "missed" when they all pass, "stale" when its search text is no longer in the
// file exactly once (the code moved: fix the table, never skip it), and "error" when the run failed
// without a failing test (a server that did not start, a crash). An unmutated baseline runs first;
// if it fails, the table would mean nothing, so it stops there.
//
//   npm run test:mutations:browser                   every mutation
//   npm run test:mutations:browser -- controls       only one area (a file of scripts/mutations/), one
//                                                    mutation by its id (Z14), or those whose name
//                                                    contains the word; several may be given (the
//                                                    baseline still runs)
//   … -- --area lazy --area build                    areas only: a word that names an area is never read as part of a name
//   … -- --list                                      the chosen mutations, each with its why and tests; nothing runs
//   KEEP_MUTANTS=1 …                                 leave the temporary copies in place
//
// Logs: test-results/mutations/<name>.log. Not part of `npm test`: it runs the relevant specs
// once per mutation, each time with a fresh Vite (about 2–3 minutes on 2 cores).
import { spawn, execFileSync } from 'node:child_process';
import fs from 'node:fs';
import net from 'node:net';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const LOG_DIR = path.join(ROOT, 'test-results', 'mutations');

/**
 * The mutations, one file per area under scripts/mutations/ (glass, controls, lazy, …): each
 * exports an array of { name, why, edits: [{ file, find, replace }], tests }. The area is the
 * file's name; `why` says what keeps the mutation out of StrykerJS's reach, and none may lack it.
 */
const MUTATIONS_DIR = path.join(ROOT, 'scripts', 'mutations');
const MUTATIONS = [];
for (const file of fs.readdirSync(MUTATIONS_DIR).filter((f) => f.endsWith('.mjs')).sort()) {
  const area = file.replace(/\.mjs$/, '');
  const { default: list } = await import(pathToFileURL(path.join(MUTATIONS_DIR, file)).href);
  for (const m of list) {
    if (typeof m.why !== 'string' || !m.why.trim()) {
      console.error(`mutations: scripts/mutations/${file}: "${m.name}" has no why (say what keeps it out of StrykerJS's reach, or retire it: Stryker generates what the unit tests alone catch in src/)`);
      process.exit(2);
    }
    MUTATIONS.push({ ...m, area });
  }
}

const occurrences = (text, find) => text.split(find).length - 1;

/** The working tree as it is (tracked and untracked, not ignored), without node_modules. */
function sourceFiles() {
  const out = execFileSync('git', ['ls-files', '-z', '--cached', '--others', '--exclude-standard'], { cwd: ROOT });
  return out.toString('utf8').split('\0').filter((f) => f && fs.existsSync(path.join(ROOT, f)));
}

/**
 * A copy of the repository in a temporary directory. node_modules is a real directory of
 * symlinks to the checkout's packages: no reinstall, while Vite's dependency cache
 * (node_modules/.vite) stays private to the copy instead of being shared with the checkout's.
 */
function makeCopy(label) {
  // The run's pid in the name: two runs side by side (or one's leftovers) never share a folder.
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), `gps-mutant-${process.pid}-${label.replace(/\W+/g, '-').slice(0, 30)}-`));
  for (const f of sourceFiles()) {
    const to = path.join(dir, f);
    fs.mkdirSync(path.dirname(to), { recursive: true });
    fs.copyFileSync(path.join(ROOT, f), to);
  }
  const modules = path.join(dir, 'node_modules');
  fs.mkdirSync(modules);
  for (const entry of fs.readdirSync(path.join(ROOT, 'node_modules'))) {
    if (entry === '.vite') continue;
    fs.symlinkSync(path.join(ROOT, 'node_modules', entry), path.join(modules, entry));
  }
  return dir;
}

/** Applies the edits; returns why the mutation is stale, or null. */
function applyEdits(dir, edits) {
  for (const { file, find, replace } of edits) {
    const p = path.join(dir, file);
    const text = fs.existsSync(p) ? fs.readFileSync(p, 'utf8') : '';
    const n = occurrences(text, find);
    if (n !== 1) return `${file}: search text found ${n} times`;
    fs.writeFileSync(p, text.replace(find, () => replace));
  }
  return null;
}

function freePort() {
  return new Promise((resolve, reject) => {
    const server = net.createServer();
    server.unref();
    server.on('error', reject);
    server.listen(0, '127.0.0.1', () => {
      const { port } = server.address();
      server.close(() => resolve(port));
    });
  });
}

function run(cmd, args, cwd, env, log) {
  return new Promise((resolve) => {
    const child = spawn(cmd, args, { cwd, env: { ...process.env, ...env }, stdio: ['ignore', 'pipe', 'pipe'] });
    let output = '';
    const take = (d) => {
      output += d;
      log.write(d);
    };
    child.stdout.on('data', take);
    child.stderr.on('data', take);
    child.on('close', (code, signal) => resolve({ code: code ?? 1, signal, output }));
  });
}

const strip = (s) => s.replace(/\x1b\[[0-9;]*m/g, '');

/**
 * Runs `tests` in `dir`: Playwright for *.spec.ts (own Vite on a free port), vitest for *.test.ts.
 * `build`: the library is built first (both vite builds), for specs that load dist/.
 */
async function runTests(dir, tests, logName, build = false) {
  fs.mkdirSync(LOG_DIR, { recursive: true });
  const log = fs.createWriteStream(path.join(LOG_DIR, `${logName.replace(/\W+/g, '-')}.log`));
  if (build) {
    for (const args of [['vite', 'build'], ['vite', 'build', '--mode', 'standalone']]) {
      const b = await run('npx', args, dir, {}, log);
      if (b.code !== 0) {
        log.end();
        return { failed: 0, passed: 0, failures: [], errors: [`the build failed (${args.join(' ')})`] };
      }
    }
  }
  const specs = tests.filter((t) => t.endsWith('.spec.ts'));
  const units = tests.filter((t) => t.endsWith('.test.ts'));
  const result = { failed: 0, passed: 0, failures: [], errors: [] };
  const runs = [];
  if (specs.length) {
    const port = await freePort();
    // CI=1: its own Vite (reuseExistingServer is off), serving this copy and nothing else.
    runs.push(['playwright', await run('npx', ['playwright', 'test', ...specs, '--reporter=list'], dir, { CI: '1', PLAYWRIGHT_PORT: String(port) }, log)]);
  }
  if (units.length) runs.push(['vitest', await run('npx', ['vitest', 'run', ...units], dir, { CI: '1' }, log)]);
  log.end();
  for (const [runner, r] of runs) {
    const out = strip(r.output);
    const failed = runner === 'vitest' ? out.match(/Tests\s+(\d+) failed/) : out.match(/^\s+(\d+) failed/m);
    const passed = runner === 'vitest' ? out.match(/Tests\s+(?:\d+ failed \| )?(\d+) passed/) : out.match(/^\s+(\d+) passed/m);
    result.failed += failed ? Number(failed[1]) : 0;
    result.passed += passed ? Number(passed[1]) : 0;
    if (runner === 'playwright') {
      for (const m of out.matchAll(/^\s+\d+\) \S+?:\d+:\d+ › (.+?) ─*$/gm)) result.failures.push(m[1].trim());
    } else {
      // vitest names a failing test twice (a × line in the run, a FAIL line in the summary): the FAIL lines alone.
      for (const m of new Set([...out.matchAll(/^\s*FAIL\s+(.+)$/gm)].map((x) => x[1].trim()))) result.failures.push(m);
    }
    // A non-zero exit with no failing test is not a catch: the run itself broke.
    if (r.code !== 0 && !failed) result.errors.push(`${runner} exited ${r.signal ?? r.code} with no failing test`);
  }
  return result;
}

function table(rows) {
  const head = ['area', 'mutation', 'why not Stryker', 'result', 'tests failed / run', 'caught by', 'time'];
  const body = rows.map((r) => [r.area, r.name, r.why, r.status, r.counts, r.by, r.time]);
  const widths = head.map((h, i) => Math.max(h.length, ...body.map((b) => b[i].length)));
  const line = (cells) => `| ${cells.map((c, i) => c.padEnd(widths[i])).join(' | ')} |`;
  return [line(head), `|${widths.map((w) => '-'.repeat(w + 2)).join('|')}|`, ...body.map(line)].join('\n');
}

const seconds = (t0) => `${((Date.now() - t0) / 1000).toFixed(0)} s`;

/** `--area NAME` pairs (areas) apart from the other words (filters); `--list`: list, run nothing. */
export function parseArguments(args) {
  const areas = [], filters = [];
  let list = false;
  for (let i = 0; i < args.length; i++) {
    if (args[i] === '--list') list = true;
    else if (args[i] === '--area') areas.push(args[++i] ?? '');
    else if (args[i].startsWith('--area=')) areas.push(args[i].slice('--area='.length));
    else filters.push(args[i]);
  }
  return { areas, filters, list };
}

async function main() {
  // Each argument: an area, a mutation's id ("Z14": that one only), or a word of its name;
  // `--area NAME`: that area, and nothing else by that word.
  const { areas, filters, list } = parseArguments(process.argv.slice(2));
  const id = (m) => m.name.split(' ')[0];
  const picks = (m, f) => m.area === f || (/^[A-Z]+\d+$/.test(f) ? id(m) === f : m.name.includes(f));
  const chosen = MUTATIONS.filter((m) => (!filters.length && !areas.length) || areas.includes(m.area) || filters.some((f) => picks(m, f)));
  const unknown = areas.filter((a) => !MUTATIONS.some((m) => m.area === a));
  if (unknown.length) {
    console.error(`mutations: no area ${unknown.join(', ')} (areas: ${[...new Set(MUTATIONS.map((m) => m.area))].join(', ')})`);
    process.exit(2);
  }
  if (!chosen.length) {
    console.error(`mutations: none matches ${filters.join(' ')}`);
    process.exit(2);
  }
  if (list) {
    for (const m of chosen) console.log(`${m.area}: ${m.name}\n    why: ${m.why}\n    tests: ${m.tests.join(' ')}${m.build ? ' (built first)' : ''}`);
    const areaCounts = [...new Set(chosen.map((m) => m.area))].map((a) => `${a} ${chosen.filter((m) => m.area === a).length}`);
    console.log(`\n${chosen.length} mutations (${areaCounts.join(', ')})`);
    return;
  }
  const started = Date.now();
  const dirs = [];
  const cleanup = () => {
    if (process.env.KEEP_MUTANTS === '1') return;
    for (const d of dirs.splice(0)) fs.rmSync(d, { recursive: true, force: true });
  };
  process.on('SIGINT', () => {
    cleanup();
    process.exit(130);
  });

  // Baseline: every spec the chosen mutations use, unmutated.
  const allTests = [...new Set(chosen.flatMap((m) => m.tests))];
  let t0 = Date.now();
  console.log(`baseline: ${allTests.join(' ')}`);
  const baseDir = makeCopy('baseline');
  dirs.push(baseDir);
  const base = await runTests(baseDir, allTests, 'baseline', chosen.some((m) => m.build));
  cleanup();
  console.log(`baseline: ${base.passed} passed, ${base.failed} failed (${seconds(t0)})`);
  if (base.failed || base.errors.length || !base.passed) {
    console.error(`mutations: the baseline does not pass (${[...base.failures, ...base.errors].join('; ')}); see ${path.relative(ROOT, LOG_DIR)}/baseline.log`);
    process.exit(2);
  }

  const rows = [];
  for (const m of chosen) {
    t0 = Date.now();
    const dir = makeCopy(m.name);
    dirs.push(dir);
    const stale = applyEdits(dir, m.edits);
    let row;
    if (stale) {
      row = { area: m.area, name: m.name, why: m.why, status: 'STALE', counts: '-', by: stale, time: seconds(t0) };
    } else {
      const r = await runTests(dir, m.tests, m.name, m.build === true);
      const status = r.errors.length ? 'ERROR' : r.failed > 0 ? 'caught' : 'MISSED';
      const by = r.errors.length ? r.errors.join('; ') : r.failures.join('; ') || '-';
      row = { area: m.area, name: m.name, why: m.why, status, counts: `${r.failed} / ${r.failed + r.passed}`, by, time: seconds(t0) };
    }
    cleanup();
    rows.push(row);
    console.log(`${row.name}: ${row.status} (${row.time})`);
  }
  console.log(`\n${table(rows)}\n`);
  const bad = rows.filter((r) => r.status !== 'caught');
  console.log(`${rows.length - bad.length} of ${rows.length} caught; total ${seconds(started)}; logs in ${path.relative(ROOT, LOG_DIR)}/`);
  process.exit(bad.length ? 1 : 0);
}

main().catch((e) => {
  console.error(e);
  process.exit(2);
});
