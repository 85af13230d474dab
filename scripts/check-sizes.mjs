// Size limits of src/, so each file and function can be read whole: no function over 80 lines, no file over 400 (the element's host 300). A long function is
// split where a name explains the piece; a long file by concern. Functions are measured on the
// syntax tree (Vite's parser), from the line their declaration starts on to the line it ends on.
//
//   node scripts/check-sizes.mjs          prints every function and file over its limit; exit 1 if any
//   node scripts/check-sizes.mjs --top 10 also prints the ten longest functions
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseSync } from 'vite';
import { sourceFiles } from './check-layers.mjs';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
export const MAX_FUNCTION_LINES = 80;
export const MAX_FILE_LINES = 400;
/** Files held to a tighter limit of lines than MAX_FILE_LINES, relative to the root. */
export const FILE_LIMITS = new Map([
  // The thin host over the element's controllers (ARCHITECTURE.md): what grows it belongs in one.
  ['src/element/glass-plane-scene.ts', 300],
]);

const FUNCTIONS = new Set(['FunctionDeclaration', 'FunctionExpression', 'ArrowFunctionExpression']);

/** Every function in `code` as { name, line, lines }: its name, first line and length in lines. */
export function functionsOf(code, filename = 'file.ts') {
  const { program, errors } = parseSync(filename, code);
  if (errors.length) throw new Error(`${filename}: ${errors[0].message}`);
  const lineStarts = [0];
  for (let i = 0; i < code.length; i++) if (code.charCodeAt(i) === 10) lineStarts.push(i + 1);
  const lineOf = (offset) => {
    let lo = 0, hi = lineStarts.length - 1;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (lineStarts[mid] <= offset) lo = mid; else hi = mid - 1;
    }
    return lo + 1;
  };
  const found = [];
  const visit = (node, parent) => {
    if (FUNCTIONS.has(node.type)) {
      // A method or a property's function starts at its name; an arrow or expression assigned to
      // a variable is named by it.
      const owner = parent && (parent.type === 'MethodDefinition' || parent.type === 'Property' || parent.type === 'PropertyDefinition') ? parent : node;
      const key = owner.key ?? (parent?.type === 'VariableDeclarator' ? parent.id : null) ?? node.id;
      const name = key?.name ?? key?.value ?? '(anonymous)';
      const line = lineOf(owner.start);
      found.push({ name: String(name), line, lines: lineOf(node.end - 1) - line + 1 });
    }
    for (const k in node) {
      if (k === 'parent') continue;
      const v = node[k];
      if (Array.isArray(v)) { for (const c of v) if (c && typeof c.type === 'string') visit(c, node); }
      else if (v && typeof v.type === 'string') visit(v, node);
    }
  };
  visit(program, null);
  return found;
}

/** Every function and file under `root`/src over its limit, as a line each; `all` collects every function measured. */
export function check(root = ROOT, all = []) {
  const problems = [];
  for (const file of sourceFiles(path.join(root, 'src'))) {
    const rel = path.relative(root, file).split(path.sep).join('/');
    const code = fs.readFileSync(file, 'utf8');
    const lines = code.split('\n').length - (code.endsWith('\n') ? 1 : 0), limit = FILE_LIMITS.get(rel) ?? MAX_FILE_LINES;
    if (lines > limit) problems.push(`${rel}: ${lines} lines (at most ${limit})`);
    for (const f of functionsOf(code, rel)) {
      all.push({ ...f, file: rel });
      if (f.lines > MAX_FUNCTION_LINES) problems.push(`${rel}:${f.line}: ${f.name} is ${f.lines} lines (at most ${MAX_FUNCTION_LINES})`);
    }
  }
  return problems;
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const all = [];
  const problems = check(ROOT, all);
  const top = process.argv.indexOf('--top');
  if (top > 0) {
    for (const f of all.sort((a, b) => b.lines - a.lines).slice(0, Number(process.argv[top + 1]) || 10)) {
      console.log(`${String(f.lines).padStart(4)}  ${f.file}:${f.line} ${f.name}`);
    }
  }
  for (const p of problems) console.error(p);
  console.log(`sizes: ${problems.length ? `${problems.length} over the limits` : `no function over ${MAX_FUNCTION_LINES} lines, no file over ${MAX_FILE_LINES}`}`);
  process.exit(problems.length ? 1 : 0);
}
