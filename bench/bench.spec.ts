// The benchmark: every configuration × view, timed in shuffled round-robin, scored against
// the float64 reference (SPEC §5), with the three.js peer in the same run. Writes
// bench/results.md and bench/results.json and prints the table. Asserts no timings.
import { existsSync, mkdirSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import { createHash } from 'node:crypto';
import { test, expect } from '../tests/e2e/fixtures';
import { renderReference, compareImages, type ReferenceImage } from '../src/reference';
import { BASELINE, CONFIGS, DEFAULTS, configName, type BenchConfig, type Knobs } from './configs';
import { SKIP_VIEWS, VIEWS, type BenchView } from './views';
import { DEFAULT_CUBE_DISTANCE } from '../src/element/attributes';
import { summary, shuffled } from './stats';
import { paretoFront } from './pareto';
import { resample } from './resample';
import { aggregate, formatResults, type Row, type ViewResult } from './report';
import type { BenchApi, Scene } from './bench-page';

const SMOKE = process.env.BENCH_SMOKE === '1';
const SCENE: Scene = SMOKE ? { width: 160, height: 90, time: 1.25 } : { width: 640, height: 360, time: 1.25 };
const REFERENCE_SPP_AXIS = SMOKE ? 1 : 8;
const REPETITIONS = SMOKE ? 1 : 5;
const FRAMES = SMOKE ? 2 : 8;
const WARMUP = SMOKE ? 0 : 2;
const CACHE = new URL('./.cache/', import.meta.url);

type Bench = { bench: BenchApi };

/** The reference is slow (64 spp, float64): cache it by everything that defines it. */
function reference(view: BenchView): ReferenceImage {
  const state = {
    width: SCENE.width, height: SCENE.height, time: SCENE.time, spin: 0.8, cubeDistance: DEFAULT_CUBE_DISTANCE, transparency: 0.5,
    ior: 1.5, fresnel: 'exact' as const, fov: 60, cameraPosition: view.cameraPosition, yaw: view.yaw, pitch: view.pitch,
    colorSpace: 'none' as const, view: 'final' as const,
  };
  const sources = ['../src/reference/', '../src/scene/', '../src/math/'].map((d) => new URL(d, import.meta.url));
  const key = createHash('sha256').update(JSON.stringify({ state, REFERENCE_SPP_AXIS, v: sourcesVersion(sources) })).digest('hex').slice(0, 16);
  const file = new URL(`reference-${key}.json`, CACHE);
  if (existsSync(file)) {
    const j = JSON.parse(readFileSync(file, 'utf8'));
    return { ...j, rgba: new Uint8ClampedArray(Buffer.from(j.rgba, 'base64')), rgb: new Float64Array(new Uint8Array(Buffer.from(j.rgb, 'base64')).buffer), regions: new Uint8Array(Buffer.from(j.regions, 'base64')) };
  }
  const ref = renderReference(state, { samplesPerAxis: REFERENCE_SPP_AXIS });
  mkdirSync(CACHE, { recursive: true });
  writeFileSync(file, JSON.stringify({
    ...ref, rgba: Buffer.from(ref.rgba).toString('base64'), rgb: Buffer.from(new Uint8Array(ref.rgb.buffer)).toString('base64'),
    regions: Buffer.from(ref.regions).toString('base64'),
  }));
  return ref;
}

/** A digest of the reference's own sources, so a change to them invalidates the cache. */
function sourcesVersion(dirs: URL[]): string {
  const h = createHash('sha256');
  for (const d of dirs) {
    for (const f of readdirSync(d).sort()) {
      if (f.endsWith('.ts')) h.update(readFileSync(new URL(f, d)));
    }
  }
  return h.digest('hex').slice(0, 12);
}

test('bench', async ({ page }) => {
  test.setTimeout(80 * 60_000);
  await page.goto('/bench/page.html');
  await page.waitForFunction(() => 'bench' in window);
  const info = await page.evaluate(() => (window as unknown as Bench).bench.info());

  const configs: BenchConfig[] = SMOKE ? [{ name: 'baseline', ...BASELINE }] : [...CONFIGS];
  const views: BenchView[] = SMOKE ? [VIEWS[0]] : [...VIEWS];
  type Kind = 'ours' | 'scene-only' | 'clear-only' | 'three';
  const runs: { key: string; kind: Kind; knobs: Knobs; label: string }[] = [
    ...configs.map((c) => ({
      key: c.name, kind: 'ours' as const, knobs: c as Knobs,
      label: c.name === configName(DEFAULTS) ? `**defaults**: ${c.name}` : c.name,
    })),
    { key: 'three.js', kind: 'three', knobs: BASELINE, label: 'three.js (Reflector, HalfFloat, MSAA 4)' },
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

  // Accuracy against the reference, per view.
  const refs = new Map(views.map((v) => [v.name, reference(v)]));
  const rows: Row[] = [];
  for (const r of runs) {
    const perView: ViewResult[] = [];
    for (const v of views) {
      const t = summary(samples.get(`${r.key}|${v.name}`)!);
      let error = null;
      if (r.kind === 'ours' || r.kind === 'three') {
        const px = await page.evaluate(([kind, scene, knobs, view]) =>
          (window as unknown as Bench).bench.pixels(kind, scene, knobs, view), [r.kind as 'ours' | 'three', SCENE, r.knobs, v] as const);
        const rgba = resample(Buffer.from(px.data, 'base64'), px.width, px.height, SCENE.width, SCENE.height);
        const c = compareImages(refs.get(v.name)!, rgba);
        error = { psnr: c.psnr, maxError: c.maxError };
      }
      perView.push({ view: v.name, ms: t.median, iqr: t.iqr, gpuMs: gpu.get(`${r.key}|${v.name}`) ?? null, error });
    }
    rows.push({ key: r.key, label: r.label, kind: r.kind, knobs: r.knobs, perView });
  }

  const scored = rows.filter((r) => r.kind === 'ours' || r.kind === 'three');
  const front = paretoFront(scored.map(aggregate));
  scored.forEach((r, i) => { r.pareto = front[i]; });

  // What SPEC §7's skips save: the defaults with and without them, same views, interleaved.
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
  const text = formatResults({ info, scene: SCENE, referenceSpp: REFERENCE_SPP_AXIS ** 2, repetitions: REPETITIONS, frames: FRAMES, rows, sizes, views: views.map((v) => v.name), savings });
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
