// Turns bench measurements into the printed table, bench/results.md and bench/results.json.
import type { PerRegion } from '../src/reference';
import { PSNR_TOLERANCE_DB, type ParetoPoint } from './pareto';
import type { Knobs } from './configs';

export interface ViewResult {
  view: string;
  /** Median ms per frame, and the interquartile range over repetitions. */
  ms: number;
  iqr: number;
  /** GPU ms per frame from EXT_disjoint_timer_query_webgl2, when available. */
  gpuMs: number | null;
  error: { psnr: PerRegion; maxError: number } | null;
}

export interface Row {
  key: string;
  label: string;
  kind: 'ours' | 'scene-only' | 'clear-only' | 'three';
  knobs: Knobs;
  perView: ViewResult[];
  pareto?: boolean;
}

const mean = (xs: number[]) => xs.reduce((a, b) => a + b, 0) / xs.length;

/** Mean PSNR of one region over the views (views where the region is empty are skipped). */
export function meanPsnr(row: Row, region: keyof PerRegion): number {
  const xs = row.perView.map((v) => v.error?.psnr[region] ?? NaN).filter((x) => !Number.isNaN(x));
  // An identical region has infinite PSNR; cap it so one view cannot dominate the mean.
  return xs.length ? mean(xs.map((x) => Math.min(x, 99))) : NaN;
}

/** Mean over views of the timer-query GPU time, NaN when any view has none. */
export function meanGpu(row: Row): number {
  const xs = row.perView.map((v) => v.gpuMs ?? NaN);
  return xs.some(Number.isNaN) ? NaN : mean(xs);
}

/** A row as one point: mean over views of the median time, of the spread, and of PSNR (all). */
export function aggregate(row: Row): ParetoPoint {
  return { ms: mean(row.perView.map((v) => v.ms)), noise: mean(row.perView.map((v) => v.iqr)), psnr: meanPsnr(row, 'all') };
}

export interface ResultsInput {
  info: { renderer: string; timerQuery: boolean; maxSamples: number };
  scene: { width: number; height: number; time: number };
  referenceSpp: number;
  repetitions: number;
  frames: number;
  views: string[];
  rows: Row[];
  sizes: { ours: number | null; three: number | null };
  /** The defaults timed with and without SPEC §7's skips (culling, scissor, off-screen/edge-on glass). */
  savings: { view: string; on: number; off: number }[];
}

const f = (x: number, d = 2) => (Number.isFinite(x) ? x.toFixed(d) : '—');
const kb = (b: number | null) => (b === null ? 'not built' : `${(b / 1024).toFixed(1)} kB`);

export function formatResults(input: ResultsInput): { markdown: string; json: unknown } {
  const { rows } = input;
  const scored = rows.filter((r) => r.kind === "ours" || r.kind === "three");
  const lines: string[] = [];
  lines.push(`# Bench results`, '');
  lines.push(`${input.scene.width}×${input.scene.height}, time ${input.scene.time} s, ${input.views.length} views (${input.views.join('; ')}).`);
  lines.push(`${input.repetitions} repetitions × ${input.frames} frames per configuration and view, shuffled round-robin; each batch closed by a 1-pixel readback (ms/frame, wall clock: what a page pays, CPU submission included).`);
  lines.push(`GPU ms: median of ${input.frames} EXT_disjoint_timer_query_webgl2 intervals per view (${input.info.timerQuery ? 'available here' : 'not available here'}); on SwiftShader the "GPU" is the CPU rasterizer. The Pareto front uses the wall clock.`);
  lines.push(`Error against the float64 reference at ${input.referenceSpp} samples per pixel (exact Fresnel). GPU: ${input.info.renderer}.`, '');
  lines.push('| config | ms/frame median [IQR] | GPU ms (timer query) | PSNR dB all / glass / objects / edges | max err | Pareto |');
  lines.push('|---|---|---|---|---|---|');
  for (const r of scored) {
    const a = aggregate(r);
    const maxErr = Math.max(...r.perView.map((v) => v.error!.maxError));
    const psnr = (['all', 'glass', 'objects', 'edges'] as const).map((g) => f(meanPsnr(r, g), 1)).join(' / ');
    lines.push(`| ${r.label} | ${f(a.ms)} [${f(a.noise)}] | ${f(meanGpu(r))} | ${psnr} | ${f(maxErr, 0)} | ${r.pareto ? '✓' : ''} |`);
  }
  const byKey = new Map(rows.map((r) => [r.key, r]));
  const base = byKey.get('baseline');
  const sceneOnly = byKey.get('scene only');
  const clear = byKey.get('clear only');
  const three = byKey.get('three.js');
  lines.push('');
  if (base && sceneOnly && clear) {
    const b = aggregate(base).ms, s = aggregate(sceneOnly).ms, c = aggregate(clear).ms;
    lines.push(`Baselines: clear-only ${f(c)} ms, scene-only ${f(s)} ms, full frame ${f(b)} ms; the reflection and glass cost ${f(b / s)}× the scene pass alone.`);
  }
  if (three) {
    const t = aggregate(three);
    const ours = scored.filter((r) => r.kind === 'ours').map((r) => ({ r, a: aggregate(r) }));
    const matched = ours.filter((o) => o.a.psnr >= t.psnr - PSNR_TOLERANCE_DB).sort((x, y) => x.a.ms - y.a.ms)[0];
    lines.push(matched
      ? `three.js: ${f(t.ms)} ms at ${f(t.psnr, 1)} dB. Our fastest configuration at equal or better accuracy, "${matched.r.label}": ${f(matched.a.ms)} ms at ${f(matched.a.psnr, 1)} dB, ${f(matched.a.ms / t.ms)}× its time.`
      : `three.js: ${f(t.ms)} ms at ${f(t.psnr, 1)} dB; no configuration of ours is as accurate.`);
  }
  lines.push(`Size, min+gzip: ours (standalone, gl-matrix included) ${kb(input.sizes.ours)}; three.js peer (three + Reflector + scene) ${kb(input.sizes.three)}.`, '');
  if (input.savings.length) {
    lines.push('## What the skips save (defaults, SPEC §7)', '');
    lines.push('Culling objects beyond the glass from the reflection, scissoring it to the glass, and skipping reflection and glass when the glass is off screen or edge-on; the same frames timed with all of it off.', '');
    lines.push('| view | with skips, ms | without, ms | saved |');
    lines.push('|---|---|---|---|');
    for (const v of input.savings) lines.push(`| ${v.view} | ${f(v.on)} | ${f(v.off)} | ${f(100 * (1 - v.on / v.off), 0)}% |`);
    lines.push('');
  }
  lines.push('## Per view: ms/frame median, PSNR dB (all)', '');
  lines.push(`| config | ${input.views.join(' | ')} |`);
  lines.push(`|---|${input.views.map(() => '---').join('|')}|`);
  for (const r of rows) {
    lines.push(`| ${r.label} | ${r.perView.map((v) => `${f(v.ms)}${v.error ? ` · ${f(v.error.psnr.all, 1)}` : ''}`).join(' | ')} |`);
  }
  const json = {
    ...input,
    rows: rows.map((r) => ({ ...r, aggregate: aggregate(r) })),
  };
  return { markdown: lines.join('\n') + '\n', json };
}
