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
  return meanRegion(row.perView.map((v) => v.error?.psnr), region);
}

/** Mean PSNR of one region over `psnrs`, one a view (absent, or an empty region's NaN, skipped). */
export function meanRegion(psnrs: readonly (PerRegion | null | undefined)[], region: keyof PerRegion): number {
  const xs = psnrs.map((p) => p?.[region] ?? NaN).filter((x) => !Number.isNaN(x));
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
  /** The defaults timed with and without the skips of docs/knobs.md#reflection-skips (culling, scissor, off-screen/edge-on glass). */
  savings: { view: string; on: number; off: number }[];
  /** srgb rows drawn at pixel-ratio ≠ 1, scored again after a downscale in linear light (resample 'srgb'). */
  linearResampled?: Row[];
}

/** The regions every PSNR column reports, in this order (the dark region, docs/colour.md#eight-bit-targets, last). */
export const PSNR_REGIONS = ['all', 'glass', 'objects', 'edges', 'dark'] as const;

/** The bars for color-space srgb (docs/knobs.md#bars-the-tests-hold) on every bench view: overall, and in the dark region. */
export const BAR_ALL_DB = 45;
export const BAR_DARK_DB = 40;

const f = (x: number, d = 2) => (Number.isFinite(x) ? x.toFixed(d) : '—');
const psnrCell = (p: PerRegion) => PSNR_REGIONS.map((g) => f(p[g], 1)).join(' / ');

/** Our fastest row at least as accurate as `peer` (within the PSNR tolerance), in the peer's colour space. */
function peerLine(rows: Row[], peer: Row | undefined, space: string): string | null {
  if (!peer) return null;
  const t = aggregate(peer);
  const ours = rows.filter((r) => r.kind === 'ours' && r.knobs.colorSpace === peer.knobs.colorSpace).map((r) => ({ r, a: aggregate(r) }));
  const matched = ours.filter((o) => o.a.psnr >= t.psnr - PSNR_TOLERANCE_DB).sort((x, y) => x.a.ms - y.a.ms)[0];
  return matched
    ? `${space}: three.js ${f(t.ms)} ms at ${f(t.psnr, 1)} dB. Our fastest configuration at equal or better accuracy, "${matched.r.label}": ${f(matched.a.ms)} ms at ${f(matched.a.psnr, 1)} dB, ${f(matched.a.ms / t.ms)}× its time.`
    : `${space}: three.js ${f(t.ms)} ms at ${f(t.psnr, 1)} dB; no configuration of ours in that colour space is as accurate.`;
}
const kb = (b: number | null) => (b === null ? 'not built' : `${(b / 1024).toFixed(1)} kB`);

export function formatResults(input: ResultsInput): { markdown: string; json: unknown } {
  const { rows } = input;
  const scored = rows.filter((r) => r.kind === "ours" || r.kind === "three");
  const lines: string[] = [];
  lines.push(`# Bench results`, '');
  lines.push(`${input.scene.width}×${input.scene.height}, time ${input.scene.time} s, ${input.views.length} views (${input.views.join('; ')}).`);
  lines.push(`${input.repetitions} repetitions × ${input.frames} frames per configuration and view, shuffled round-robin; each batch closed by a 1-pixel readback (ms/frame, wall clock: what a page pays, CPU submission included).`);
  lines.push(`GPU ms: median of ${input.frames} EXT_disjoint_timer_query_webgl2 intervals per view (${input.info.timerQuery ? 'available here' : 'not available here'}); on SwiftShader the "GPU" is the CPU rasterizer. The Pareto front uses the wall clock.`);
  lines.push(`Error against the float64 reference at ${input.referenceSpp} samples per pixel (exact Fresnel) in the row's own colour space ([colour](../docs/colour.md#srgb)): ` +
    'every row is drawn in linear light with sRGB output (color-space srgb, the element\'s default) and scored against the srgb reference, but those named "color-space none", ' +
    'drawn with values as stored (every row before color-space existed) and scored against the none reference. ' +
    `PSNR regions: all, glass, objects, edges, and dark (pixels whose reference, as displayed, is below 32/255 in every channel; they count in their own region too). Each is the mean over the views that have the region. GPU: ${input.info.renderer}.`);
  lines.push('The Pareto front is taken over the srgb rows only (three.js included): a none row is scored against another reference, so its PSNR is not comparable with theirs and it is on no front ("n/a").', '');
  lines.push(`| config | ms/frame median [IQR] | GPU ms (timer query) | PSNR dB ${PSNR_REGIONS.join(' / ')} | max err | Pareto (srgb) |`);
  lines.push('|---|---|---|---|---|---|');
  for (const r of scored) {
    const a = aggregate(r);
    const maxErr = Math.max(...r.perView.map((v) => v.error!.maxError));
    const psnr = PSNR_REGIONS.map((g) => f(meanPsnr(r, g), 1)).join(' / ');
    const pareto = r.knobs.colorSpace === 'srgb' ? (r.pareto ? '✓' : '') : 'n/a';
    lines.push(`| ${r.label} | ${f(a.ms)} [${f(a.noise)}] | ${f(meanGpu(r))} | ${psnr} | ${f(maxErr, 0)} | ${pareto} |`);
  }
  const byKey = new Map(rows.map((r) => [r.key, r]));
  const base = byKey.get('baseline');
  const sceneOnly = byKey.get('scene only');
  const clear = byKey.get('clear only');
  lines.push('');
  if (base && sceneOnly && clear) {
    const b = aggregate(base).ms, s = aggregate(sceneOnly).ms, c = aggregate(clear).ms;
    lines.push(`Baselines: clear-only ${f(c)} ms, scene-only ${f(s)} ms, full frame ${f(b)} ms; the reflection and glass cost ${f(b / s)}× the scene pass alone.`);
  }
  // The peer against our rows of its own colour space: srgb (three.js's default pipeline) first.
  const peers = scored.filter((r) => r.kind === 'three');
  for (const [space, name] of [['srgb', 'In linear light (srgb)'], ['none', 'As stored (color-space none, as the runs before color-space existed)']] as const) {
    const line = peerLine(scored, peers.find((p) => p.knobs.colorSpace === space), name);
    if (line) lines.push(line);
  }
  lines.push(`Size, min+gzip: ours (standalone, gl-matrix included) ${kb(input.sizes.ours)}; three.js peer (three + Reflector + scene) ${kb(input.sizes.three)}.`, '');
  if (input.savings.length) {
    lines.push('## What the skips save (defaults)', '');
    lines.push('Culling objects beyond the glass from the reflection, scissoring it to the glass, and skipping reflection and glass when the glass is off screen or edge-on; the same frames timed with all of it off.', '');
    lines.push('| view | with skips, ms | without, ms | saved |');
    lines.push('|---|---|---|---|');
    for (const v of input.savings) lines.push(`| ${v.view} | ${f(v.on)} | ${f(v.off)} | ${f(100 * (1 - v.on / v.off), 0)}% |`);
    lines.push('');
  }
  const bars = scored.filter((r) => r.label.startsWith('**defaults**') || r.key === 'baseline' || r.key === 'color-space none' || r.kind === 'three');
  if (bars.length) {
    lines.push(`## Per view: every region (the bars for srgb: ≥ ${BAR_ALL_DB} dB overall, ≥ ${BAR_DARK_DB} dB dark)`, '');
    lines.push(`PSNR dB ${PSNR_REGIONS.join(' / ')} per view ("—": the view has no pixel of that region). Marked ✗: an srgb figure under its bar.`, '');
    lines.push(`| config | ${input.views.join(' | ')} |`);
    lines.push(`|---|${input.views.map(() => '---').join('|')}|`);
    for (const r of bars) {
      const srgb = r.knobs.colorSpace === 'srgb';
      lines.push(`| ${r.label} | ${r.perView.map((v) => {
        const p = v.error!.psnr;
        const under = srgb && (p.all < BAR_ALL_DB || p.dark < BAR_DARK_DB);
        return `${psnrCell(p)}${under ? ' ✗' : ''}`;
      }).join(' | ')} |`);
    }
    const under = scored.filter((r) => r.kind === 'ours' && r.knobs.colorSpace === 'srgb')
      .flatMap((r) => r.perView.flatMap((v) => [
        ...(v.error!.psnr.all < BAR_ALL_DB ? [`${r.label} in ${v.view}: all ${f(v.error!.psnr.all, 1)}`] : []),
        ...(v.error!.psnr.dark < BAR_DARK_DB ? [`${r.label} in ${v.view}: dark ${f(v.error!.psnr.dark, 1)}`] : []),
      ]));
    lines.push('', under.length
      ? `Every srgb figure of ours under a bar, in any row: ${under.join('; ')}.`
      : 'No srgb figure of ours is under a bar, in any row and view.', '');
  }
  if (input.linearResampled?.length) {
    lines.push('## Pixel-ratio rows downscaled in linear light', '');
    lines.push(`The pixel-ratio rows above are brought back to ${input.scene.width}×${input.scene.height} as a compositor does, filtering the encoded bytes. ` +
      'Here the same frames are filtered in linear light (decoded, averaged, encoded: resample \'srgb\'), the sRGB-correct downscale, against the same srgb reference.', '');
    lines.push(`| config | PSNR dB ${PSNR_REGIONS.join(' / ')}, as stored | in linear light |`);
    lines.push('|---|---|---|');
    for (const l of input.linearResampled) {
      const r = rows.find((x) => x.key === l.key)!;
      lines.push(`| ${l.label} | ${PSNR_REGIONS.map((g) => f(meanPsnr(r, g), 1)).join(' / ')} | ${PSNR_REGIONS.map((g) => f(meanPsnr(l, g), 1)).join(' / ')} |`);
    }
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
    linearResampled: input.linearResampled?.map((r) => ({ key: r.key, perView: r.perView.map((v) => ({ view: v.view, error: v.error })) })),
  };
  return { markdown: lines.join('\n') + '\n', json };
}
