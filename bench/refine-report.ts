// Turns bench/refine.spec.ts's measurements of refinement at rest (docs/refinement.md) into bench/refine.md: a still view's
// PSNR and cumulative time by frame, the time to a PSNR, the moving frame beside three.js, the software renderer and rough glass.
import { cpus } from 'node:os';
import type { PerRegion } from '../src/reference';
import { refinementGrid } from '../src/frame/refinement';
import { meanRegion } from './report';

/** One view's still view of `frames` frames: index k − 1 holds frame k's cumulative ms and the PSNR of the picture after it. */
export interface ViewStill {
  view: string;
  ms: number[];
  /** null: that frame's picture was not read. */
  psnr: (PerRegion | null)[];
}

export interface Still {
  frames: number;
  perView: ViewStill[];
}

/** A moving frame (one configuration, drawn again and again): ms per frame and PSNR, per view. */
export interface Moving {
  label: string;
  perView: { view: string; ms: number; iqr: number; psnr: PerRegion }[];
}

export interface RoughCase {
  roughness: number;
  ior: number;
  long: Still;
  short: Still;
  /** The same still views drawn by the software renderer in Node (render() alone timed). */
  software: { long: Still; short: Still };
  /** The reference's making, when it was made in this run (ms), else null. */
  referenceMs: number | null;
}

export interface RefineInput {
  date: string;
  renderer: string;
  node: string;
  size: { width: number; height: number; time: number };
  referenceSpp: number;
  views: string[];
  runs: number;
  warmup: number;
  stops: number[];
  /** WebGL, the long still view (N = 82) and the short one (N = 10). */
  long: Still;
  short: Still;
  moving: Moving[];
  /** Which of `moving` is ours while moving with refinement on, and which the peer the ratio is taken to. */
  ours: string;
  three: string;
  movingReps: number;
  movingFrames: number;
  software: { long: Still; short: Still; moving: Moving };
  /** Per view, the side × side supersampled picture the short view should end as: WebGL's at pixel-ratio side, and the software renderer's. */
  supersampled: { side: number; webgl: PerRegion[]; software: PerRegion[] };
  rough: { size: { width: number; height: number }; spp: number; microfacets: number; cases: RoughCase[] };
  thresholds: number[];
  /** The machine's 1-minute load average when the spec started and ended, and the spec's own minutes. */
  load: [number, number];
  minutes: number;
}

export const REGIONS = ['all', 'objects', 'glass', 'edges'] as const;

const mean = (xs: number[]) => xs.reduce((a, b) => a + b, 0) / xs.length;
const f = (x: number, d = 1) => (Number.isFinite(x) ? x.toFixed(d) : '—');
const ms = (x: number) => (Number.isFinite(x) ? (x >= 100 ? x.toFixed(0) : x.toFixed(1)) : '—');

/** Frame k of a still view, mean over views: cumulative ms and PSNR of `region` (NaN where no view read that frame). */
export const meanMs = (s: Still, k: number) => mean(s.perView.map((v) => v.ms[k - 1]));
export const meanAt = (s: Still, k: number, region: keyof PerRegion) => meanRegion(s.perView.map((v) => v.psnr[k - 1]), region);

/** The first frame whose mean PSNR (all) reaches `db`, with its mean cumulative ms; null if none does. */
export function firstReaching(s: Still, db: number): { k: number; ms: number } | null {
  for (let k = 1; k <= s.frames; k++) if (meanAt(s, k, 'all') >= db) return { k, ms: meanMs(s, k) };
  return null;
}

const cells = (p: PerRegion | null) => (p ? REGIONS.map((r) => f(p[r])).join(' / ') : '—');
const regionMeans = (psnrs: (PerRegion | null)[]) => REGIONS.map((r) => f(meanRegion(psnrs, r))).join(' | ');

/** The frames of `stops` a still view of `frames` has, and its last. */
const framesOf = (stops: number[], frames: number) => [...new Set([...stops.filter((k) => k <= frames), frames])];

/** The stops of the long view, then the short view's last frame. */
function columns(input: RefineInput): { label: string; still: Still; k: number }[] {
  return [
    ...framesOf(input.stops, input.long.frames).map((k) => ({ label: `${k} of ${input.long.frames}`, still: input.long, k })),
    { label: `${input.short.frames} of ${input.short.frames}`, still: input.short, k: input.short.frames },
  ];
}

function reached(s: Still, db: number): string {
  const r = firstReaching(s, db);
  if (r) return `frame ${r.k}, ${ms(r.ms)} ms`;
  let best = -Infinity;
  for (let k = 1; k <= s.frames; k++) best = Math.max(best, meanAt(s, k, 'all'));
  return `not reached (best ${f(best)} dB)`;
}

function movingRow(m: Moving): string {
  return `| ${m.label} | ${ms(mean(m.perView.map((v) => v.ms)))} [${ms(mean(m.perView.map((v) => v.iqr)))}] | ${regionMeans(m.perView.map((v) => v.psnr))} |`;
}

function stillTable(name: string, s: Still, stops: number[], short: Still | null): string[] {
  const rows = [...framesOf(stops, s.frames).map((k) => ({ s, k })), ...(short ? [{ s: short, k: short.frames }] : [])];
  return [
    `| ${name} frame | of N | ms | ${REGIONS.join(' | ')} |`, '|---|---|---|---|---|---|---|',
    ...rows.map(({ s, k }) => `| ${k} | ${s.frames} | ${ms(meanMs(s, k))} | ${regionMeans(s.perView.map((v) => v.psnr[k - 1]))} |`),
  ];
}

export function formatRefine(input: RefineInput): string {
  const { long, short, size, supersampled: ss } = input;
  const cols = columns(input);
  const ours = input.moving.find((m) => m.label === input.ours)!, three = input.moving.find((m) => m.label === input.three)!;
  const movingMs = (m: Moving) => mean(m.perView.map((v) => v.ms));
  const lines: string[] = [
    '# Refinement at rest, measured ([refinement](../docs/refinement.md))', '',
    `Written by \`npm run bench\` (bench/refine.spec.ts) on ${input.date}; WebGL: ${input.renderer}; software: Node ${input.node}.`,
    `${size.width}×${size.height}, time ${size.time} s, the ${input.views.length} views of bench/results.md (${input.views.join('; ')}), each scored against`,
    `bench.spec.ts's float64 reference (${input.referenceSpp} samples a pixel, cached); PSNR dB in the regions of compareImages, mean over the views`,
    'that have the region. A still view is drawn as the element draws it (bench/bench-state.ts stillState) at the element\'s defaults',
    '(reflection-scale 1, tessellation auto, color-space srgb): frame 1 the preview at samples 4, frames 2..N strata frames at samples 0,',
    'averaged in linear light; "after frame k" is the picture the element shows then. ms: from the still view\'s start to the end of',
    `frame k, each frame waited for by a 1-pixel readPixels, after ${input.warmup} moving frames (samples 0) of the same view; median of`,
    `${input.runs} runs per view, the runs and the moving rows in one shuffled round-robin; mean over views. The element draws one frame a`,
    'display refresh: at 60 Hz frame k is on screen no sooner than k × 16.7 ms after the view stopped moving, whatever the frames cost.',
    `Load average (1 min) ${input.load[0].toFixed(2)} at the start, ${input.load[1].toFixed(2)} at the end, on ${cpus().length} cores; the spec took ${input.minutes.toFixed(1)} min.`, '',
    '## Summary', '',
    ...input.thresholds.map((db) => `- ${db} dB (all, mean over views): N = ${long.frames}: ${reached(long, db)}; N = ${short.frames}: ${reached(short, db)}.`),
    `- After the last frame: N = ${long.frames} ${f(meanAt(long, long.frames, 'all'))} dB in ${ms(meanMs(long, long.frames))} ms; ` +
      `N = ${short.frames} ${f(meanAt(short, short.frames, 'all'))} dB in ${ms(meanMs(short, short.frames))} ms; the preview alone ${f(meanAt(long, 1, 'all'))} dB in ${ms(meanMs(long, 1))} ms.`,
    `- The moving frame: ${input.moving.map((m) => `${m.label} ${ms(movingMs(m))} ms at ${f(meanRegion(m.perView.map((v) => v.psnr), 'all'))} dB`).join('; ')}. ` +
      `Ours moving ÷ three.js (MSAA 4): ${(movingMs(ours) / movingMs(three)).toFixed(2)} of its time.`, '',
    '## WebGL: a still view, mean over views', '',
    'PSNR dB after frame k of a still view of N frames, and the ms it took to get there.', '',
    ...stillTable('WebGL', long, input.stops, short), '',
    `The short view should end as the ${ss.side} × ${ss.side} supersampled picture (N = ${long.frames} as the ${refinementGrid(long.frames)} × ${refinementGrid(long.frames)} one): here it is, drawn by each renderer`,
    `at ${ss.side} × ${ss.side} samples a pixel (WebGL: pixel-ratio ${ss.side}, samples 0, brought back to ${size.width}×${size.height} in linear light by`,
    `bench/resample.ts; the software renderer: samplesPerAxis ${ss.side}), beside what each still view of ${short.frames} frames ends as.`, '',
    `| picture | ${REGIONS.join(' | ')} |`, '|---|---|---|---|---|',
    `| WebGL, frame ${short.frames} of ${short.frames} | ${regionMeans(short.perView.map((v) => v.psnr[short.frames - 1]))} |`,
    `| WebGL, ${ss.side} × ${ss.side} supersampled | ${regionMeans(ss.webgl)} |`,
    `| software, frame ${input.software.short.frames} of ${input.software.short.frames} | ${regionMeans(input.software.short.perView.map((v) => v.psnr[input.software.short.frames - 1]))} |`,
    `| software, ${ss.side} × ${ss.side} supersampled | ${regionMeans(ss.software)} |`, '',
    ...shortfall(input), '## WebGL: the moving frame', '',
    `What the element draws while something moves: with refine > 0 one sample a pixel (samples 0), whatever \`samples\` says; the`,
    'element with refinement off (refine 0, samples 4) for comparison, and the three.js peer (bench/three-peer.ts) in the same run, as',
    `bench.spec.ts draws it. ms/frame: median [IQR] of ${input.movingReps} batches of ${input.movingFrames} frames per view, each batch closed by a`,
    `1-pixel readPixels, mean over views; PSNR dB ${REGIONS.join(' / ')}, mean over views.`, '',
    `| frame | ms/frame [IQR] | ${REGIONS.join(' | ')} |`, '|---|---|---|---|---|---|',
    ...input.moving.map(movingRow), '',
    ...input.moving.filter((m) => m !== three).map((m) => `${m.label} ÷ ${three.label}: ${(movingMs(m) / movingMs(three)).toFixed(2)} of its time.`), '',
    '## WebGL per view', '',
    `PSNR dB ${REGIONS.join(' / ')} after frame k of N.`, '',
    `| view | ${cols.map((c) => c.label).join(' | ')} | ${ss.side} × ${ss.side} supersampled |`, `|---|${cols.map(() => '---').join('|')}|---|`,
    ...input.views.map((v, i) => `| ${v} | ${cols.map((c) => cells(c.still.perView[i].psnr[c.k - 1])).join(' | ')} | ${cells(ss.webgl[i])} |`), '',
    'Cumulative ms at frame k of N.', '',
    `| view | ${cols.map((c) => c.label).join(' | ')} |`, `|---|${cols.map(() => '---').join('|')}|`,
    ...input.views.map((v, i) => `| ${v} | ${cols.map((c) => ms(c.still.perView[i].ms[c.k - 1])).join(' | ')} |`), '',
    '## The software renderer', '',
    `SoftwareRenderer.render() in Node (one thread, no worker: the element's SoftwareHost splits a frame into bands, one a worker),`,
    'the same views, frames and reference; ms: one run per view, cumulative, mean over views; the moving frame (samples 0, refine > 0):',
    'median of a few frames.', '',
    ...stillTable('software', input.software.long, input.stops, input.software.short), '',
    `| frame | ms/frame | ${REGIONS.join(' | ')} |`, '|---|---|---|---|---|---|',
    `| ${input.software.moving.label} | ${ms(movingMs(input.software.moving))} | ${regionMeans(input.software.moving.perView.map((v) => v.psnr))} |`, '',
    '## Rough glass at rest', '',
    `The floor of bench/rough-scene.ts at ${input.rough.size.width}×${input.rough.size.height}, roughness-quality medium, samples 4 for the preview, against`,
    `bench/rough.spec.ts's reference (${input.rough.spp}×${input.rough.spp} strata a pixel, ${input.rough.microfacets} microfacet normals each; cached):`,
    'PSNR dB on the glass after frame k of N, and the cumulative ms (one run, each frame waited for; reads not timed). WebGL in the',
    'page, then the software renderer in Node (one thread).', '',
    ...roughTable(input, 'WebGL', (c) => c), '',
    ...roughTable(input, 'software', (c) => c.software), '', ...input.rough.cases.filter((c) => c.referenceMs !== null).map((c) => `Reference of ${c.roughness} / ${c.ior} computed in this run in ${(c.referenceMs! / 1000).toFixed(0)} s.`),
    '', '## The plot', '',
    '![Mean PSNR (all) against cumulative ms, WebGL](refine.svg)', '',
    'bench/refine.svg, drawn by the spec: mean PSNR (all) over the views against the cumulative ms of a still view (every frame of',
    `N = ${long.frames} and of N = ${short.frames}), ms on a log scale, with the moving frames of ours and of three.js marked.`, '',
  ];
  return lines.join('\n');
}

/** The rough cases' glass after the frames of roughColumns, by one renderer's still views. */
function roughTable(input: RefineInput, renderer: string, views: (c: RoughCase) => { long: Still; short: Still }): string[] {
  const cols = roughColumns(input);
  return [
    `| ${renderer}: roughness / ior | ${cols.map((c) => c.label).join(' | ')} | ms at ${cols.map((c) => c.label).join(', ')} |`,
    `|---|${cols.map(() => '---').join('|')}|---|`,
    ...input.rough.cases.map((c) => {
      const at = cols.map((col) => ({ s: views(c)[col.which], k: col.k }));
      return `| ${c.roughness} / ${c.ior} | ${at.map(({ s, k }) => f(s.perView[0].psnr[k - 1]?.glass ?? NaN)).join(' | ')} | ${at.map(({ s, k }) => ms(s.perView[0].ms[k - 1])).join(', ')} |`;
    }),
  ];
}

function roughColumns(input: RefineInput): { label: string; which: 'long' | 'short'; k: number }[] {
  const c = input.rough.cases[0];
  return [
    ...[1, 10, c.long.frames].filter((k, i, a) => k <= c.long.frames && a.indexOf(k) === i).map((k) => ({ label: `${k} of ${c.long.frames}`, which: 'long' as const, k })),
    { label: `${c.short.frames} of ${c.short.frames}`, which: 'short' as const, k: c.short.frames },
  ];
}

/** Shortfalls smaller than this are not told. */
const SHORTFALL_DB = 1;

/** WebGL's short view ending short of its own supersampled picture: told, with where to look first. */
function shortfall(input: RefineInput): string[] {
  const { short, supersampled: ss } = input;
  const gap = meanRegion(ss.webgl, 'all') - meanAt(short, short.frames, 'all');
  if (!(gap > SHORTFALL_DB)) return [];
  return [
    `WebGL's still view of ${short.frames} frames ends ${f(gap)} dB (all) short of WebGL's own ${ss.side} × ${ss.side} picture. Where to`,
    'look first: something its strata frames still decide by the pixel rather than by the stratum, as the level-of-detail bias did',
    'before the textures were read by scaled derivatives (the far view\'s glass 41.0 dB after 10 frames, 53.0 with them;',
    '[footprints](../docs/refinement.md#footprints)).', '',
  ];
}
