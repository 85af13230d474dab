// The README's figures, from the files that hold them, never typed by hand:
// between <!-- figures:NAME --> and <!-- /figures:NAME --> the README holds what this script
// writes. `size` comes from scripts/size.mjs on the current dist/, `bench` from the last
// `npm run bench` (bench/results.json, bench/software.md).
//
//   npm run figures           rewrite the blocks
//   node scripts/readme-figures.mjs --check    exit 1 when a block is stale (npm test runs it)
import fs from 'node:fs';
import path from 'node:path';
import { execFileSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const README = path.join(ROOT, 'README.md');

function sizeBlock() {
  let out;
  try {
    out = execFileSync(process.execPath, [path.join(ROOT, 'scripts/size.mjs')], { encoding: 'utf8' });
  } catch (e) {
    out = e.stdout ?? ''; // over budget still prints the table
  }
  return out.split('\n').filter((l) => l.startsWith('|')).join('\n');
}

function benchBlock() {
  const r = JSON.parse(fs.readFileSync(path.join(ROOT, 'bench/results.json'), 'utf8'));
  const row = (key) => r.rows.find((x) => x.key === key);
  const mean = (x, f) => x.perView.reduce((s, v) => s + f(v), 0) / x.perView.length;
  const ours = row('tessellation auto'), three = row('three.js');
  const soft = fs.readFileSync(path.join(ROOT, 'bench/software.md'), 'utf8').split('\n')
    .find((l) => l.startsWith('| software, SoftwareHost') && l.includes('(samples 4, the default)'));
  const cells = soft ? soft.split('|').map((c) => c.trim()) : [];
  const lines = [
    `- WebGL, the element's defaults, ${r.scene.width}×${r.scene.height}, mean of ${ours.perView.length} views: ` +
      `**${mean(ours, (v) => v.ms).toFixed(2)} ms/frame**, **${mean(ours, (v) => v.error.psnr.all).toFixed(1)} dB** against the float64 reference` +
      (three ? `; the three.js + Reflector peer ${mean(three, (v) => v.ms).toFixed(2)} ms/frame at ${mean(three, (v) => v.error.psnr.all).toFixed(1)} dB.` : '.'),
  ];
  if (cells.length > 6) lines.push(`- Software renderer, default scene, 640×360, samples 4 (2×2 multisampled, the default), in its worker: **${cells[3].split(' ')[0]} ms/frame**, **${cells[6].split(' ')[0]} dB**.`);
  lines.push(`- ${r.info?.renderer ? `GPU: ${r.info.renderer}.` : ''} Method and every table: [BENCH.md](BENCH.md).`);
  return lines.join('\n');
}

const BLOCKS = { size: sizeBlock, bench: benchBlock };

let text = fs.readFileSync(README, 'utf8');
const stale = [];
for (const [name, make] of Object.entries(BLOCKS)) {
  const re = new RegExp(`(<!-- figures:${name} -->)[\\s\\S]*?(<!-- /figures:${name} -->)`);
  if (!re.test(text)) { stale.push(`${name} (no block)`); continue; }
  const body = make();
  const next = text.replace(re, (_, a, b) => `${a}\n${body}\n${b}`);
  if (next !== text) stale.push(name);
  text = next;
}
if (process.argv.includes('--check')) {
  if (stale.length) {
    console.error(`README figures out of date: ${stale.join(', ')}; run \`npm run figures\``);
    process.exit(1);
  }
  console.log('README figures: current');
} else {
  fs.writeFileSync(README, text);
  console.log(stale.length ? `README figures rewritten: ${stale.join(', ')}` : 'README figures: current');
}
