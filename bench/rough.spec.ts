// `npm run bench`, the rough glass rows (docs/rough-glass.md#roughness) on a glass floor with a cube resting on
// it and a sphere 1.5 above it (bench/rough-scene.ts), at roughness 0.1, 0.3 and 0.6 and ior 1.5
// and 10 (where F ≥ 0.67: the glass shows mostly the reflection). For each renderer (WebGL in the
// page, the software renderer in Node) and each setting of `roughness-quality`: ms per frame and
// PSNR on the glass against the float64 reference; the Pareto front; and the peers' method — the
// reflection blurred by one radius over the whole glass (a mip level, eight of them, the best
// kept) — beside the polished frame. The reference's own noise: its glass against itself with
// twice the microfacet normals, and how much that moves the rows. Writes bench/rough.md;
// BENCH_SMOKE=1 runs it tiny so the pipeline cannot rot.
import { writeFileSync } from 'node:fs';
import { test, expect } from '../tests/e2e/fixtures';
import { compareImages, type ReferenceImage } from '../src/reference';
import { SoftwareRenderer } from '../src/software';
import { ROUGHNESS_QUALITIES, type RoughnessQuality } from '../src/frame/rough-glass';
import type { FrameState } from '../src/frame/types';
import { roughFloorScene, SPHERE_HEIGHT } from './rough-scene';
import { roughReference as reference, roughState as state, ROUGH_MICROFACETS, ROUGH_REF_SPP, ROUGH_SIZE } from './rough-reference';
import { paretoFront } from './pareto';
import { summary } from './stats';

const SMOKE = process.env.BENCH_SMOKE === '1';
const CASES: [number, number][] = SMOKE ? [[0.3, 10]] : [[0.1, 1.5], [0.1, 10], [0.3, 1.5], [0.3, 10], [0.6, 1.5], [0.6, 10]];
/** The reference's sampling (rough-reference.ts); the check doubles the microfacet normals. */
const SIZE = ROUGH_SIZE, REF_SPP = ROUGH_REF_SPP, MICROFACETS = ROUGH_MICROFACETS;
const CHECK_CASE = '0.3/10';
const LEVELS = SMOKE ? [2] : [0, 1, 2, 3, 4, 5, 6, 7];
const FRAMES = SMOKE ? 1 : 3;
const WARMUP = SMOKE ? 0 : 1;
const RUNS = SMOKE ? 1 : 3;

type Page = import('@playwright/test').Page;
interface Bench {
  bench: {
    roughTime(s: FrameState, frames: number, warmup: number): Promise<number>;
    roughPixels(s: FrameState): Promise<{ width: number; height: number; data: string }>;
    info(): { renderer: string };
  };
}

interface Config { label: string; extra: Partial<FrameState>; rough: boolean; quality?: RoughnessQuality; level?: number }
const CONFIGS: Config[] = [
  { label: 'polished (roughness 0)', extra: { roughness: 0 }, rough: false },
  ...LEVELS.map((level) => ({ label: `one radius: mip level ${level}`, extra: { fixedBlurLevel: level }, rough: false, level })),
  ...ROUGHNESS_QUALITIES.map((quality) => ({ label: `roughness-quality ${quality}`, extra: { roughnessQuality: quality }, rough: true, quality })),
];

interface Row { config: Config; ms: number; noise: number; psnr: number; image: Uint8ClampedArray }

async function webglRows(page: Page, roughness: number, ior: number, ref: ReferenceImage): Promise<Row[]> {
  const rows: Row[] = [];
  for (const config of CONFIGS) {
    const s = state(roughness, ior, config.extra);
    const ms: number[] = [];
    for (let r = 0; r < RUNS; r++) ms.push(await page.evaluate(([s, f, w]) => (window as unknown as Bench).bench.roughTime(s, f, w), [s, FRAMES, WARMUP] as const));
    const px = await page.evaluate((s) => (window as unknown as Bench).bench.roughPixels(s), s);
    const image = new Uint8ClampedArray(Buffer.from(px.data, 'base64'));
    rows.push({ config, ms: summary(ms).median, noise: summary(ms).iqr, psnr: compareImages(ref, image).psnr.glass, image });
  }
  return rows;
}

function softwareRows(roughness: number, ior: number, ref: ReferenceImage): Row[] {
  const rows: Row[] = [];
  const scene = roughFloorScene();
  for (const config of CONFIGS) {
    const s = state(roughness, ior, config.extra), r = new SoftwareRenderer();
    const image = r.render(scene, s).slice();
    const ms: number[] = [];
    for (let k = 0; k < RUNS; k++) {
      const t0 = performance.now();
      for (let f = 0; f < FRAMES; f++) r.render(scene, s);
      ms.push((performance.now() - t0) / FRAMES);
    }
    rows.push({ config, ms: summary(ms).median, noise: summary(ms).iqr, psnr: compareImages(ref, image).psnr.glass, image });
  }
  return rows;
}

const f1 = (x: number) => (Number.isFinite(x) ? x.toFixed(1) : String(x));

/** The best of the one-radius rows (the peers' method at its best radius). */
const bestFixed = (rows: Row[]) => rows.filter((r) => r.config.level !== undefined).reduce((a, b) => (b.psnr > a.psnr ? b : a));
const medium = (rows: Row[]) => rows.find((r) => r.config.quality === 'medium')!;

test('rough glass', async ({ page }) => {
  test.setTimeout(SMOKE ? 5 * 60_000 : 75 * 60_000);
  await page.goto('/bench/page.html');
  const info = await page.evaluate(() => (window as unknown as Bench).bench.info());
  const out: string[] = [
    '# Rough glass ([the model](../docs/rough-glass.md#the-model))', '',
    `Written by \`npm run bench\` (bench/rough.spec.ts) on ${new Date().toISOString().slice(0, 10)}; WebGL: ${info.renderer}; software: Node ${process.version}.`,
    `Scene: bench/rough-scene.ts — a glass floor, a cube resting on it, a sphere ${SPHERE_HEIGHT} above it; ${SIZE.width}×${SIZE.height},`,
    'color-space srgb, samples 4, transparency 0.5. PSNR (dB) on the glass against the float64 reference',
    `(${REF_SPP}×${REF_SPP} strata per pixel, ${MICROFACETS} microfacet normals each). ms: median of ${RUNS} runs of ${FRAMES} frames.`,
    '"one radius": the reflection blurred by one radius over the whole glass (a mip level), the peers\' method; front: on the',
    'Pareto front of the rows beside it (no row both faster and more accurate).', '',
  ];
  const summaryRows: string[] = ['| roughness / ior | renderer | polished | best one radius (level) | low | medium | high | medium − best one radius |', '|---|---|---|---|---|---|---|---|'];
  let check = '';
  for (const [roughness, ior] of CASES) {
    const { ref, ms: refMs, cached } = reference(roughness, ior, MICROFACETS);
    const gl = await webglRows(page, roughness, ior, ref);
    const sw = softwareRows(roughness, ior, ref);
    out.push(`## roughness ${roughness}, ior ${ior}`, '');
    if (refMs !== null && !cached) out.push(`Reference computed in ${(refMs / 1000).toFixed(0)} s.`, '');
    const glFront = paretoFront(gl);
    const swFront = paretoFront(sw);
    out.push('| configuration | WebGL ms | WebGL dB | front | software ms | software dB | front |', '|---|---|---|---|---|---|---|');
    gl.forEach((g, i) => out.push(`| ${g.config.label} | ${f1(g.ms)} | ${f1(g.psnr)} | ${glFront[i] ? '✓' : ''} | ${f1(sw[i].ms)} | ${f1(sw[i].psnr)} | ${swFront[i] ? '✓' : ''} |`));
    out.push('');
    for (const [name, rows] of [['WebGL', gl], ['software', sw]] as const) {
      const b = bestFixed(rows), q = (k: RoughnessQuality) => f1(rows.find((r) => r.config.quality === k)!.psnr);
      summaryRows.push(`| ${roughness} / ${ior} | ${name} | ${f1(rows[0].psnr)} | ${f1(b.psnr)} (${b.config.level}) | ${q('low')} | ${q('medium')} | ${q('high')} | ${(medium(rows).psnr - b.psnr >= 0 ? '+' : '')}${f1(medium(rows).psnr - b.psnr)} |`);
      for (const r of rows) expect(Number.isFinite(r.psnr), `${name} ${r.config.label}`).toBe(true);
    }
    if (`${roughness}/${ior}` === CHECK_CASE || SMOKE) {
      // The reference against itself with twice the normals, and how far that moves the medium rows.
      const doubled = reference(roughness, ior, 2 * MICROFACETS).ref;
      const self = compareImages(doubled, ref.rgba).psnr.glass;
      const moves = [gl, sw].map((rows) => compareImages(doubled, medium(rows).image).psnr.glass - medium(rows).psnr);
      check = `The reference's noise (roughness ${roughness}, ior ${ior}): its glass with ${MICROFACETS} normals per stratum against ${2 * MICROFACETS}: ` +
        `${f1(self)} dB; scored against the doubled reference the medium rows move by ${moves.map((m) => `${m >= 0 ? '+' : ''}${m.toFixed(2)}`).join(' (WebGL) and ')} (software) dB.`;
    }
  }
  out.splice(9, 0, '## Summary', '', ...summaryRows, '', check, '');
  if (!SMOKE) writeFileSync(new URL('./rough.md', import.meta.url), out.join('\n') + '\n');
  else console.log(out.join('\n'));
});
