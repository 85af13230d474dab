// `npm run bench`, the projection rows (docs/interaction.md#orthographic-projection): the default knobs in every bench view, drawn
// perspective and orthographic, ms/frame and PSNR against the float64 reference of the same
// projection. Writes bench/projection.md; BENCH_SMOKE=1 runs the default view small, so the
// pipeline cannot rot. BENCH_ONLY=projection.spec.ts runs it alone.
import { writeFileSync } from 'node:fs';
import { test, expect } from '../tests/e2e/fixtures';
import { renderReference, compareImages } from '../src/reference';
import { defaultFrameState } from '../tests/unit/helpers/frame-state';
import type { Projection } from '../src/frame/types';
import { DEFAULTS } from './configs';
import { VIEWS, type BenchView } from './views';
import { summary, shuffled } from './stats';
import type { BenchApi, Scene } from './bench-page';

const SMOKE = process.env.BENCH_SMOKE === '1';
const SCENE: Scene = SMOKE ? { width: 160, height: 90, time: 1.25 } : { width: 640, height: 360, time: 1.25 };
const SPP_AXIS = SMOKE ? 1 : 4;
const REPETITIONS = SMOKE ? 1 : 5;
const FRAMES = SMOKE ? 2 : 8;
const WARMUP = SMOKE ? 0 : 2;
const PROJECTIONS: readonly Projection[] = ['perspective', 'orthographic'];

type Bench = { bench: BenchApi };

function psnrOf(view: BenchView, rgba: Uint8Array) {
  const ref = renderReference(defaultFrameState({
    width: SCENE.width, height: SCENE.height, time: SCENE.time,
    cameraPosition: view.cameraPosition, yaw: view.yaw, pitch: view.pitch, colorSpace: DEFAULTS.colorSpace, projection: view.projection,
  }), { samplesPerAxis: SPP_AXIS });
  return compareImages(ref, rgba).psnr;
}

test('bench: perspective and orthographic', async ({ page }) => {
  test.setTimeout(30 * 60_000);
  await page.goto('/bench/page.html');
  await page.waitForFunction(() => 'bench' in window);
  const views = SMOKE ? [VIEWS[0]] : [...VIEWS];
  const jobs = views.flatMap((v) => PROJECTIONS.map((projection) => ({ ...v, projection })));
  const samples = new Map<string, number[]>();
  const key = (v: BenchView) => `${v.projection}|${v.name}`;
  for (let rep = 0; rep < REPETITIONS; rep++) {
    for (const v of shuffled(jobs, 77 + rep)) {
      const ms = await page.evaluate(([scene, knobs, view, frames, warmup]) =>
        (window as unknown as Bench).bench.time('ours', scene, knobs, view, frames, warmup), [SCENE, DEFAULTS, v, FRAMES, WARMUP] as const);
      samples.set(key(v), [...(samples.get(key(v)) ?? []), ms]);
    }
  }
  const cells = new Map<string, { ms: number; iqr: number; all: number; glass: number; dark: number }>();
  for (const v of jobs) {
    const px = await page.evaluate(([scene, knobs, view]) =>
      (window as unknown as Bench).bench.pixels('ours', scene, knobs, view), [SCENE, DEFAULTS, v] as const);
    const psnr = psnrOf(v, new Uint8Array(Buffer.from(px.data, 'base64')));
    const t = summary(samples.get(key(v))!);
    cells.set(key(v), { ms: t.median, iqr: t.iqr, all: psnr.all, glass: psnr.glass, dark: psnr.dark });
  }
  const f = (x: number, d = 2) => (Number.isFinite(x) ? x.toFixed(d) : '—');
  const lines = [
    '# Bench: perspective and orthographic', '',
    `The element's defaults (tessellation auto, samples 4, reflection-scale 1, color-space ${DEFAULTS.colorSpace}) at ${SCENE.width}×${SCENE.height}, time ${SCENE.time} s, in each bench view (bench/views.ts), drawn with projection perspective and orthographic (sized at the glass centre: [orthographic size](../docs/interaction.md#orthographic-size)).`,
    `ms/frame: median [IQR] of ${REPETITIONS} repetitions × ${FRAMES} frames, shuffled round-robin, wall clock. PSNR: against the float64 reference of the same projection and colour space at ${SPP_AXIS ** 2} samples per pixel (all / glass / dark; dark: pixels whose reference, as displayed, is below 32/255 in every channel).`, '',
    '| view | perspective ms | perspective PSNR dB | orthographic ms | orthographic PSNR dB |',
    '|---|---|---|---|---|',
  ];
  const mean = (xs: number[]) => xs.reduce((a, b) => a + b, 0) / xs.length;
  for (const v of views) {
    const [p, o] = PROJECTIONS.map((projection) => cells.get(`${projection}|${v.name}`)!);
    lines.push(`| ${v.name} | ${f(p.ms)} [${f(p.iqr)}] | ${f(p.all, 1)} / ${f(p.glass, 1)} / ${f(p.dark, 1)} | ${f(o.ms)} [${f(o.iqr)}] | ${f(o.all, 1)} / ${f(o.glass, 1)} / ${f(o.dark, 1)} |`);
  }
  const avg = PROJECTIONS.map((projection) => {
    const c = views.map((v) => cells.get(`${projection}|${v.name}`)!);
    return { ms: mean(c.map((x) => x.ms)), all: mean(c.map((x) => Math.min(x.all, 99))) };
  });
  lines.push(`| **mean** | ${f(avg[0].ms)} | ${f(avg[0].all, 1)} | ${f(avg[1].ms)} | ${f(avg[1].all, 1)} |`);
  const markdown = lines.join('\n') + '\n';
  console.log('\n' + markdown);
  if (!SMOKE) writeFileSync(new URL('./projection.md', import.meta.url), markdown);
  for (const c of cells.values()) {
    expect(Number.isFinite(c.ms)).toBe(true);
    expect(Number.isFinite(c.all)).toBe(true);
  }
});
