// The bench's own arithmetic: Pareto dominance with noise, quartiles, seeded shuffle, resampling, the refinement bench's
// still views, means and plot.
import { describe, expect, it } from 'vitest';
import { dominates, paretoFront, PSNR_TOLERANCE_DB } from '../../bench/pareto';
import { quantile, shuffled, summary } from '../../bench/stats';
import { resample } from '../../bench/resample';
import { CONFIGS, BASELINE, DEFAULTS, configName } from '../../bench/configs';
import { stillState } from '../../bench/bench-state';
import { meanRegion } from '../../bench/report';
import { firstReaching, meanAt, meanMs, type Still } from '../../bench/refine-report';
import { refinePlot } from '../../bench/refine-plot';
import { defaultFrameState } from './helpers/frame-state';

describe('pareto', () => {
  it('dominates when no slower, no worse, and better beyond the noise in one', () => {
    const slowGood = { ms: 10, noise: 0.5, psnr: 40 };
    const fastBad = { ms: 5, noise: 0.5, psnr: 30 };
    const fastGood = { ms: 5, noise: 0.5, psnr: 41 };
    expect(dominates(fastGood, slowGood)).toBe(true);
    expect(dominates(fastBad, slowGood)).toBe(false);
    expect(dominates(slowGood, fastBad)).toBe(false);
    expect(dominates(fastGood, fastBad)).toBe(true); // as fast, far more accurate
    // Inside the bands: not told apart, neither dominates.
    const twin = { ms: 10.3, noise: 0.5, psnr: 40 + PSNR_TOLERANCE_DB / 2 };
    expect(dominates(twin, slowGood)).toBe(false);
    expect(dominates(slowGood, twin)).toBe(false);
    // Faster beyond the noise but less accurate beyond the tolerance: a trade, not dominance.
    expect(dominates({ ms: 5, noise: 0.5, psnr: 39 }, slowGood)).toBe(false);
    expect(paretoFront([slowGood, fastBad, fastGood])).toEqual([false, false, true]);
    expect(paretoFront([slowGood, fastBad])).toEqual([true, true]);
  });
});

describe('stats', () => {
  it('interpolates quantiles and summarises', () => {
    expect(quantile([1, 2, 3, 4], 0.5)).toBe(2.5);
    expect(summary([5, 1, 3, 2, 4])).toEqual({ median: 3, q1: 2, q3: 4, iqr: 2 });
  });
  it('shuffles reproducibly and completely', () => {
    const xs = Array.from({ length: 20 }, (_, i) => i);
    expect(shuffled(xs, 7)).toEqual(shuffled(xs, 7));
    expect(shuffled(xs, 7)).not.toEqual(xs);
    expect([...shuffled(xs, 7)].sort((a, b) => a - b)).toEqual(xs);
  });
});

describe('resample', () => {
  it('box-filters an integer shrink and keeps a same-size image', () => {
    const src = new Uint8ClampedArray([0, 0, 0, 255, 100, 100, 100, 255, 200, 200, 200, 255, 100, 100, 100, 255]);
    expect([...resample(src, 2, 2, 1, 1)]).toEqual([100, 100, 100, 255]);
    expect([...resample(src, 2, 2, 2, 2)]).toEqual([...src]);
  });
  it("mixes as stored by default, in linear light with 'srgb' (alpha as stored either way)", () => {
    const blackWhite = new Uint8ClampedArray([0, 0, 0, 255, 255, 255, 255, 0]);
    expect([...resample(blackWhite, 2, 1, 1, 1)]).toEqual([128, 128, 128, 128]); // 127.5, rounded up
    // Half-way between black and white in light: encode(0.5) = 0.7354, level 188 (docs/colour.md#the-transfer-curve).
    expect([...resample(blackWhite, 2, 1, 1, 1, 'srgb')]).toEqual([188, 188, 188, 128]);
    const grey = new Uint8ClampedArray(4 * 4).fill(77);
    expect(new Set(resample(grey, 2, 2, 3, 3, 'srgb'))).toEqual(new Set([77])); // bilinear, decoded and encoded again
  });
  it('bilinearly enlarges, preserving a constant image', () => {
    const src = new Uint8ClampedArray(4 * 4).fill(77);
    expect(new Set(resample(src, 2, 2, 3, 3))).toEqual(new Set([77]));
  });
});

describe('configs', () => {
  it('has about 30 distinct configurations, named by what differs from the baseline', () => {
    expect(CONFIGS.length).toBeGreaterThanOrEqual(25);
    expect(CONFIGS.length).toBeLessThanOrEqual(40);
    expect(new Set(CONFIGS.map((c) => c.name)).size).toBe(CONFIGS.length);
    expect(configName(BASELINE)).toBe('baseline');
    expect(configName({ ...BASELINE, samples: 0 })).toBe('samples 0');
  });
  it('draws every row in linear light but the baseline and the defaults as stored, named so', () => {
    expect(BASELINE.colorSpace).toBe('srgb');
    expect(DEFAULTS.colorSpace).toBe('srgb');
    const none = CONFIGS.filter((c) => c.colorSpace === 'none').map((c) => c.name);
    expect(none).toContain('color-space none');
    expect(none).toContain(configName({ ...DEFAULTS, colorSpace: 'none' }));
    expect(configName({ ...DEFAULTS, colorSpace: 'none' })).toBe('tessellation auto, color-space none');
    for (const c of CONFIGS) expect(c.name.includes('color-space none')).toBe(c.colorSpace === 'none');
  });
});

describe('refinement bench', () => {
  const region = (all: number) => ({ all, glass: NaN, objects: all, background: all, edges: all, dark: all });
  const still = (frames: number, dbs: number[][], ms: number[][]): Still => ({
    frames, perView: dbs.map((d, i) => ({ view: `v${i}`, ms: ms[i], psnr: d.map((x) => (Number.isNaN(x) ? null : region(x))) })),
  });

  it('draws a still view as the element does: the preview at the samples asked for, strata and moving frames at one', () => {
    const s = defaultFrameState({ samples: 4 });
    expect(stillState(s, 1, 10)).toMatchObject({ samples: 4, refinement: 1, refinementFrames: 10 });
    expect(stillState(s, 2, 10)).toMatchObject({ samples: 0, refinement: 2, refinementFrames: 10 });
    expect(stillState(s, 0, 10)).toMatchObject({ samples: 0, refinement: 0, refinementFrames: 10 });
    expect(s.samples).toBe(4);
  });

  it('means a region over views, skipping empty regions and views not read, capping an identical one at 99', () => {
    expect(meanRegion([region(40), region(50)], 'all')).toBe(45);
    expect(meanRegion([region(40), null, undefined], 'all')).toBe(40);
    expect(meanRegion([region(40), region(Infinity)], 'all')).toBe(69.5);
    expect(meanRegion([region(40)], 'glass')).toBeNaN();
  });

  it('finds the first frame whose mean over views reaches a PSNR, with its mean cumulative ms', () => {
    const s = still(3, [[48, 49, 52], [50, 52, 54]], [[10, 20, 30], [12, 22, 32]]);
    expect(meanAt(s, 2, 'all')).toBe(50.5);
    expect(meanMs(s, 2)).toBe(21);
    expect(firstReaching(s, 50)).toEqual({ k: 2, ms: 21 });
    expect(firstReaching(s, 53)).toEqual({ k: 3, ms: 31 });
    expect(firstReaching(s, 54)).toBeNull();
    // A frame not read in every view is the mean of those that were.
    expect(firstReaching(still(2, [[NaN, 51], [49, 50]], [[5, 9], [5, 9]]), 50)).toEqual({ k: 2, ms: 9 });
  });

  it('plots ms on a log scale: a curve\'s points left to right as the ms grow, ten times the ms one decade further', () => {
    const svg = refinePlot('t', [{ label: 'c', marks: [1], points: [{ ms: 10, db: 40 }, { ms: 100, db: 45 }, { ms: 1000, db: 50 }] }],
      [{ label: 'p', ms: 50, db: 42, shape: 'circle' }], [50]);
    const xs = [...svg.matchAll(/[ML]([\d.]+),([\d.]+)/g)].slice(0, 3).map((m) => Number(m[1]));
    expect(xs[1] - xs[0]).toBeCloseTo(xs[2] - xs[1], 0);
    expect(xs[1]).toBeGreaterThan(xs[0]);
    const ys = [...svg.matchAll(/[ML]([\d.]+),([\d.]+)/g)].slice(0, 3).map((m) => Number(m[2]));
    expect(ys[2]).toBeLessThan(ys[0]); // more dB higher up
    expect(svg.startsWith('<svg')).toBe(true);
    expect(svg.trim().endsWith('</svg>')).toBe(true);
  });
});
