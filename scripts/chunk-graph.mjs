// The chunks a built entry reaches (scripts/size.mjs, bench/gltf.spec.ts): its static imports
// (loaded with it), its dynamic ones (lazy) and its workers, followed through the files of dist/.
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const DIST = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', 'dist');

/** The chunks the entry reaches: static imports (loaded with it) and dynamic ones (lazy), and workers. */
export function graph(entry, dir = DIST) {
  const chunks = new Map();
  const visit = (file, lazy, from) => {
    if (chunks.has(file)) return;
    // The bundler's build leaves workers and assets where our dist has them: only its eager files count.
    if (lazy && dir !== DIST && !fs.existsSync(path.join(dir, file))) return;
    const text = fs.readFileSync(path.join(dir, file), 'utf8');
    chunks.set(file, { file, text, lazy, from });
    // Quotes of either kind (the minifier writes template literals).
    const q = '["\'`]';
    const rel = (m) => path.posix.join(path.posix.dirname(file), m[1]);
    for (const m of text.matchAll(new RegExp(`(?:from|^import)\\s*${q}\\.\\/([^"'\`]+\\.js)${q}`, 'gm'))) visit(rel(m), lazy, file);
    for (const m of text.matchAll(new RegExp(`import\\(\\s*${q}\\.\\/([^"'\`]+\\.js)${q}\\s*\\)`, 'g'))) visit(rel(m), true, file);
    for (const m of text.matchAll(new RegExp(`new URL\\(\\s*(?:/\\*[^*]*\\*/\\s*)?(?:new URL\\(\\s*)?${q}\\.?\\/?(assets\\/[^"'\`]+\\.js)${q}`, 'g'))) visit(m[1], true, file);
  };
  visit(entry, false, null);
  return [...chunks.values()];
}

/** A chunk's name without its hash: "model-loader", "assets/worker". */
export const nameOf = (file) => file.replace(/-[A-Za-z0-9_-]{8}\.js$/, '').replace(/\.js$/, '');

