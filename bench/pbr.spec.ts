// `npm run bench`, the glTF materials' rows (docs/pbr.md): the grid of twelve spheres (metallic 0, ½, 1 × roughness 0.05 … 1,
// tests/unit/helpers/pbr-scenes.ts studioGrid) over a glass floor, under its two lights and in the studio, tone mapped. For each
// renderer (WebGL in the page, the CPU renderer in Node) and a few settings of its accuracy: ms per frame and PSNR by region
// against the float64 reference (4×4 strata a pixel, 1,024 directions of the studio each); the Pareto front; the reference's
// own noise (against itself at 2,048 directions); and the studio's maps' making (once a page), in Node. Writes bench/pbr.md;
// BENCH_SMOKE=1 runs it tiny so the pipeline cannot rot. Not yet here: three.js's peer (MeshStandardMaterial, PMREM) and the
// ratio at equal accuracy (the issue's note says what is left).
import { writeFileSync } from 'node:fs';
import { createHash } from 'node:crypto';
import { test, expect } from '../tests/e2e/fixtures';
import { compareImages, renderScene, type ReferenceImage } from '../src/reference';
import { defaultFrameState } from '../tests/unit/helpers/frame-state';
import { SoftwareRenderer } from '../src/software';
import { prepareEnvironment } from '../src/frame/environment-light';
import type { FrameState } from '../src/frame/types';
import { STUDIO, studioGrid } from '../tests/unit/helpers/pbr-scenes';
import { cachedImage, sourcesVersion } from './reference-cache';
import { paretoFront } from './pareto';
import { summary } from './stats';

const SMOKE = process.env.BENCH_SMOKE === '1';
const SIZE = SMOKE ? { width: 80, height: 45 } : { width: 320, height: 180 };
const REF_SPP = SMOKE ? 1 : 4;
const DIRECTIONS = SMOKE ? 16 : 1024;
const FRAMES = SMOKE ? 1 : 3;
const WARMUP = SMOKE ? 0 : 1;
const RUNS = SMOKE ? 1 : 3;
const REGIONS = ['all', 'objects', 'glass', 'edges', 'dark'] as const;

type Page = import('@playwright/test').Page;
interface Bench {
  bench: {
    pbrTime(s: FrameState, frames: number, warmup: number): Promise<number>;
    pbrPixels(s: FrameState): Promise<{ width: number; height: number; data: string }>;
    info(): { renderer: string };
  };
}

/** The view of tests/e2e/environment.spec.ts. */
function state(extra: Partial<FrameState> = {}): FrameState {
  return defaultFrameState({ ...SIZE, cameraPosition: [0, 1.5, 3.3], yaw: -90, pitch: -8, time: 0, spin: 0, toneMapping: 'neutral', ...extra });
}

/** The reference, cached in bench/.cache by its state, sampling and the reference's sources. */
function reference(directions: number): { ref: ReferenceImage; ms: number | null } {
  const s = state();
  const sources = ['../src/reference/', '../src/scene/', '../src/math/'].map((d) => new URL(d, import.meta.url));
  const key = createHash('sha256').update(JSON.stringify({ s, spp: REF_SPP, directions, v: sourcesVersion(sources), scene: 'studio-grid' })).digest('hex').slice(0, 16);
  return cachedImage(`pbr-${key}`, () => renderScene(studioGrid(), s, null, { samplesPerAxis: REF_SPP, environmentSamples: directions }));
}

interface Row { label: string; ms: number; iqr: number; psnr: Record<(typeof REGIONS)[number], number> }

async function webglRows(page: Page, ref: ReferenceImage): Promise<Row[]> {
  const rows: Row[] = [];
  for (const samples of [0, 4] as const) {
    const s = state({ samples });
    const ms: number[] = [];
    for (let r = 0; r < RUNS; r++) ms.push(await page.evaluate(([s, f, w]) => (window as unknown as Bench).bench.pbrTime(s, f, w), [s, FRAMES, WARMUP] as const));
    const px = await page.evaluate((s) => (window as unknown as Bench).bench.pbrPixels(s), s);
    const cmp = compareImages(ref, new Uint8ClampedArray(Buffer.from(px.data, 'base64')));
    rows.push({ label: `samples ${samples}`, ms: summary(ms).median, iqr: summary(ms).iqr, psnr: cmp.psnr });
  }
  return rows;
}

function softwareRows(ref: ReferenceImage): Row[] {
  prepareEnvironment(STUDIO);
  const rows: Row[] = [];
  const scene = studioGrid(), s = state({ samples: 0 });
  for (const spp of [1, 2, 4]) {
    const r = new SoftwareRenderer({ samplesPerAxis: spp });
    const image = r.render(scene, s).slice();
    const ms: number[] = [];
    for (let k = 0; k < RUNS; k++) {
      // A fresh renderer each run: the frame-to-frame cache would make repeated frames of a still scene nearly free.
      const fresh = new SoftwareRenderer({ samplesPerAxis: spp });
      const t0 = performance.now();
      for (let f = 0; f < FRAMES; f++) fresh.render(scene, { ...s, time: f * 1e-3 });
      ms.push((performance.now() - t0) / FRAMES);
    }
    rows.push({ label: `${spp}×${spp} samples a pixel`, ms: summary(ms).median, iqr: summary(ms).iqr, psnr: compareImages(ref, image).psnr });
  }
  return rows;
}

const f1 = (x: number) => (Number.isFinite(x) ? x.toFixed(1) : String(x));

/** The studio's maps and split-sum table made afresh in Node (the table of prepared environments emptied first). */
function preparationMs(): number {
  const table = (globalThis as Record<symbol, unknown>)[Symbol.for('glass-plane-scene.environments')] as Map<unknown, unknown> | undefined;
  table?.clear();
  const t0 = performance.now();
  prepareEnvironment(STUDIO);
  return performance.now() - t0;
}

test('glTF materials in the studio', async ({ page }) => {
  test.setTimeout(SMOKE ? 5 * 60_000 : 60 * 60_000);
  await page.goto('/bench/page.html');
  const info = await page.evaluate(() => (window as unknown as Bench).bench.info());
  const { ref, ms: refMs } = reference(DIRECTIONS);
  const gl = await webglRows(page, ref);
  const sw = softwareRows(ref);
  const prep = (SMOKE ? [0] : [0, 1, 2]).map(() => preparationMs());
  const doubled = reference(2 * DIRECTIONS).ref;
  const self = compareImages(doubled, ref.rgba).psnr;
  const out: string[] = [
    '# glTF materials in the studio ([PBR](../docs/pbr.md))', '',
    `Written by \`npm run bench\` (bench/pbr.spec.ts) on ${new Date().toISOString().slice(0, 10)}; WebGL: ${info.renderer}; software: Node ${process.version}.`,
    `Scene: tests/unit/helpers/pbr-scenes.ts studioGrid — twelve spheres (metallic 0, ½, 1 × roughness 0.05, 0.3, 0.6, 1) over a glass`,
    `floor, two lights and the studio, tone-mapping neutral, ${SIZE.width}×${SIZE.height}. PSNR (dB) by region against the float64 reference`,
    `(${REF_SPP}×${REF_SPP} strata a pixel, ${DIRECTIONS} directions of the studio each${refMs === null ? '' : `, computed in ${(refMs / 1000).toFixed(0)} s`}).`,
    `ms: median of ${RUNS} runs of ${FRAMES} frames; front: on the Pareto front of its renderer's rows (no row both faster and more accurate on the objects).`, '',
    '| renderer | setting | ms | all | objects | glass | edges | dark | front |', '|---|---|---|---|---|---|---|---|---|',
  ];
  for (const [name, rows] of [['WebGL', gl], ['software', sw]] as const) {
    const front = paretoFront(rows.map((r) => ({ ms: r.ms, noise: r.iqr, psnr: r.psnr.objects })));
    rows.forEach((r, i) => out.push(`| ${name} | ${r.label} | ${f1(r.ms)} | ${REGIONS.map((k) => f1(r.psnr[k])).join(' | ')} | ${front[i] ? '✓' : ''} |`));
    for (const r of rows) expect(Number.isFinite(r.psnr.objects), `${name} ${r.label}`).toBe(true);
  }
  out.push('',
    `The reference's own noise: its image at ${DIRECTIONS} directions against ${2 * DIRECTIONS}: all ${f1(self.all)}, objects ${f1(self.objects)} dB.`,
    '',
    `The studio's maps and split-sum table (docs/pbr.md#prefiltered-maps), made once a page: ${prep.map((m) => `${m.toFixed(0)} ms`).join(', ')} in Node`,
    '(in one go; a page makes them a row at a time, 8 ms tasks, tests/e2e/environment.spec.ts).', '',
    'Objects under 40 dB: each renderer shades a pixel once (WebGL) or 1, 4, 16 times (software) where the reference takes 16 strata of',
    '1,024 directions, and the split sum errs at grazing views of rough metals (docs/pbr.md#the-split-sum: 16–18 % at roughness ½–¾), which the',
    'spheres\' rims show. three.js\'s peer and the ratio at equal accuracy are not in this table yet.');
  if (!SMOKE) writeFileSync(new URL('./pbr.md', import.meta.url), out.join('\n') + '\n');
  else console.log(out.join('\n'));
});
