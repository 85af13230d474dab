// The layers of src/ (ARCHITECTURE.md, "Layers"), checked over every import: a module may import
// its own folder and the layers below it, never a layer above, never a sibling of its own layer.
// The table is read from ARCHITECTURE.md's ```layers block, so the document and the check are one:
// one line a layer, top first; the folders on a line are siblings (they must not import each other).
//
//   node scripts/check-layers.mjs          prints every import that breaks the layering; exit 1 if any
//   node scripts/check-layers.mjs --list   also prints the layer table it read
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const SRC = path.join(ROOT, 'src');

/** Layers, top first: [['index'], ['element'], ['render', 'software', 'reference'], …]. */
export function readLayers(markdown) {
  const block = markdown.match(/```layers\n([\s\S]*?)```/);
  if (!block) throw new Error('ARCHITECTURE.md has no ```layers block');
  return block[1]
    .split('\n')
    .map((line) => line.replace(/#.*/, '').trim())
    .filter(Boolean)
    .map((line) => line.split(/\s+/));
}

/** Every .ts file under `dir` (not .d.ts); check-sizes.mjs walks src/ with it too. */
export function sourceFiles(dir) {
  const out = [];
  for (const entry of fs.readdirSync(dir, { withFileTypes: true })) {
    const p = path.join(dir, entry.name);
    if (entry.isDirectory()) out.push(...sourceFiles(p));
    else if (/\.ts$/.test(entry.name) && !entry.name.endsWith('.d.ts')) out.push(p);
  }
  return out;
}

/** Relative specifiers of static imports, re-exports and dynamic import() calls, with their lines. */
export function importsOf(text) {
  const found = [];
  const patterns = [
    /^\s*(?:import|export)\b[^'"]*?\bfrom\s*['"]([^'"]+)['"]/gm,
    /^\s*import\s*['"]([^'"]+)['"]/gm,
    /\bimport\(\s*['"]([^'"]+)['"]\s*\)/g,
  ];
  const seen = new Set();
  for (const re of patterns) {
    for (const m of text.matchAll(re)) {
      if (!m[1].startsWith('.')) continue;
      const line = text.slice(0, m.index + m[0].indexOf(m[1])).split('\n').length;
      const key = `${line}:${m[1]}`;
      if (seen.has(key)) continue;
      seen.add(key);
      found.push({ spec: m[1], line });
    }
  }
  return found;
}

/** The folder of `src` a file belongs to ('index' for src/index.ts), or null outside it. */
function unitOf(file, src) {
  const rel = path.relative(src, file);
  if (rel.startsWith('..')) return null;
  const parts = rel.split(path.sep);
  return parts.length === 1 ? parts[0].replace(/\.ts$/, '') : parts[0];
}

/** Every import under `src` (default: this checkout's src/) that breaks `layers`, as a line each. */
export function check(layers, src = SRC) {
  const root = path.dirname(src);
  const level = new Map();
  layers.forEach((names, i) => names.forEach((n) => level.set(n, layers.length - i)));
  const problems = [];
  for (const file of sourceFiles(src)) {
    const from = unitOf(file, src);
    const text = fs.readFileSync(file, 'utf8');
    const rel = path.relative(root, file);
    if (!level.has(from)) {
      problems.push(`${rel}: src/${from} is in no layer of ARCHITECTURE.md`);
      continue;
    }
    for (const { spec, line } of importsOf(text)) {
      const target = path.resolve(path.dirname(file), spec.replace(/\?.*$/, ''));
      const to = unitOf(target, src);
      if (to === null || to === from) continue; // shaders/ and other non-src files; its own folder
      if (!level.has(to)) {
        problems.push(`${rel}:${line}: imports ${spec}, and src/${to} is in no layer`);
      } else if (level.get(to) > level.get(from)) {
        problems.push(`${rel}:${line}: ${from} imports ${spec}, a higher layer (${to})`);
      } else if (level.get(to) === level.get(from)) {
        problems.push(`${rel}:${line}: ${from} imports ${spec}, a sibling on its own layer (${to})`);
      }
    }
  }
  return problems;
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const layers = readLayers(fs.readFileSync(path.join(ROOT, 'ARCHITECTURE.md'), 'utf8'));
  if (process.argv.includes('--list')) layers.forEach((l, i) => console.log(`${layers.length - i}  ${l.join(' ')}`));
  const problems = check(layers);
  for (const p of problems) console.error(p);
  console.log(`layers: ${problems.length ? `${problems.length} import(s) break the layering` : 'every import goes down'}`);
  process.exit(problems.length ? 1 : 0);
}
