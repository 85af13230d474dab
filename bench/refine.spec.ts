// `npm run bench`, refinement at rest (docs/refinement.md, issue 35): what a still view buys and costs, frame by frame. In
// the bench's seven views at 640×360 against bench.spec.ts's float64 reference: WebGL's PSNR after every frame of a still
// view of 82 frames and of 10, and the cumulative time to get there; the time to a PSNR; the moving frame (samples 0, what
// the element draws while moving with refine > 0) beside refine 0 (samples 4) and the three.js peer, in one shuffled
// round-robin with the still views; the software renderer's still views in Node; rough glass at rest against
// bench/rough.spec.ts's reference. Writes bench/refine.md and bench/refine.svg, prints the summary; asserts no timings.
// BENCH_SMOKE=1 runs it tiny (one view, a few frames) so the pipeline cannot rot.
import { writeFileSync } from 'node:fs';
import { loadavg } from 'node:os';
import { test, expect } from '../tests/e2e/fixtures';
import { compareImages, type PerRegion, type ReferenceImage } from '../src/reference';
import { SoftwareRenderer } from '../src/software';
import type { FrameState } from '../src/frame/types';
import { BASELINE, DEFAULTS, type Knobs } from './configs';
import { VIEWS, type BenchView } from './views';
import { frameState, stillState, type Scene } from './bench-state';
import { cachedReference } from './reference-cache';
import { roughReference, roughState, ROUGH_MICROFACETS, ROUGH_REF_SPP, ROUGH_SIZE } from './rough-reference';
import { ROUGH_FLOOR_VIEW, roughFloorScene } from './rough-scene';
import { shuffled, summary } from './stats';
import { resample } from './resample';
import { refinementGrid } from '../src/frame/refinement';
import { formatRefine, meanAt, meanMs, type Moving, type RoughCase, type Still, type ViewStill } from './refine-report';
import { refinePlot } from './refine-plot';
import type { BenchApi } from './bench-page';

const SMOKE = process.env.BENCH_SMOKE === '1';
const SCENE: Scene = SMOKE ? { width: 160, height: 90, time: 1.25 } : { width: 640, height: 360, time: 1.25 };
/** bench.spec.ts's reference (same size, time, views and spp), so the cache serves both. */
const REFERENCE_SPP_AXIS = SMOKE ? 1 : 8;
/** The still views: N = 82 ends as the 9 × 9 supersampled picture, N = 10 as the 3 × 3 one (refinementGrid). */
const LONG = SMOKE ? 3 : 82;
const SHORT = SMOKE ? 2 : 10;
const STOPS = [1, 2, 4, 10, 28, 82];
/** Timed runs of each still view per view; moving frames before each. */
const RUNS = SMOKE ? 1 : 3;
const WARMUP = SMOKE ? 0 : 2;
const MOVING_REPS = SMOKE ? 1 : 5;
const MOVING_FRAMES = SMOKE ? 2 : 8;
const ROUGH: [number, number][] = SMOKE ? [[0.3, 10]] : [[0.1, 10], [0.3, 10], [0.6, 10]];
const THRESHOLDS = [50, 54];

type Page = import('@playwright/test').Page;
type Bench = { bench: BenchApi };

/** What the still views and the moving rows draw: ours at the element's defaults, the peer as bench.spec.ts draws it. */
const STILL_KNOBS: Knobs = DEFAULTS;
const MOVING = [
  { key: 'moving', label: 'ours moving, refine > 0 (samples 0)', kind: 'ours' as const, knobs: { ...DEFAULTS, samples: 0 } as Knobs },
  { key: 'default', label: 'ours, refine 0 (samples 4)', kind: 'ours' as const, knobs: DEFAULTS },
  { key: 'three', label: 'three.js (Reflector, MSAA 4, 128 segments)', kind: 'three' as const, knobs: BASELINE },
  { key: 'three0', label: 'three.js, samples 0', kind: 'three' as const, knobs: { ...BASELINE, samples: 0 } as Knobs },
];

const decode = (b64: string) => new Uint8ClampedArray(Buffer.from(b64, 'base64'));

/**
 * A still view drawn in the page frame by frame, in order: its cumulative ms (each frame waited for, the reads not timed) and
 * the PSNR after each frame `read` says to read (null for the others).
 */
async function stillView(page: Page, view: BenchView, frames: number, ref: ReferenceImage, read: (k: number) => boolean, rough: FrameState | null = null): Promise<{ ms: number[]; psnr: (PerRegion | null)[] }> {
  const ms: number[] = [], psnr: (PerRegion | null)[] = [];
  for (let k = 1; k <= frames; k++) {
    const f = await page.evaluate(([scene, knobs, view, k, frames, read, warmup, rough]) =>
      (window as unknown as Bench).bench.stillFrame(scene, knobs, view, k, frames, read, warmup, rough), [SCENE, STILL_KNOBS, view, k, frames, read(k), WARMUP, rough] as const);
    ms.push((ms[k - 2] ?? 0) + f.ms);
    psnr.push(f.picture === null ? null : compareImages(ref, decode(f.picture)).psnr);
  }
  return { ms, psnr };
}

/** Median per frame of runs of cumulative ms. */
const medianRuns = (runs: number[][]) => runs[0].map((_, k) => summary(runs.map((r) => r[k])).median);

/**
 * The software renderer's still view in Node: cumulative ms (render() alone) and PSNR after the frames `read` says; of the
 * default scene in a bench view, or of the rough floor in its state `rough`.
 */
function softwareStill(view: BenchView, frames: number, ref: ReferenceImage, read: (k: number) => boolean, rough: FrameState | null = null): ViewStill {
  const r = new SoftwareRenderer(), s = rough ?? frameState(SCENE, STILL_KNOBS, view), scene = rough ? roughFloorScene() : null;
  for (let i = 0; i < WARMUP; i++) r.render(scene, stillState(s, 0, frames));
  const ms: number[] = [], psnr: (PerRegion | null)[] = [];
  let total = 0;
  for (let k = 1; k <= frames; k++) {
    const t0 = performance.now();
    const px = r.render(scene, stillState(s, k, frames));
    total += performance.now() - t0;
    ms.push(total);
    psnr.push(read(k) ? compareImages(ref, px).psnr : null);
  }
  return { view: view.name, ms, psnr };
}

test('refinement at rest', async ({ page }) => {
  test.setTimeout(SMOKE ? 5 * 60_000 : 40 * 60_000);
  const started = performance.now(), loadBefore = loadavg()[0];
  await page.goto('/bench/page.html');
  await page.waitForFunction(() => 'bench' in window);
  const info = await page.evaluate(() => (window as unknown as Bench).bench.info());
  const views: BenchView[] = SMOKE ? [VIEWS[0]] : [...VIEWS];
  const refs = new Map(views.map((v) => [v.name, cachedReference({ ...SCENE, view: v, colorSpace: 'srgb', samplesPerAxis: REFERENCE_SPP_AXIS })]));
  const rough = ROUGH.map(([roughness, ior]) => ({ roughness, ior, state: roughState(roughness, ior), ...roughReference(roughness, ior) }));

  const log = (what: string) => console.log(`${((performance.now() - started) / 60_000).toFixed(1)} min: ${what}`);

  // Pictures first (every frame of both still views: the curve and the time to a PSNR); they also compile and allocate
  // whatever the timed runs then find ready.
  const pictures = new Map<string, (PerRegion | null)[]>();
  for (const v of views) {
    for (const frames of [LONG, SHORT]) pictures.set(`${v.name}|${frames}`, (await stillView(page, v, frames, refs.get(v.name)!, () => true)).psnr);
  }
  log('still views read');
  // Rough glass: one run, its pictures read at a few frames. A frame of rough glass costs this rasterizer ~1.3 s at
  // 320×180 (bench/rough.md): runs enough for a median would take the bench's quarter hour alone.
  const roughViews = new Map<string, { ms: number[]; psnr: (PerRegion | null)[] }>();
  for (const c of rough) {
    for (const frames of [LONG, SHORT]) {
      const read = (k: number) => k === 1 || k === 10 || k === frames;
      roughViews.set(`${c.roughness}|${frames}`, await stillView(page, ROUGH_FLOOR_VIEW, frames, c.ref, read, c.state));
    }
  }
  log('rough still views drawn');
  const movingPsnr = new Map<string, PerRegion>();
  for (const m of MOVING) {
    for (const v of views) {
      const px = await page.evaluate(([kind, scene, knobs, view]) => (window as unknown as Bench).bench.pixels(kind, scene, knobs, view), [m.kind, SCENE, m.knobs, v] as const);
      movingPsnr.set(`${m.key}|${v.name}`, compareImages(refs.get(v.name)!, decode(px.data)).psnr);
    }
  }

  // What the short view should end as (docs/refinement.md#averaging): the 3 × 3 supersampled picture — WebGL's own, drawn at
  // pixel-ratio 3 and brought back in linear light, and the software renderer's.
  const side = refinementGrid(SHORT);
  const supersampled = { side, webgl: [] as PerRegion[], software: [] as PerRegion[] };
  for (const v of views) {
    const px = await page.evaluate(([scene, knobs, view]) => (window as unknown as Bench).bench.pixels('ours', scene, knobs, view),
      [SCENE, { ...STILL_KNOBS, samples: 0, pixelRatio: side } as Knobs, v] as const);
    supersampled.webgl.push(compareImages(refs.get(v.name)!, resample(Buffer.from(px.data, 'base64'), px.width, px.height, SCENE.width, SCENE.height, 'srgb')).psnr);
    const s = { ...frameState(SCENE, STILL_KNOBS, v), samples: 0 };
    supersampled.software.push(compareImages(refs.get(v.name)!, new SoftwareRenderer({ samplesPerAxis: side }).render(null, s)).psnr);
  }
  log('supersampled pictures');

  // Timing: the still views and the moving rows in one shuffled round-robin, so drift spreads evenly.
  type Job = { still: { view: BenchView; frames: number } } | { moving: (typeof MOVING)[number]; view: BenchView };
  const jobs: Job[] = views.flatMap((view) => [LONG, SHORT].map((frames) => ({ still: { view, frames } })));
  const movingJobs: Job[] = MOVING.flatMap((moving) => views.map((view) => ({ moving, view })));
  const stillRuns = new Map<string, number[][]>(), movingMs = new Map<string, number[]>();
  for (let rep = 0; rep < Math.max(RUNS, MOVING_REPS); rep++) {
    for (const job of shuffled([...(rep < RUNS ? jobs : []), ...(rep < MOVING_REPS ? movingJobs : [])], 35 + rep)) {
      if ('still' in job) {
        const { view, frames } = job.still;
        const ms = await page.evaluate(([scene, knobs, view, frames, warmup]) =>
          (window as unknown as Bench).bench.stillTimes(scene, knobs, view, frames, warmup), [SCENE, STILL_KNOBS, view, frames, WARMUP] as const);
        const key = `${view.name}|${frames}`;
        stillRuns.set(key, [...(stillRuns.get(key) ?? []), ms]);
      } else {
        const { moving: m, view } = job;
        const ms = await page.evaluate(([kind, scene, knobs, view, frames, warmup]) =>
          (window as unknown as Bench).bench.time(kind, scene, knobs, view, frames, warmup), [m.kind, SCENE, m.knobs, view, MOVING_FRAMES, WARMUP] as const);
        const key = `${m.key}|${view.name}`;
        movingMs.set(key, [...(movingMs.get(key) ?? []), ms]);
      }
    }
  }
  log('timed');

  const still = (frames: number): Still => ({
    frames, perView: views.map((v) => ({ view: v.name, ms: medianRuns(stillRuns.get(`${v.name}|${frames}`)!), psnr: pictures.get(`${v.name}|${frames}`)! })),
  });
  const long = still(LONG), short = still(SHORT);
  const moving: Moving[] = MOVING.map((m) => ({
    label: m.label,
    perView: views.map((v) => {
      const t = summary(movingMs.get(`${m.key}|${v.name}`)!);
      return { view: v.name, ms: t.median, iqr: t.iqr, psnr: movingPsnr.get(`${m.key}|${v.name}`)! };
    }),
  }));
  const roughCases: RoughCase[] = rough.map((c) => {
    const one = (frames: number): Still => ({ frames, perView: [{ view: ROUGH_FLOOR_VIEW.name, ...roughViews.get(`${c.roughness}|${frames}`)! }] });
    // The software renderer's after the page's work, as below.
    const sw = (frames: number): Still => ({ frames, perView: [softwareStill(ROUGH_FLOOR_VIEW, frames, c.ref, (k) => k === 1 || k === 10 || k === frames, c.state)] });
    return { roughness: c.roughness, ior: c.ior, long: one(LONG), short: one(SHORT), software: { long: sw(LONG), short: sw(SHORT) }, referenceMs: c.cached ? null : c.ms };
  });

  // The software renderer in Node, after the page's work (it would take a core from the page's timings).
  const read = (frames: number) => (k: number) => STOPS.includes(k) || k === frames;
  const software = {
    long: { frames: LONG, perView: views.map((v) => softwareStill(v, LONG, refs.get(v.name)!, read(LONG))) },
    short: { frames: SHORT, perView: views.map((v) => softwareStill(v, SHORT, refs.get(v.name)!, read(SHORT))) },
    moving: {
      label: 'software moving, refine > 0 (samples 0)',
      perView: views.map((v) => {
        const r = new SoftwareRenderer(), s = stillState(frameState(SCENE, STILL_KNOBS, v), 0, LONG);
        const px = r.render(null, s).slice(), ms: number[] = [];
        for (let i = 0; i < 5; i++) {
          const t0 = performance.now();
          r.render(null, s);
          ms.push(performance.now() - t0);
        }
        const t = summary(ms);
        return { view: v.name, ms: t.median, iqr: t.iqr, psnr: compareImages(refs.get(v.name)!, px).psnr };
      }),
    },
  };
  log('software renderer');

  const input = {
    date: new Date().toISOString().slice(0, 10), renderer: info.renderer, node: process.version, size: SCENE, referenceSpp: REFERENCE_SPP_AXIS ** 2,
    views: views.map((v) => v.name), runs: RUNS, warmup: WARMUP, stops: STOPS, long, short, moving, ours: MOVING[0].label, three: MOVING[2].label,
    movingReps: MOVING_REPS, movingFrames: MOVING_FRAMES, software, supersampled, rough: { size: ROUGH_SIZE, spp: ROUGH_REF_SPP, microfacets: ROUGH_MICROFACETS, cases: roughCases },
    thresholds: THRESHOLDS, load: [loadBefore, loadavg()[0]] as [number, number], minutes: (performance.now() - started) / 60_000,
  };
  const markdown = formatRefine(input);
  const curve = (s: Still, label: string, dashed = false) => ({
    label, dashed, marks: STOPS.filter((k) => k <= s.frames && (dashed ? k === s.frames : true)),
    points: Array.from({ length: s.frames }, (_, i) => ({ ms: meanMs(s, i + 1), db: meanAt(s, i + 1, 'all') })),
  });
  const point = (m: Moving, label: string, shape: 'circle' | 'square' | 'diamond' | 'triangle') => ({
    label, shape, ms: m.perView.reduce((a, v) => a + v.ms, 0) / m.perView.length, db: m.perView.reduce((a, v) => a + Math.min(99, v.psnr.all), 0) / m.perView.length,
  });
  const svg = refinePlot(`Refinement at rest, WebGL, ${SCENE.width}×${SCENE.height}, ${views.length} views`,
    [curve(long, `still view, N = ${LONG}`), curve(short, `still view, N = ${SHORT}`, true)],
    [point(moving[0], 'ours moving (samples 0)', 'circle'), point(moving[1], 'ours, samples 4', 'square'),
      point(moving[2], 'three.js, MSAA 4', 'diamond'), point(moving[3], 'three.js, samples 0', 'triangle')],
    THRESHOLDS);
  const summaryLines = markdown.slice(markdown.indexOf('## Summary'), markdown.indexOf('## WebGL: a still view')).trim();
  console.log(`\n${summaryLines}\n\nspec: ${input.minutes.toFixed(1)} min, load ${input.load.map((l) => l.toFixed(2)).join(' → ')}`);
  if (!SMOKE) {
    writeFileSync(new URL('./refine.md', import.meta.url), markdown);
    writeFileSync(new URL('./refine.svg', import.meta.url), svg);
  } else console.log(markdown);

  // The smoke run proves the pipeline end to end: every frame timed, every picture read scored, the plot drawn.
  for (const s of [long, short, software.long, software.short, ...roughCases.flatMap((c) => [c.long, c.short, c.software.long, c.software.short])]) {
    for (const v of s.perView) {
      for (const ms of v.ms) expect(Number.isFinite(ms), `${v.view} ms`).toBe(true);
      expect(Number.isFinite(v.psnr[s.frames - 1]!.all), `${v.view} PSNR after frame ${s.frames} of ${s.frames}`).toBe(true);
    }
  }
  for (const m of [...moving, software.moving]) for (const v of m.perView) expect(Number.isFinite(v.ms) && Number.isFinite(v.psnr.all), `${m.label} ${v.view}`).toBe(true);
  expect(svg).toContain('</svg>');
});
