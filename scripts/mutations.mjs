// Mutation check for the tests (issue 14 §2): each mutation below breaks one pass on purpose in a
// temporary copy of the repository and runs the tests meant to catch it. A mutation is "caught"
// when at least one of those tests fails, "missed" when they all pass, "stale" when its search
// text is no longer in the file exactly once (the code moved: fix the table, never skip it), and
// "error" when the run failed without a failing test (a server that did not start, a crash).
// An unmutated baseline runs first; if it fails, the table would mean nothing, so it stops there.
//
//   npm run test:mutations              every mutation
//   npm run test:mutations -- clip      only those whose name contains "clip" (the baseline still runs)
//   KEEP_MUTANTS=1 …                    leave the temporary copies in place
//
// Logs: test-results/mutations/<name>.log. Not part of `npm test`: it runs the relevant specs
// once per mutation, each time with a fresh Vite (about 2–3 minutes on 2 cores).
import { spawn, execFileSync } from 'node:child_process';
import fs from 'node:fs';
import net from 'node:net';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const LOG_DIR = path.join(ROOT, 'test-results', 'mutations');

const PASSES = 'tests/e2e/passes.spec.ts';
const LEAKS = 'tests/e2e/gl-leaks.spec.ts';
const CONTROLS = 'tests/e2e/controls.spec.ts';

/** { name, edits: [{ file, find, replace }], tests: spec (Playwright) or test (vitest) files }. */
const MUTATIONS = [
  {
    name: '1 reflection drawn from the unmirrored camera',
    edits: [{
      file: 'src/render/frame-setup.ts',
      find: 'this.compose(o.mirrored, o.model, mirroredEye, this.mirroredViewProjection);',
      replace: 'this.compose(o.mirrored, o.model, eye, this.viewProjection);',
    }],
    tests: [PASSES],
  },
  {
    name: '2 clip plane sign flipped',
    edits: [{
      file: 'src/render/frame-setup.ts',
      find: 'this.clipPlane[0] = this.side * p[0];\n    this.clipPlane[1] = this.side * p[1];\n    this.clipPlane[2] = this.side * p[2];\n    this.clipPlane[3] = this.side * signedDistance(p, mirroredEye);',
      replace: 'this.clipPlane[0] = -this.side * p[0];\n    this.clipPlane[1] = -this.side * p[1];\n    this.clipPlane[2] = -this.side * p[2];\n    this.clipPlane[3] = -this.side * signedDistance(p, mirroredEye);',
    }],
    tests: [PASSES],
  },
  {
    name: '3 abs() removed from cosθ',
    edits: [{
      file: 'shaders/glass.frag',
      find: 'float c = clamp(abs(dot(normalize(vNormal), v)), 0.0, 1.0);',
      replace: 'float c = clamp(dot(normalize(vNormal), v), 0.0, 1.0);',
    }],
    tests: [PASSES],
  },
  {
    name: '4 dispose() skips the texture',
    edits: [{ file: 'src/render/gl/shared-resources.ts', find: '    this.procedural?.dispose();\n', replace: '' }],
    tests: [LEAKS],
  },
  {
    name: '5a discard fallback removed',
    edits: [{ file: 'shaders/standard.frag', find: '  if (vClipDistance < 0.0) discard;\n', replace: '' }],
    tests: [PASSES],
  },
  {
    name: '5b discard fallback inverted',
    edits: [{ file: 'shaders/standard.frag', find: 'if (vClipDistance < 0.0) discard;', replace: 'if (vClipDistance > 0.0) discard;' }],
    tests: [PASSES],
  },
  {
    name: '6a classic alpha without (1 − T)',
    edits: [{
      file: 'shaders/glass.frag',
      find: 'float a = (1.0 - uTransparency) * (0.2 + 0.8 * f);',
      replace: 'float a = 0.2 + 0.8 * f;',
    }],
    tests: [PASSES],
  },
  {
    name: '6b classic colour not premultiplied',
    edits: [{ file: 'shaders/glass.frag', find: 'outColor = vec4(mix(d, r, f) * a, a);', replace: 'outColor = vec4(mix(d, r, f), a);' }],
    tests: [PASSES],
  },
  {
    name: '7a far-side clip removed (clip distance and discard)',
    edits: [
      { file: 'shaders/standard.vert', find: 'gl_ClipDistance[0] = clipDistance;', replace: 'gl_ClipDistance[0] = 1.0;' },
      { file: 'shaders/standard.frag', find: '  if (vClipDistance < 0.0) discard;\n', replace: '' },
    ],
    tests: [PASSES],
  },
  {
    name: '7b far-side clip removed (uClipPlane zeroed)',
    edits: [{
      file: 'src/render/passes/draw-objects.ts',
      find: "gl.uniform4fv(program.location('uClipPlane'), setup.clipPlane);",
      replace: "gl.uniform4fv(program.location('uClipPlane'), [0, 0, 0, 0]);",
    }],
    tests: [PASSES],
  },
  {
    name: '8 F forced to 0',
    edits: [{ file: 'shaders/glass.frag', find: 'float f = fresnel(c);', replace: 'float f = 0.0;' }],
    tests: [PASSES],
  },
  {
    name: '9 inertia stepped by Euler (frame-rate dependent)',
    edits: [{ file: 'src/element/controls/inertia.ts', find: '    const f = INERTIA_TAU * (1 - k);', replace: '    const f = t;' }],
    tests: [CONTROLS],
  },
  {
    name: '10 touch-action none without controls',
    edits: [{ file: 'src/element/element-style.ts', find: 'canvas { display: block; width: 100%; height: 100%; }', replace: 'canvas { display: block; width: 100%; height: 100%; touch-action: none; }' }],
    tests: [CONTROLS],
  },
  {
    name: '11 pointer-lock entry movement turned by',
    edits: [{ file: 'src/element/flyby-input.ts', find: '    this.skipNext = true;', replace: '' }],
    tests: [CONTROLS],
  },
  {
    name: '12 a dense mesh\'s clustered reflection copies never released',
    edits: [{ file: 'src/render/object-meshes.ts', find: '    for (const entry of slot.reflection.values()) if (entry) this.shared.releaseMesh(entry.key);\n', replace: '' }],
    tests: [LEAKS],
  },
  {
    name: '13 software rasterizer without the top-left rule',
    edits: [{
      file: 'src/software/raster.ts',
      find: '    const bias0 = (ay0 === 0 && ax0 > 0) || ay0 < 0 ? 0 : -1;\n    const bias1 = (ay1 === 0 && ax1 > 0) || ay1 < 0 ? 0 : -1;\n    const bias2 = (ay2 === 0 && ax2 > 0) || ay2 < 0 ? 0 : -1;',
      replace: '    const bias0 = 0;\n    const bias1 = 0;\n    const bias2 = 0;',
    }],
    tests: ['tests/unit/software-raster.test.ts'],
  },
  {
    name: '14 the software renderer never given the decoded images',
    edits: [{ file: 'src/element/glass-plane-scene.ts', find: '      this.images.attach(host);\n', replace: '' }],
    tests: ['tests/e2e/model-reference.spec.ts'],
  },
];

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
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), `gps-mutant-${label.replace(/\W+/g, '-').slice(0, 30)}-`));
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

/** Runs `tests` in `dir`: Playwright for *.spec.ts (own Vite on a free port), vitest for *.test.ts. */
async function runTests(dir, tests, logName) {
  fs.mkdirSync(LOG_DIR, { recursive: true });
  const log = fs.createWriteStream(path.join(LOG_DIR, `${logName.replace(/\W+/g, '-')}.log`));
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
      for (const m of out.matchAll(/^\s*(?:FAIL|×)\s+(.+)$/gm)) result.failures.push(m[1].trim());
    }
    // A non-zero exit with no failing test is not a catch: the run itself broke.
    if (r.code !== 0 && !failed) result.errors.push(`${runner} exited ${r.signal ?? r.code} with no failing test`);
  }
  return result;
}

function table(rows) {
  const head = ['mutation', 'result', 'tests failed / run', 'caught by', 'time'];
  const body = rows.map((r) => [r.name, r.status, r.counts, r.by, r.time]);
  const widths = head.map((h, i) => Math.max(h.length, ...body.map((b) => b[i].length)));
  const line = (cells) => `| ${cells.map((c, i) => c.padEnd(widths[i])).join(' | ')} |`;
  return [line(head), `|${widths.map((w) => '-'.repeat(w + 2)).join('|')}|`, ...body.map(line)].join('\n');
}

const seconds = (t0) => `${((Date.now() - t0) / 1000).toFixed(0)} s`;

async function main() {
  const filter = process.argv[2];
  const chosen = MUTATIONS.filter((m) => !filter || m.name.includes(filter));
  if (!chosen.length) {
    console.error(`mutations: no mutation name contains "${filter}"`);
    process.exit(2);
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
  const base = await runTests(baseDir, allTests, 'baseline');
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
      row = { name: m.name, status: 'STALE', counts: '-', by: stale, time: seconds(t0) };
    } else {
      const r = await runTests(dir, m.tests, m.name);
      const status = r.errors.length ? 'ERROR' : r.failed > 0 ? 'caught' : 'MISSED';
      const by = r.errors.length ? r.errors.join('; ') : r.failures.join('; ') || '-';
      row = { name: m.name, status, counts: `${r.failed} / ${r.failed + r.passed}`, by, time: seconds(t0) };
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
