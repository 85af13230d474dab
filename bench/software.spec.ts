// `npm run bench`, the software renderer's rows. The default scene at 640×360 in the
// element's worker (round trip and the worker's own time) next to the WebGL renderer, with PSNR
// against the float64 reference, and in Node by shading mode; a ~100k-triangle mesh with its
// frame split into transform, raster and shading; a bicubic Bézier patch's evaluation time and
// image error against E; and main-thread long tasks while the element draws continuously, in a
// worker and without one; and the default scene's accuracy in every view of bench/views.ts. In
// linear light (color-space srgb, the default), with rows as stored (none) against their own reference.
// Writes bench/software.md; BENCH_SMOKE=1 runs each part tiny so the pipeline cannot rot.
import { writeFileSync } from 'node:fs';
import { loadavg } from 'node:os';
import { test, expect } from '../tests/e2e/fixtures';
import { renderScene, compareImages, type ImageComparison } from '../src/reference';
import { DEFAULT_CAMERA_POSITION, DEFAULT_CAMERA_ROTATION, DEFAULT_CUBE_DISTANCE } from '../src/element/attributes';
import { bezierPatchMesh } from '../src/scene/geometry/bezier';
import { defaultScene } from '../src/scene/default-scene';
import { SoftwareRenderer, type SoftwareTiming } from '../src/software';
import type { ColorSpace, FrameState } from '../src/frame/types';
import { defaultFrameState } from '../tests/unit/helpers/frame-state';
import { BENCH_SCENES } from './scenes';
import { cachedReference } from './reference-cache';
import { BAR_ALL_DB, BAR_DARK_DB } from './report';
import { BEZIER_PATCH, BEZIER_VIEW, bezierScene, WHITE, WHITE_URL } from './bezier-scene';
import { summary, shuffled } from './stats';
import { VIEWS, type BenchView } from './views';
import type { Size, SoftwareBenchApi } from './software-page';

const SMOKE = process.env.BENCH_SMOKE === '1';
const SIZE: Size = SMOKE ? { width: 160, height: 90 } : { width: 640, height: 360 };
const REF_SPP = SMOKE ? 1 : 4;
const REPETITIONS = SMOKE ? 1 : 5;
const FRAMES = SMOKE ? 2 : 10;
const WARMUP = SMOKE ? 0 : 3;
const TARGET_MS = 25;
const GAUSS_100K = BENCH_SCENES.findIndex((b) => b.scene.glass !== null && b.triangles > 90_000);
const BEZIER_E = SMOKE ? [10] : [5, 10, 20, 40, 160];
/** The reference's tessellation of the patch (bezierPatchMesh's maximum) and a coarser one to show it has converged. */
const REF_E = SMOKE ? 40 : 1024;
const REF_E_CHECK = SMOKE ? null : 512;
const PROBE_MS = SMOKE ? 500 : 3000;
/** Section 6's probes per worker count and samples, alternating with the other counts'. */
const PROBE_ROUNDS = SMOKE ? 1 : 2;
const PIXEL_TIME = 1.25;
/** Section 5's reference: bench.spec.ts's own (same size, time, views and spp), so the cache serves both. */
const VIEWS_REF_SPP = SMOKE ? 1 : 8;
const REGIONS = ['all', 'objects', 'glass', 'edges', 'dark'] as const;

type Page = import('@playwright/test').Page;
const api = (page: Page) => ({
  call: <K extends keyof SoftwareBenchApi>(name: K, ...args: Parameters<SoftwareBenchApi[K]>) =>
    page.evaluate(([name, args]) => {
      const b = (window as unknown as { softwareBench: Record<string, (...a: unknown[]) => unknown> }).softwareBench;
      return b[name](...args);
    }, [name, args] as const) as Promise<Awaited<ReturnType<SoftwareBenchApi[K]>>>,
});

/**
 * How a software row samples a pixel: `samples` as the element passes it (4, its default: 2×2
 * samples, shaded once per pixel, as MSAA; 0: one sample) and the renderer's supersampling.
 */
interface Sampling { key: string; label: string; samplesPerAxis: number; samples: FrameState['samples'] }
const MSAA: Sampling = { key: 'msaa', label: '2×2 multisampled (samples 4, the default)', samplesPerAxis: 1, samples: 4 };
const ONE: Sampling = { key: 'one', label: '1 (samples 0)', samplesPerAxis: 1, samples: 0 };
const SSAA: Sampling = { key: 'ssaa', label: '2×2 supersampled', samplesPerAxis: 2, samples: 4 };

function state(size: Size, view: BenchView, time = PIXEL_TIME, colorSpace: ColorSpace = 'srgb', samples: FrameState['samples'] = 4): FrameState {
  return defaultFrameState({
    width: size.width, height: size.height, time, cameraPosition: view.cameraPosition, yaw: view.yaw, pitch: view.pitch, colorSpace, samples,
  });
}
const DEFAULT_VIEW: BenchView = { name: 'default', cameraPosition: [...DEFAULT_CAMERA_POSITION], yaw: DEFAULT_CAMERA_ROTATION[0], pitch: DEFAULT_CAMERA_ROTATION[1] };

const bytes = (b64: string) => new Uint8Array(Buffer.from(b64, 'base64'));
const f1 = (x: number) => (Number.isFinite(x) ? x.toFixed(1) : String(x));
const med = (xs: number[]) => { const s = summary(xs); return `${s.median.toFixed(1)} [${s.iqr.toFixed(1)}]`; };
const regionCells = (c: ImageComparison) => REGIONS.map((g) => (Number.isNaN(c.psnr[g]) ? '—' : f1(c.psnr[g]))).join(' / ');
const psnrCells = (c: ImageComparison) => `${regionCells(c)} | ${c.maxError.toFixed(0)}`;

/** Median ms of `f` over `runs` runs after one untimed. */
function timeNode(f: () => unknown, runs: number): number[] {
  f();
  const out: number[] = [];
  for (let i = 0; i < runs; i++) {
    const t0 = performance.now();
    f();
    out.push(performance.now() - t0);
  }
  return out;
}

async function defaultSceneRows(page: Page): Promise<string[]> {
  const b = api(page);
  type Job = { key: string; run(): Promise<void> };
  const rt = new Map<string, number[]>(), own = new Map<string, number[]>();
  const push = (m: Map<string, number[]>, k: string, xs: number[]) => m.set(k, [...(m.get(k) ?? []), ...xs]);
  // Element's worker: each sampling in srgb, the default one and one sample in none; the bench
  // worker (the same renderer, timing its own render) for the default and the supersampled.
  const hostRows: [Sampling, ColorSpace][] = [[MSAA, 'srgb'], [ONE, 'srgb'], [SSAA, 'srgb'], [MSAA, 'none'], [ONE, 'none']];
  const hostKey = (m: Sampling, cs: ColorSpace) => `host ${m.key} ${cs}`;
  const jobs: Job[] = [
    ...hostRows.map(([m, cs]) => ({
      key: hostKey(m, cs), run: async () => { push(rt, hostKey(m, cs), await b.call('hostFrames', SIZE, m.samplesPerAxis, FRAMES, WARMUP, cs, m.samples)); },
    })),
    ...[MSAA, SSAA].map((m) => ({
      key: `worker ${m.key}`, run: async () => {
        const r = await b.call('workerFrames', null, SIZE, m.samplesPerAxis, FRAMES, WARMUP, null);
        push(rt, `worker ${m.key}`, r.map((x) => x.roundTrip));
        push(own, `worker ${m.key}`, r.map((x) => x.render));
      },
    })),
    { key: 'gl', run: async () => { push(rt, 'gl', await b.call('glFrames', SIZE, FRAMES, WARMUP)); } },
    { key: 'gl none', run: async () => { push(rt, 'gl none', await b.call('glFrames', SIZE, FRAMES, WARMUP, null, 'none')); } },
  ];
  for (let rep = 0; rep < REPETITIONS; rep++) for (const j of shuffled(jobs, 11 + rep)) await j.run();

  const ref = renderScene(defaultScene(DEFAULT_CUBE_DISTANCE, 0.8), state(SIZE, DEFAULT_VIEW), null, { samplesPerAxis: REF_SPP });
  const refNone = renderScene(defaultScene(DEFAULT_CUBE_DISTANCE, 0.8), state(SIZE, DEFAULT_VIEW, PIXEL_TIME, 'none'), null, { samplesPerAxis: REF_SPP });
  const cmp = new Map<string, ImageComparison>();
  for (const [m, cs] of hostRows) {
    const px = bytes(await b.call('hostPixels', SIZE, m.samplesPerAxis, PIXEL_TIME, cs, m.samples));
    cmp.set(hostKey(m, cs), compareImages(cs === 'srgb' ? ref : refNone, px));
  }
  cmp.set('gl', compareImages(ref, bytes(await b.call('glPixels', SIZE, PIXEL_TIME, null))));
  cmp.set('gl none', compareImages(refNone, bytes(await b.call('glPixels', SIZE, PIXEL_TIME, null, 'none'))));
  for (const c of cmp.values()) expect(Number.isFinite(c.psnr.all)).toBe(true);
  const met = (k: string) => (summary(rt.get(k)!).median <= TARGET_MS ? 'yes' : 'no');
  const none = (cs: ColorSpace) => (cs === 'none' ? ', color-space none' : '');
  return [
    `## 1. Default scene, ${SIZE.width}×${SIZE.height}`, '',
    `Default knobs (phong, fresnel exact, samples 4; WebGL: reflection-scale 1, tessellation auto); the clock moves each frame so the cube turns. ` +
      `${REPETITIONS} repetitions × ${FRAMES} frames per row (after ${WARMUP} warm-up frames), rows shuffled per repetition. ` +
      '**Samples per pixel**: the software renderer honours `samples` as WebGL does — 4 (the default; 2 too) draws 2×2 samples per pixel, coverage and depth per sample, ' +
      'each triangle shaded once per pixel at its centre, the samples averaged in linear light (multisampling); 0 draws one sample at the centre; ' +
      '"2×2 supersampled" shades every sample (SoftwareRenderer samplesPerAxis 2, the bench and tests only). ' +
      `**Round trip**: main thread, request posted → pixels back (one frame in flight, as the element does); through the element's own SoftwareHost ` +
      `(src/element/software-host.ts, its worker src/software/worker.ts) and through a bench worker (bench/software-worker.ts, the same SoftwareRenderer) ` +
      `that also reports **its own render time** (render() and the copy of the pixels, inside the worker). WebGL: renderer.render() closed by a 1-pixel readPixels per frame. ` +
      `PSNR against the float64 reference (renderScene, ${REF_SPP}×${REF_SPP} spp, box-filtered) at t = ${PIXEL_TIME} s, in the row's colour space: ` +
      'linear light with sRGB output (color-space srgb, the element\'s default) against the srgb reference, the rows marked color-space none (values as stored) against the none reference. ' +
      'dark: pixels whose reference, as displayed, is below 32/255 in every channel (counted in their own region too).', '',
    '| renderer | samples per pixel | round trip, ms/frame median [IQR] | worker\'s own render, ms median [IQR] | ≤ 25 ms? | PSNR dB all / objects / glass / edges / dark | max err |',
    '|---|---|---|---|---|---|---|',
    ...hostRows.flatMap(([m, cs]) => {
      const k = hostKey(m, cs), w = `worker ${m.key}`;
      const row = `| software, SoftwareHost (element's worker)${none(cs)} | ${m.label} | ${med(rt.get(k)!)} | — | ${met(k)} | ${psnrCells(cmp.get(k)!)} |`;
      return cs === 'srgb' && own.has(w) ? [row, `| software, bench worker | ${m.label} | ${med(rt.get(w)!)} | ${med(own.get(w)!)} | ${met(w)} | (same pixels) | |`] : [row];
    }),
    `| WebGL (SwiftShader), same page and run | MSAA 4 | ${med(rt.get('gl')!)} | — | ${met('gl')} | ${psnrCells(cmp.get('gl')!)} |`,
    `| WebGL (SwiftShader), color-space none | MSAA 4 | ${med(rt.get('gl none')!)} | — | ${met('gl none')} | ${psnrCells(cmp.get('gl none')!)} |`,
    '',
    ...nodeRows(),
  ];
}

/**
 * The same default scene rendered by SoftwareRenderer.render() in Node (no worker, no copy of
 * the pixels), by shading mode and samples per pixel: the renderer's own cost on this machine's
 * V8 (measured here, not in the unit suite, which asserts no time).
 */
function nodeRows(): string[] {
  const scene = defaultScene(DEFAULT_CUBE_DISTANCE, 0.8);
  const rows: [Sampling, FrameState['shading'], ColorSpace][] = [
    [MSAA, 'phong', 'srgb'], [ONE, 'phong', 'srgb'], [MSAA, 'gouraud', 'srgb'], [MSAA, 'flat', 'srgb'], [SSAA, 'phong', 'srgb'],
    [MSAA, 'phong', 'none'], [ONE, 'phong', 'none'],
  ];
  const times = new Map<string, number[]>();
  const renderers = new Map([1, 2].map((n) => [n, new SoftwareRenderer({ samplesPerAxis: n })]));
  let frame = 0;
  for (let rep = 0; rep < REPETITIONS; rep++) {
    for (const [m, shading, colorSpace] of shuffled(rows, 71 + rep)) {
      const r = renderers.get(m.samplesPerAxis)!, key = `${m.key} ${shading} ${colorSpace}`;
      // The clock moves so the cube turns: every frame is a new one.
      const next = () => r.render(scene, { ...state(SIZE, DEFAULT_VIEW, PIXEL_TIME + frame++ / 60, colorSpace, m.samples), shading });
      for (let i = 0; i < WARMUP; i++) next();
      times.set(key, [...(times.get(key) ?? []), ...timeNode(next, FRAMES)]);
    }
  }
  return [
    `In Node ${process.version} (SoftwareRenderer.render() on the main thread, no worker, no copy of the pixels), the same scene and clock, ` +
      `${REPETITIONS} repetitions × ${FRAMES} frames per row (after ${WARMUP + 1} warm-up frames), rows shuffled per repetition:`, '',
    '| samples per pixel | shading | color-space | ms/frame median [IQR] |',
    '|---|---|---|---|',
    ...rows.map(([m, shading, colorSpace]) => `| ${m.label} | ${shading} | ${colorSpace} | ${med(times.get(`${m.key} ${shading} ${colorSpace}`)!)} |`),
    '',
  ];
}

async function split(page: Page): Promise<string[]> {
  const b = api(page), bs = BENCH_SCENES[GAUSS_100K];
  type Kind = 'off' | 'shaded' | 'constant';
  const kinds: Kind[] = ['off', 'shaded', 'constant'];
  const frames = new Map<Kind, { roundTrip: number; render: number; timing: SoftwareTiming | null }[]>();
  for (let rep = 0; rep < REPETITIONS; rep++) {
    for (const k of shuffled(kinds, 31 + rep)) {
      const r = await b.call('workerFrames', GAUSS_100K, SIZE, 1, SMOKE ? 1 : 4, SMOKE ? 0 : 1, k === 'off' ? null : { constantFragments: k === 'constant' });
      frames.set(k, [...(frames.get(k) ?? []), ...r]);
    }
  }
  const t = (k: Kind, f: (x: SoftwareTiming) => number) => summary(frames.get(k)!.map((x) => f(x.timing!))).median;
  const off = frames.get('off')!;
  const vertex = t('shaded', (x) => x.vertex), trisShaded = t('shaded', (x) => x.triangles), trisConst = t('constant', (x) => x.triangles);
  const glass = t('shaded', (x) => x.glass), total = t('shaded', (x) => x.total);
  const other = total - vertex - trisShaded - glass;
  const shading = trisShaded - trisConst;
  const pct = (x: number) => `${((100 * x) / total).toFixed(0)} %`;
  expect(total).toBeGreaterThan(0);
  return [
    `## 2. ${bs.name} (${bs.triangles.toLocaleString('en')} triangles), ${SIZE.width}×${SIZE.height}, samples 4 (the default: 2×2 multisampled)`, '',
    `bench/scenes.ts's Gaussian 225² over a glass floor, in the bench worker; ${REPETITIONS} repetitions × ${SMOKE ? 1 : 4} frames of each kind (timing off; timing on, shaded; timing on, constant fragments), shuffled. ` +
      'Every triangle is drawn twice (scene and reflection passes). ' +
      '**Method**: SoftwareRenderer.timing (an optional record; null in the element) adds performance.now() around each object\'s vertex stage and its drawTriangles call, and around the glass draw — per draw, never per pixel. ' +
      'Clipping, setup, coverage, depth and the fragment calls are interleaved inside drawTriangles, so the split of that call comes from a second run whose objects\' fragments write a constant colour: ' +
      '**raster** = drawTriangles with constant fragments (clipping + triangle setup + edge functions + depth test + perspective-correct barycentrics and derivatives + a store), ' +
      '**shading** = drawTriangles shaded − constant (interpolation of varyings, Blinn-Phong, texture, blend). **transform** = vertex stages (model/view/projection of every vertex, both passes). ' +
      '**other** = clears, sorting, resolve to RGBA8 and the copy. Medians of the per-frame figures.', '',
    '| | ms/frame median [IQR] |',
    '|---|---|',
    `| worker's own render, timing off | ${med(off.map((x) => x.render))} |`,
    `| round trip, timing off | ${med(off.map((x) => x.roundTrip))} |`,
    `| worker's own render, timing on (shaded) | ${med(frames.get('shaded')!.map((x) => x.render))} |`,
    '',
    '| phase | ms/frame (median) | share of the frame |',
    '|---|---|---|',
    `| transform (vertex stage) | ${vertex.toFixed(1)} | ${pct(vertex)} |`,
    `| raster (clipping, setup, coverage, depth) | ${trisConst.toFixed(1)} | ${pct(trisConst)} |`,
    `| shading (fragments) | ${shading.toFixed(1)} | ${pct(shading)} |`,
    `| glass (mask + composite) | ${glass.toFixed(1)} | ${pct(glass)} |`,
    `| other | ${other.toFixed(1)} | ${pct(other)} |`,
    `| total (timing on, shaded) | ${total.toFixed(1)} | 100 % |`,
    '',
  ];
}

async function bezier(page: Page): Promise<string[]> {
  const b = api(page);
  const images = new Map([[WHITE_URL, WHITE]]);
  const s = state(SIZE, BEZIER_VIEW);
  const ref = renderScene(bezierScene(REF_E), s, images, { samplesPerAxis: REF_SPP });
  let check = '';
  if (REF_E_CHECK !== null) {
    const c = compareImages(ref, renderScene(bezierScene(REF_E_CHECK), s, images, { samplesPerAxis: REF_SPP }).rgba);
    check = ` The reference at E = ${REF_E_CHECK} against the one at E = ${REF_E}: ${f1(c.psnr.all)} dB (max error ${c.maxError.toFixed(0)}), so E = ${REF_E} stands for the exact surface well beyond these rows.`;
  }
  const runs = (e: number) => (SMOKE ? 2 : Math.max(15, Math.min(400, Math.round(2e6 / (e * e)))));
  const lines = [
    `## 3. Bézier: a bicubic patch, ${SIZE.width}×${SIZE.height}`, '',
    'bench/bezier-scene.ts: a 4×4 control net, a bump with opposite corners twisted up and down (a saddle), white (1×1 image texture, so texture filtering adds no error), ' +
      'a point light placed for two Blinn-Phong highlights (shininess 60). **Evaluation**: bezierPatchMesh(patch, E) (E×E de Casteljau points, normals from the partial derivatives, UVs, indices) ' +
      `in Node ${process.version}, median of repeated calls. **PSNR** against the float64 reference renderer drawing the same patch tessellated at E = ${REF_E} ` +
      `(2·${REF_E - 1}² triangles through its BVH, normals interpolated per ray), ${REF_SPP}×${REF_SPP} spp; the software renderer in Node ` +
      `at 1 spp and at ${REF_SPP}×${REF_SPP} spp (the reference's own sample positions: the row isolates the geometry's error), and WebGL (MSAA 4, this page) at each E.${check} ` +
      'Both images are rounded to 8 bits, which alone caps PSNR near 59 dB where they differ by rounding only. ' +
      'In linear light (color-space srgb, the default) on every side; dark: pixels whose reference, as displayed, is below 32/255 in every channel.', '',
    `| E | triangles | bezierPatchMesh, ms median [IQR] (runs) | µs per point | software 1 spp: ms/frame (Node) | PSNR 1 spp all / objects / edges / dark | software ${REF_SPP}×${REF_SPP}: PSNR all / objects / edges / dark, max err | WebGL: ms/frame | WebGL PSNR all / objects / edges / dark |`,
    '|---|---|---|---|---|---|---|---|---|',
  ];
  const three = (c: ImageComparison) => (['all', 'objects', 'edges', 'dark'] as const).map((g) => f1(c.psnr[g])).join(' / ');
  const one = new SoftwareRenderer({ samplesPerAxis: 1 }), fine = new SoftwareRenderer({ samplesPerAxis: REF_SPP });
  const s1 = { ...s, samples: 0 }; // one sample per pixel, as labelled
  for (const e of [...BEZIER_E, ...(SMOKE ? [] : [REF_E])]) {
    const evals = e === REF_E ? timeNode(() => bezierPatchMesh(BEZIER_PATCH, e), SMOKE ? 1 : 5) : timeNode(() => bezierPatchMesh(BEZIER_PATCH, e), runs(e));
    const scene = bezierScene(e);
    const swMs = timeNode(() => one.render(scene, s1, images), SMOKE ? 1 : e === REF_E ? 3 : 9);
    const c1 = compareImages(ref, one.render(scene, s1, images));
    const c4 = compareImages(ref, fine.render(scene, s, images));
    let glCells = '— | —';
    if (e !== REF_E) {
      const glMs = await b.call('glFrames', SIZE, SMOKE ? 1 : 10, SMOKE ? 0 : 2, e);
      const cg = compareImages(ref, bytes(await b.call('glPixels', SIZE, PIXEL_TIME, e)));
      glCells = `${med(glMs)} | ${three(cg)}`;
    }
    const ev = summary(evals);
    lines.push(`| ${e}${e === REF_E ? ' (the reference\'s own mesh)' : ''} | ${(2 * (e - 1) ** 2).toLocaleString('en')} | ${ev.median < 1 ? ev.median.toFixed(3) : ev.median.toFixed(1)} [${ev.iqr.toFixed(ev.median < 1 ? 3 : 1)}] (${evals.length}) | ` +
      `${((1000 * ev.median) / (e * e)).toFixed(2)} | ${med(swMs)} | ${three(c1)} | ${three(c4)}, ${c4.maxError.toFixed(0)} | ${glCells} |`);
  }
  lines.push('');
  return lines;
}

/**
 * The default scene in every bench view (bench/views.ts), software renderer in Node (the pixels
 * the worker returns), both colour spaces, each against its own float64 reference: the
 * bars (srgb ≥ 45 dB overall and ≥ 40 dB in the dark region) for the software renderer.
 */
function views(): string[] {
  const views = SMOKE ? [VIEWS[0]] : [...VIEWS];
  const modes = SMOKE ? [MSAA] : [ONE, MSAA, SSAA];
  const scene = defaultScene(DEFAULT_CUBE_DISTANCE, 0.8);
  const under: string[] = [];
  const lines = [
    `## 5. Default scene in every bench view, ${SIZE.width}×${SIZE.height}`, '',
    `bench/views.ts's ${views.length} views at t = ${PIXEL_TIME} s (those of bench/results.md), SoftwareRenderer.render() in Node, ${modes.map((m) => m.label).join('; ')}, ` +
      `against the float64 reference of the same view and colour space at ${VIEWS_REF_SPP ** 2} spp (bench.spec.ts's, cached). PSNR dB ${REGIONS.join(' / ')} ("—": no pixel of that region). ` +
      `Marked ✗: an srgb figure under the bars (≥ ${BAR_ALL_DB} dB overall, ≥ ${BAR_DARK_DB} dB dark).`, '',
    `| view | ${modes.flatMap((m) => [`srgb, ${m.label}`, `none, ${m.label}`]).join(' | ')} |`,
    `|---|${modes.flatMap(() => ['---', '---']).join('|')}|`,
  ];
  const renderers = new Map([1, 2].map((n) => [n, new SoftwareRenderer({ samplesPerAxis: n })]));
  const sums = new Map<string, number[]>();
  for (const view of views) {
    const cells: string[] = [];
    for (const m of modes) {
      for (const colorSpace of ['srgb', 'none'] as const) {
        const ref = cachedReference({ ...SIZE, time: PIXEL_TIME, view, colorSpace, samplesPerAxis: VIEWS_REF_SPP });
        const c = compareImages(ref, renderers.get(m.samplesPerAxis)!.render(scene, state(SIZE, view, PIXEL_TIME, colorSpace, m.samples)));
        expect(Number.isFinite(c.psnr.all), `${view.name} ${colorSpace} ${m.key} PSNR`).toBe(true);
        const bad = colorSpace === 'srgb' && (c.psnr.all < BAR_ALL_DB || c.psnr.dark < BAR_DARK_DB);
        if (colorSpace === 'srgb' && c.psnr.all < BAR_ALL_DB) under.push(`${view.name}, ${m.label}: all ${f1(c.psnr.all)}`);
        if (colorSpace === 'srgb' && c.psnr.dark < BAR_DARK_DB) under.push(`${view.name}, ${m.label}: dark ${f1(c.psnr.dark)}`);
        cells.push(`${regionCells(c)}${bad ? ' ✗' : ''}`);
        const k = `${m.key} ${colorSpace}`;
        sums.set(k, [...(sums.get(k) ?? []), Math.min(c.psnr.all, 99)]);
      }
    }
    lines.push(`| ${view.name} | ${cells.join(' | ')} |`);
  }
  const mean = (xs: number[]) => xs.reduce((a, b) => a + b, 0) / xs.length;
  lines.push(`| **mean, all** | ${modes.flatMap((m) => (['srgb', 'none'] as const).map((cs) => f1(mean(sums.get(`${m.key} ${cs}`)!)))).join(' | ')} |`, '');
  lines.push(under.length ? `Under a bar in srgb: ${under.join('; ')}.` : 'No srgb figure is under a bar in any view.', '');
  return lines;
}

interface Probe { thread: string; frames: number; longTasks: number; longMs: number; maxLong: number; rafs: number; maxRafGap: number; blockedMs: number; windowMs: number; intervals: number[] }

/** A gap between the setTimeout probe's ticks longer than this means the main thread was held (a missed 60 Hz frame). */
const BLOCKED_GAP_MS = 16;

/** Mounts a spinning renderer="software" element and watches the main thread for `PROBE_MS`. */
async function probe(page: Page, samples: number | null = null, workers: number | null = null): Promise<Probe> {
  await page.goto('/bench/software-element.html');
  return page.evaluate(async ({ size, windowMs, blockedGap, samples, workers }) => {
    await customElements.whenDefined('glass-plane-scene');
    if (workers !== null) {
      // The element's SoftwareHost (the module it loads, served by Vite) starts this many workers.
      const url = '/src/element/software-host.ts';
      ((await import(/* @vite-ignore */ url)) as { SoftwareHost: { workerCount: number | null } }).SoftwareHost.workerCount = workers;
    }
    const el = document.createElement('glass-plane-scene') as HTMLElement & { stats: { frames: number; thread?: string } };
    el.setAttribute('renderer', 'software');
    if (samples !== null) el.setAttribute('samples', String(samples));
    el.style.cssText = `display:block;width:${size.width}px;height:${size.height}px`;
    document.body.append(el);
    const start = performance.now();
    while (el.stats.frames < 3) {
      if (performance.now() - start > 60_000) throw new Error('no software frames');
      await new Promise((r) => setTimeout(r, 20));
    }
    const entries: PerformanceEntry[] = [];
    const observer = new PerformanceObserver((list) => entries.push(...list.getEntries()));
    observer.observe({ type: 'longtask' });
    let rafs = 0, maxRafGap = 0, last = performance.now(), running = true;
    const tick = (now: number) => { rafs++; maxRafGap = Math.max(maxRafGap, now - last); last = now; if (running) requestAnimationFrame(tick); };
    requestAnimationFrame(tick);
    // setTimeout(1) chain: a gap well over its ~1–4 ms period is time the main thread was held.
    const gaps: [number, number][] = [];
    let lastTimer = performance.now();
    const timer = () => {
      const now = performance.now();
      if (now - lastTimer > blockedGap) gaps.push([lastTimer, now]);
      lastTimer = now;
      if (running) setTimeout(timer, 1);
    };
    setTimeout(timer, 1);
    // The time between `frame` events (the bar: a new frame every ≤ 16 ms).
    const frameTimes: number[] = [];
    const onFrame = () => frameTimes.push(performance.now());
    el.addEventListener('frame', onFrame);
    const frames0 = el.stats.frames, t0 = performance.now();
    await new Promise((r) => setTimeout(r, windowMs));
    const t1 = performance.now();
    running = false;
    el.removeEventListener('frame', onFrame);
    const intervals = frameTimes.slice(1).map((t, i) => t - frameTimes[i]);
    const frames = el.stats.frames - frames0;
    await new Promise((r) => setTimeout(r, 50)); // the last long task's entry arrives after it ends
    entries.push(...observer.takeRecords());
    observer.disconnect();
    // Both measures count only what falls inside [t0, t1].
    let blockedMs = 0;
    for (const [a, b] of gaps) blockedMs += Math.max(0, Math.min(t1, b) - Math.max(t0, a));
    let longMs = 0, maxLong = 0, longTasks = 0;
    for (const e of entries) {
      const a = Math.max(t0, e.startTime), b = Math.min(t1, e.startTime + e.duration);
      if (b <= a) continue;
      longTasks++;
      longMs += b - a;
      maxLong = Math.max(maxLong, e.duration);
    }
    const thread = el.stats.thread ?? '?';
    el.remove();
    return { thread, frames, longTasks, longMs, maxLong, rafs, maxRafGap, blockedMs, windowMs: t1 - t0, intervals };
  }, { size: SIZE, windowMs: PROBE_MS, blockedGap: BLOCKED_GAP_MS, samples, workers });
}

const share = (ms: number, p: Probe) => `${((100 * ms) / p.windowMs).toFixed(1)} %`;

const median = (xs: number[]) => summary(xs).median;

async function responsiveness(page: Page): Promise<string[]> {
  const oneSample = await probe(page, 0);
  const withWorker = await probe(page);
  const bare = await page.context().newPage();
  // No Worker constructor: SoftwareHost settles for the main thread, as under CSP worker-src 'none'.
  await bare.addInitScript(() => { (window as unknown as { Worker: unknown }).Worker = undefined; });
  const mainThread = await probe(bare);
  await bare.close();
  expect(withWorker.thread).toBe('worker');
  expect(mainThread.thread).toBe('main');
  const row = (label: string, p: Probe) => `| ${label} | ${p.thread} | ${(p.windowMs / 1000).toFixed(1)} | ${p.frames} (${((1000 * p.frames) / p.windowMs).toFixed(1)}/s) | ` +
    `${p.longTasks} | ${p.longMs.toFixed(0)} | **${((100 * p.longMs) / p.windowMs).toFixed(1)} %** | ${p.maxLong.toFixed(0)} | ${((100 * p.blockedMs) / p.windowMs).toFixed(1)} % | ${p.rafs} | ${p.maxRafGap.toFixed(0)} |`;
  return [
    `## 4. Responsiveness: main-thread long tasks while the element draws continuously`, '',
    `\`<glass-plane-scene renderer="software">\` at ${SIZE.width}×${SIZE.height} CSS px (DPR 1), spin on and no \`time\` attribute, so it draws continuously (the next frame is asked for when the last is back). ` +
      `After its first frames, ${PROBE_MS / 1000} s of PerformanceObserver 'longtask' entries (tasks over 50 ms; their time inside the window summed) a setTimeout(1) chain (the time in gaps between its ticks over ${BLOCKED_GAP_MS} ms: the main thread held long enough to miss a 60 Hz frame, which catches frames under the long-task threshold too) and a requestAnimationFrame probe on the main thread. ` +
      'The second row makes `window.Worker` undefined (an init script), so the element draws on the main thread as where no worker may start. The bar ([worker](../docs/software-renderer.md#worker)): long tasks under 10 % of the time.', '',
    '| | thread | window, s | element frames | long tasks | long-task ms | long tasks\' share of the time | longest, ms | held > 16 ms (setTimeout probe) | rAF callbacks | longest rAF gap, ms |',
    '|---|---|---|---|---|---|---|---|---|---|---|',
    row('worker', withWorker),
    row('no Worker (main thread)', mainThread),
    '',
    `**Frame interval** (the bar: a new frame every ≤ 16 ms at ${SIZE.width}×${SIZE.height}, 1 sample per pixel, while the cube spins): the median time between the element's \`frame\` events in the window — ` +
      `samples 0 (1 spp), worker: **${median(oneSample.intervals).toFixed(1)} ms** (${oneSample.intervals.length} intervals; ${oneSample.thread}); samples 4 (the default), worker: ${median(withWorker.intervals).toFixed(1)} ms; ` +
      `samples 4 on the main thread: ${median(mainThread.intervals).toFixed(1)} ms. In a worker the next frame is asked for as the last one lands (while the scene moves); on the main thread it waits for requestAnimationFrame, so there no interval is shorter than one display frame.`,
    '',
    `With the worker the main thread only posts requests and puts the pixels on the canvas: ${share(withWorker.longMs, withWorker)} in long tasks, ` +
      `${share(withWorker.blockedMs, withWorker)} held over ${BLOCKED_GAP_MS} ms. Without it: ${share(mainThread.longMs, mainThread)} in long tasks and ${share(mainThread.blockedMs, mainThread)} held over ${BLOCKED_GAP_MS} ms` +
      (mainThread.longMs < 0.1 * mainThread.windowMs && mainThread.blockedMs > 0.5 * mainThread.windowMs
        ? ' — each frame drawn there is under the 50 ms that makes a long task, so the long-task criterion alone does not see the page held frame after frame.'
        : '.'),
    '',
  ];
}

/**
 * The frame split into bands across 1, 2 and all workers (SoftwareHost, one per core up
 * to 4): the element's frame interval and long tasks (probe), the host's round trip and its slowest
 * band's own time for the default scene and the 100k-triangle floor, WebGL beside them; the pixels
 * of every count are the same bytes (asserted), so one PSNR per scene.
 */
async function workerRows(page: Page): Promise<string[]> {
  await page.goto('/bench/software.html'); // section 4's probes left it
  await page.waitForFunction(() => 'softwareBench' in window);
  const b = api(page), all = await b.call('defaultWorkers');
  const counts = [...new Set([1, 2, all])];
  const label = (n: number) => `${n}${n === all ? ' (all: one per core, up to 4)' : ''}`;
  type Kind = { key: string; label: string; scene: number | null; samples: FrameState['samples'] };
  const kinds: Kind[] = [
    { key: 'default 0', label: 'default scene, samples 0', scene: null, samples: 0 },
    { key: 'default 4', label: 'default scene, samples 4', scene: null, samples: 4 },
    { key: 'floor 4', label: `${BENCH_SCENES[GAUSS_100K].name}, samples 4`, scene: GAUSS_100K, samples: 4 },
  ];
  const rt = new Map<string, number[]>(), own = new Map<string, number[]>(), gl = new Map<string, number[]>();
  const push = (m: Map<string, number[]>, k: string, xs: number[]) => m.set(k, [...(m.get(k) ?? []), ...xs]);
  const frames = (k: Kind) => (k.scene === null ? FRAMES : Math.max(2, FRAMES / 2));
  for (let rep = 0; rep < REPETITIONS; rep++) {
    for (const [n, k] of shuffled(counts.flatMap((n) => kinds.map((k) => [n, k] as const)), 41 + rep)) {
      const r = await b.call('hostFramesTimed', SIZE, 1, frames(k), WARMUP, 'srgb', k.samples, n, k.scene);
      push(rt, `${n} ${k.key}`, r.map((x) => x.roundTrip));
      push(own, `${n} ${k.key}`, r.map((x) => x.render));
    }
    for (const k of kinds) push(gl, k.key, await b.call('glFrames', SIZE, frames(k), WARMUP, null, 'srgb', k.scene));
  }
  const psnr = new Map<string, string>(), glPsnr = new Map<string, string>();
  for (const k of kinds) {
    const view = k.scene === null ? DEFAULT_VIEW : BENCH_SCENES[k.scene].view;
    const scene = k.scene === null ? defaultScene(DEFAULT_CUBE_DISTANCE, 0.8) : BENCH_SCENES[k.scene].scene;
    const ref = renderScene(scene, state(SIZE, view, PIXEL_TIME, 'srgb', k.samples), null, { samplesPerAxis: REF_SPP });
    const pixels = await Promise.all(counts.map((n) => b.call('hostPixels', SIZE, 1, PIXEL_TIME, 'srgb', k.samples, n, k.scene)));
    for (const p of pixels) expect(p, `${k.label}: every worker count draws the same bytes`).toBe(pixels[0]);
    psnr.set(k.key, regionCells(compareImages(ref, bytes(pixels[0]))));
    if (k.samples === 4) glPsnr.set(k.key, regionCells(compareImages(ref, bytes(await b.call('glPixels', SIZE, PIXEL_TIME, null, 'srgb', k.scene)))));
  }
  // Each count's probes alternate with the others' (2 rounds, shuffled), so a load that comes
  // and goes on a shared machine falls on every count alike; their intervals are pooled.
  const probes = new Map<string, Probe>();
  for (let round = 0; round < PROBE_ROUNDS; round++) {
    for (const [n, samples] of shuffled(counts.flatMap((n) => [[n, 0], [n, 4]] as const), 53 + round)) {
      const p = await probe(page, samples, n), k = `${n} ${samples}`, q = probes.get(k);
      probes.set(k, q ? { ...q, longMs: q.longMs + p.longMs, windowMs: q.windowMs + p.windowMs, intervals: [...q.intervals, ...p.intervals] } : p);
    }
  }
  const interval = (n: number, k: Kind) => {
    const p = probes.get(`${n} ${k.samples}`);
    if (k.scene !== null || !p) return '—';
    const m = median(p.intervals);
    return `${k.samples === 0 ? `**${m.toFixed(1)}**` : m.toFixed(1)} (${p.intervals.length}); long tasks ${share(p.longMs, p)}`;
  };
  return [
    `## 6. The frame split across workers, ${SIZE.width}×${SIZE.height}`, '',
    'SoftwareHost cuts each frame into bands of rows, one per worker, each drawn as in the whole frame (the bytes of every worker count below are the same: asserted), ' +
      'its rows weighted by each worker\'s speed in the frames before; rough glass and the `passes` view go whole to one worker. ' +
      `This machine reports ${all} cores (navigator.hardwareConcurrency), so "all" is ${all} workers. ` +
      `**Frame interval**: the median time between the element\'s \`frame\` events while the cube spins (section 4\'s probe, ${PROBE_ROUNDS} × ${PROBE_MS / 1000} s, each count\'s windows alternating with the others\'; the number of intervals in brackets) and the long tasks\' share of that time; ` +
      `**round trip**: SoftwareHost.render() posted → whole frame back on the main thread, one frame in flight, the clock moving (${REPETITIONS} repetitions × ${FRAMES} frames, ${Math.max(2, FRAMES / 2)} for the floor, after ${WARMUP} warm-up, shuffled); ` +
      '**slowest band**: that frame\'s slowest worker\'s own time (render and copy of its rows). ' +
      `PSNR against the float64 reference (${REF_SPP}×${REF_SPP} spp) at t = ${PIXEL_TIME} s, srgb, dB ${REGIONS.join(' / ')}. WebGL (SwiftShader, MSAA 4, the same page) beside each scene.`, '',
    '| scene | workers | element frame interval, ms median (intervals); long tasks | round trip, ms/frame median [IQR] | slowest band, ms median [IQR] | PSNR dB |',
    '|---|---|---|---|---|---|',
    ...kinds.flatMap((k) => [
      ...counts.map((n) => `| ${k.label} | ${label(n)} | ${interval(n, k)} | ${med(rt.get(`${n} ${k.key}`)!)} | ${med(own.get(`${n} ${k.key}`)!)} | ${psnr.get(k.key)} |`),
      `| ${k.label} | WebGL | — | ${med(gl.get(k.key)!)} | — | ${glPsnr.get(k.key) ?? '(MSAA 4 only)'} |`,
    ]),
    '',
  ];
}

test('bench: software renderer', async ({ page }) => {
  test.setTimeout(40 * 60_000);
  const loadBefore = loadavg()[0];
  await page.goto('/bench/software.html');
  await page.waitForFunction(() => 'softwareBench' in window);
  const sections = [
    ...(await defaultSceneRows(page)),
    ...(await split(page)),
    ...(await bezier(page)),
    ...(await responsiveness(page)),
    ...views(),
    ...(await workerRows(page)),
  ];
  const md = [
    '# Bench: the software renderer', '',
    `Headless Chromium (the pinned SwiftShader build of the test suite) for the browser rows, Node ${process.version} for the software renderer's own time in section 1, the Bézier evaluation and its software images. ` +
      '2 cores; the load averages say whether anything else ran (above 1, other work shared the machine and the times are pessimistic); IQRs show the spread. ' +
      `1-minute load average ${loadBefore.toFixed(1)} when this run started, ${loadavg()[0].toFixed(1)} when it ended. ` +
      'Speed is measured here, never asserted in a test.', '',
    ...sections,
  ].join('\n');
  console.log('\n' + md);
  if (!SMOKE) writeFileSync(new URL('./software.md', import.meta.url), md);
});
