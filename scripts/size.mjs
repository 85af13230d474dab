// Size check (docs/package.md#size-budget): the gzip size of every chunk of the self-contained build
// (dist/glass-plane-scene.standalone.js, minified, and what it imports statically or lazily)
// against the budget of each chunk in src/frame/chunks.ts (bytes, min+gzip); and the core as a
// bundler's app gets it: `import 'glass-plane-scene'` (dist/glass-plane-scene.js, gl-matrix from
// node_modules) bundled and minified by rolldown (Vite's bundler), its eager files against the
// same budget. `--tree` shows
// where the bytes go, from the ES build (dist/glass-plane-scene.js), whose chunks keep a
// "// path" line before each module: each module gzipped alone, so a share, not exact bytes
// (and before whitespace removal, gl-matrix excluded: a map of the weight, not the budget).
//
//   npm run size            the table, and a non-zero exit over budget
//   npm run size -- --tree  and every module of every chunk, largest first
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import os from 'node:os';
import { fileURLToPath } from 'node:url';
import { build } from 'rolldown';
import { graph, nameOf } from './chunk-graph.mjs';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const DIST = path.join(ROOT, 'dist');
const ENTRY = 'glass-plane-scene.standalone.js';
const gz = (s) => zlib.gzipSync(s, { level: 9 }).length;
const kB = (n) => (n / 1000).toFixed(1);

function modules(text) {
  const parts = text.split(/^(?=\/\/ (?:src|node_modules|shaders|\.\.)\/)/m);
  return parts.map((p) => {
    const m = /^\/\/ (\S+)/.exec(p);
    return { name: m ? m[1] : '(chunk glue)', bytes: gz(p) };
  }).sort((a, b) => b.bytes - a.bytes);
}

/** The eager files of an app that only does `import 'glass-plane-scene'`, built minified by rolldown. */
async function bundlerCore() {
  const out = fs.mkdtempSync(path.join(os.tmpdir(), 'glass-plane-scene-size-'));
  try {
    const entry = path.join(out, 'app.js');
    fs.writeFileSync(entry, `import ${JSON.stringify(path.join(DIST, 'glass-plane-scene.js'))};\n`);
    await build({ input: entry, cwd: ROOT, logLevel: 'silent', output: { dir: path.join(out, 'dist'), format: 'es', minify: true } });
    return graph('app.js', path.join(out, 'dist')).filter((c) => !c.lazy);
  } finally {
    fs.rmSync(out, { recursive: true, force: true });
  }
}

/** src/frame/chunks.ts's table (TypeScript, plain data), built in memory by rolldown. */
async function chunkTable() {
  const out = await build({ input: path.join(ROOT, 'src/frame/chunks.ts'), cwd: ROOT, logLevel: 'silent', write: false, output: { format: 'es' } });
  const { CHUNKS } = await import(`data:text/javascript,${encodeURIComponent(out.output[0].code)}`);
  return CHUNKS;
}

const table = await chunkTable();
const budget = Object.fromEntries(Object.entries(table).map(([name, c]) => [name, c.budget]));
if (!fs.existsSync(path.join(DIST, ENTRY))) {
  console.error('size: dist is missing; run `npm run build` first');
  process.exit(1);
}
const chunks = graph(ENTRY);
const core = chunks.filter((c) => !c.lazy);
const rows = [{ name: 'core', files: core }];
for (const c of chunks.filter((c) => c.lazy)) rows.push({ name: nameOf(c.file), files: [c] });
rows.splice(1, 0, { name: 'core', label: 'core (a bundler\'s import)', files: await bundlerCore() });
let over = 0;
const lines = ['| chunk | loaded | min+gzip | budget |', '|---|---|---|---|'];
for (const r of rows) {
  const bytes = r.files.reduce((s, c) => s + gz(c.text), 0);
  const b = budget[r.name];
  const ok = b === undefined || bytes <= b;
  if (!ok) over++;
  lines.push(`| ${r.label ?? r.name} | ${table[r.name]?.when ?? '—'} | ${kB(bytes)} kB | ${b === undefined ? '—' : `${kB(b)} kB${ok ? '' : ` **over** by ${bytes - b} B`}`} |`);
}
console.log(lines.join('\n'));
if (process.argv.includes('--tree')) {
  const es = graph('glass-plane-scene.js');
  const groups = [{ name: 'core', files: es.filter((c) => !c.lazy) }, ...es.filter((c) => c.lazy).map((c) => ({ name: nameOf(c.file), files: [c] }))];
  for (const g of groups) {
    const all = g.files.flatMap((c) => modules(c.text)).sort((a, b) => b.bytes - a.bytes);
    console.log(`\n${g.name} (ES build, modules gzipped alone):`);
    for (const m of all) console.log(`  ${kB(m.bytes).padStart(6)} kB  ${m.name}`);
  }
}
const missing = rows.filter((r) => budget[r.name] === undefined).map((r) => r.name);
if (missing.length) console.log(`size: no budget for ${missing.join(', ')} (src/frame/chunks.ts)`);
// A chunk in the table that the build no longer makes: its budget (and its group) are stale.
const unbuilt = Object.keys(table).filter((name) => !rows.some((r) => r.name === name));
if (unbuilt.length) console.log(`size: src/frame/chunks.ts names chunks the build does not make: ${unbuilt.join(', ')}`);
console.log(`size: ${rows.length - over} within budget, ${over} over`);
process.exit(over || missing.length || unbuilt.length ? 1 : 0);
