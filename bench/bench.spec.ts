// The benchmark: every configuration × view, timed in shuffled round-robin, scored against
// the float64 reference (docs/knobs.md#measuring-accuracy), with the three.js peer in the same run. Writes
// bench/results.md and bench/results.json and prints the table. Asserts no timings.
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import { test, expect } from '../tests/e2e/fixtures';
import { compareImages, type ReferenceImage } from '../src/reference';
import { COLOR_SPACES } from '../src/math/srgb';
import { BASELINE, CONFIGS, DEFAULTS, configName, type BenchConfig, type Knobs } from './configs';
import { SKIP_VIEWS, VIEWS, type BenchView } from './views';
import { summary, shuffled } from './stats';
import { paretoFront } from './pareto';
import { resample } from './resample';
import { cachedReference } from './reference-cache';
import { aggregate, formatResults, type Row, type ViewResult } from './report';
import type { BenchApi, Scene } from './bench-page';

const SMOKE = process.env.BENCH_SMOKE === '1';
const SCENE: Scene = SMOKE ? { width: 160, height: 90, time: 1.25 } : { width: 640, height: 360, time: 1.25 };
const REFERENCE_SPP_AXIS = SMOKE ? 1 : 8;
const REPETITIONS = SMOKE ? 1 : 5;
const FRAMES = SMOKE ? 2 : 8;
const WARMUP = SMOKE ? 0 : 2;

type Bench = { bench: BenchApi };

test('bench', async ({ page }) => {
  test.setTimeout(80 * 60_000);
  await page.goto('/bench/page.html');
  await page.waitForFunction(() => 'bench' in window);
  const info = await page.evaluate(() => (window as unknown as Bench).bench.info());

  // The smoke run keeps one configuration in each colour space, so both paths cannot rot.
  const configs: BenchConfig[] = SMOKE ? CONFIGS.filter((c) => configName({ ...c, colorSpace: 'srgb' }) === 'baseline') : [...CONFIGS];
  const views: BenchView[] = SMOKE ? [VIEWS[0]] : [...VIEWS];
  type Kind = 'ours' | 'scene-only' | 'clear-only' | 'three';
  const NONE: Knobs = { ...BASELINE, colorSpace: 'none' };
  const runs: { key: string; kind: Kind; knobs: Knobs; label: string }[] = [
    ...configs.map((c) => ({
      key: c.name, kind: 'ours' as const, knobs: c as Knobs,
      label: configName({ ...c, colorSpace: DEFAULTS.colorSpace }) === configName(DEFAULTS) ? `**defaults**: ${c.name}` : c.name,
    })),
    { key: 'three.js', kind: 'three', knobs: BASELINE, label: 'three.js (Reflector, HalfFloat, MSAA 4, sRGB output)' },
    { key: 'three.js, color-space none', kind: 'three', knobs: NONE, label: 'three.js (Reflector, HalfFloat, MSAA 4), color-space none' },
    { key: 'scene only', kind: 'scene-only', knobs: BASELINE, label: 'baseline, scene pass only' },
    { key: 'clear only', kind: 'clear-only', knobs: BASELINE, label: 'clear only' },
  ];

  // Timing: shuffled round-robin over run × view, so drift spreads evenly.
  const samples = new Map<string, number[]>();
  const jobs = runs.flatMap((r) => views.map((v) => ({ r, v })));
  for (let rep = 0; rep < REPETITIONS; rep++) {
    for (const { r, v } of shuffled(jobs, 1234 + rep)) {
      const ms = await page.evaluate(([kind, scene, knobs, view, frames, warmup]) =>
        (window as unknown as Bench).bench.time(kind, scene, knobs, view, frames, warmup),
        [r.kind, SCENE, r.knobs, v, FRAMES, WARMUP] as const);
      const k = `${r.key}|${v.name}`;
      samples.set(k, [...(samples.get(k) ?? []), ms]);
    }
  }

  // GPU time per frame from timer queries where the context has them (one pass, shuffled).
  const gpu = new Map<string, number | null>();
  for (const { r, v } of shuffled(jobs, 4321)) {
    const ms = await page.evaluate(([kind, scene, knobs, view, frames]) =>
      (window as unknown as Bench).bench.gpuTime(kind, scene, knobs, view, frames),
      [r.kind, SCENE, r.knobs, v, FRAMES] as const);
    gpu.set(`${r.key}|${v.name}`, ms);
  }

  // Accuracy against the reference of the row's own colour space, per view.
  const refs = new Map<string, ReferenceImage>();
  for (const colorSpace of COLOR_SPACES) {
    for (const view of views) {
      refs.set(`${colorSpace}|${view.name}`, cachedReference({ ...SCENE, view, colorSpace, samplesPerAxis: REFERENCE_SPP_AXIS }));
    }
  }
  /** Pixel-ratio rows brought back to the bench size in linear light instead of as stored (srgb only). */
  const linearResampled = new Map<string, ViewResult[]>();
  const rows: Row[] = [];
  for (const r of runs) {
    const perView: ViewResult[] = [];
    for (const v of views) {
      const t = summary(samples.get(`${r.key}|${v.name}`)!);
      let error = null;
      if (r.kind === 'ours' || r.kind === 'three') {
        const px = await page.evaluate(([kind, scene, knobs, view]) =>
          (window as unknown as Bench).bench.pixels(kind, scene, knobs, view), [r.kind as 'ours' | 'three', SCENE, r.knobs, v] as const);
        const bytes = Buffer.from(px.data, 'base64');
        const ref = refs.get(`${r.knobs.colorSpace}|${v.name}`)!;
        const c = compareImages(ref, resample(bytes, px.width, px.height, SCENE.width, SCENE.height));
        error = { psnr: c.psnr, maxError: c.maxError };
        if (r.knobs.pixelRatio !== 1 && r.knobs.colorSpace === 'srgb') {
          const l = compareImages(ref, resample(bytes, px.width, px.height, SCENE.width, SCENE.height, 'srgb'));
          linearResampled.set(r.key, [...(linearResampled.get(r.key) ?? []), { view: v.name, ms: NaN, iqr: NaN, gpuMs: null, error: { psnr: l.psnr, maxError: l.maxError } }]);
        }
      }
      perView.push({ view: v.name, ms: t.median, iqr: t.iqr, gpuMs: gpu.get(`${r.key}|${v.name}`) ?? null, error });
    }
    rows.push({ key: r.key, label: r.label, kind: r.kind, knobs: r.knobs, perView });
  }

  const scored = rows.filter((r) => r.kind === 'ours' || r.kind === 'three');
  // One front per colour space: a none row's PSNR is against another reference. Only srgb has
  // enough rows for a front to mean anything; none rows are left off it.
  const srgbRows = scored.filter((r) => r.knobs.colorSpace === 'srgb');
  const front = paretoFront(srgbRows.map(aggregate));
  srgbRows.forEach((r, i) => { r.pareto = front[i]; });

  // What the skips of docs/knobs.md#reflection-skips save: the defaults with and without them, same views, interleaved.
  const savings: { view: string; on: number; off: number }[] = [];
  const savingViews = SMOKE ? [] : [VIEWS[0], VIEWS[3], ...SKIP_VIEWS];
  const saved = new Map<string, number[]>();
  for (let rep = 0; rep < REPETITIONS; rep++) {
    const pairs = savingViews.flatMap((v) => (['ours', 'ours-unoptimized'] as const).map((kind) => ({ v, kind })));
    for (const { v, kind } of shuffled(pairs, 99 + rep)) {
      const ms = await page.evaluate(([k, scene, knobs, view, frames, warmup]) =>
        (window as unknown as Bench).bench.time(k, scene, knobs, view, frames, warmup), [kind, SCENE, DEFAULTS, v, FRAMES, WARMUP] as const);
      const key = `${kind}|${v.name}`;
      saved.set(key, [...(saved.get(key) ?? []), ms]);
    }
  }
  for (const v of savingViews) {
    savings.push({ view: v.name, on: summary(saved.get(`ours|${v.name}`)!).median, off: summary(saved.get(`ours-unoptimized|${v.name}`)!).median });
  }

  const sizes = await bundleSizes();
  const linear = [...linearResampled].map(([key, perView]) => ({ ...rows.find((r) => r.key === key)!, perView }));
  const text = formatResults({
    info, scene: SCENE, referenceSpp: REFERENCE_SPP_AXIS ** 2, repetitions: REPETITIONS, frames: FRAMES, rows, sizes, views: views.map((v) => v.name), savings,
    linearResampled: linear,
  });
  console.log('\n' + text.markdown);
  if (!SMOKE) {
    writeFileSync(new URL('./results.md', import.meta.url), text.markdown);
    writeFileSync(new URL('./results.json', import.meta.url), JSON.stringify(text.json, null, 2) + '\n');
  }
  // The smoke run proves the pipeline end to end: every row timed and scored, nothing NaN.
  for (const r of rows) for (const v of r.perView) expect(Number.isFinite(v.ms), `${r.key} ${v.view}`).toBe(true);
  for (const r of scored) for (const v of r.perView) expect(Number.isFinite(v.error!.psnr.all), `${r.key} ${v.view} PSNR`).toBe(true);
});

/** min+gzip of our standalone build, and of the peer built the same way (three bundled). */
async function bundleSizes(): Promise<{ ours: number | null; three: number | null }> {
  const gz = (path: URL) => (existsSync(path) ? gzipSync(readFileSync(path), { level: 9 }).length : null);
  const peerOut = new URL('../dist-bench/', import.meta.url);
  if (!SMOKE) {
    const { build } = await import('vite');
    await build({
      configFile: false, logLevel: 'warn',
      build: {
        outDir: peerOut.pathname, emptyOutDir: true, minify: true, target: 'es2022',
        lib: { entry: new URL('./three-peer.ts', import.meta.url).pathname, formats: ['es'], fileName: () => 'three-peer.js' },
      },
    });
  }
  return {
    ours: gz(new URL('../dist/glass-plane-scene.standalone.js', import.meta.url)),
    three: gz(new URL('three-peer.js', peerOut)),
  };
}
