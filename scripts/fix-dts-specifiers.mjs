// After `tsc -p tsconfig.build.json`: relative specifiers in dist/types/**/*.d.ts get their
// `.js` (or `/index.js`) so node16/nodenext resolve them as bundlers do. tsc writes them as the
// source has them (extensionless, moduleResolution bundler); rewriting the output keeps the
// sources as they are and one .d.ts per module (go-to-definition lands in the right file).
// A specifier that names no emitted declaration fails the build.
import { existsSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';

const root = resolve(process.argv[2] ?? 'dist/types');
const SPECIFIER = /(\bfrom\s*|\bimport\s*\(\s*|\bimport\s+)(['"])(\.{1,2}\/[^'"]*)\2/g;

function* files(dir) {
  for (const e of readdirSync(dir, { withFileTypes: true })) {
    const p = join(dir, e.name);
    if (e.isDirectory()) yield* files(p);
    else if (e.name.endsWith('.d.ts')) yield p;
  }
}

let changed = 0;
const missing = [];
for (const file of files(root)) {
  const text = readFileSync(file, 'utf8');
  const out = text.replace(SPECIFIER, (whole, lead, q, spec) => {
    if (/\.(js|mjs|cjs|json)$/.test(spec)) return whole;
    const base = resolve(dirname(file), spec);
    if (existsSync(`${base}.d.ts`)) return `${lead}${q}${spec}.js${q}`;
    if (existsSync(join(base, 'index.d.ts'))) return `${lead}${q}${spec.replace(/\/$/, '')}/index.js${q}`;
    missing.push(`${relative(process.cwd(), file)}: ${spec}`);
    return whole;
  });
  if (out !== text) {
    writeFileSync(file, out);
    changed++;
  }
}
if (missing.length) {
  console.error(`glass-plane-scene: declarations import what was not emitted:\n  ${missing.join('\n  ')}`);
  process.exit(1);
}
console.log(`fix-dts-specifiers: ${changed} files rewritten under ${relative(process.cwd(), root)}`);
