// Refinement at rest (docs/refinement.md): the offsets of the pixel grid, the running mean's weights, which frames
// refine, the clip-space shift, FrameSetup's use of it and the software renderer's mean — each by hand.
import { describe, expect, it } from 'vitest';
import { binomial3, gatherJitter, jitterClip, MAX_REFINEMENT, meanShare, refinementGrid, refinementOffset, refinementScale, refinementWeight, refines } from '../../src/frame/refinement';
import { FrameSetup } from '../../src/frame/frame-setup';
import { RunningMean } from '../../src/software/running-mean';
import { defaultScene } from '../../src/scene/default-scene';
import { defaultFrameState } from './helpers/frame-state';
import { expectClose } from './helpers/math';

const offset = (k: number, frames: number) => Array.from(refinementOffset(k, frames, [0, 0]));

describe('refinement: the strata', () => {
  it('the grid is the least power of 3 whose square holds the frames after the preview', () => {
    expect([1, 2, 3, 10, 11, 82, 83, 730, 731].map(refinementGrid)).toEqual([1, 1, 3, 3, 9, 9, 27, 27, 81]);
    expect(refinementGrid(1e9)).toBe(729); // at most six digits
    expect(refinementGrid(0)).toBe(1);
  });

  it('C(n, k) mod 3 by hand', () => {
    // Row 4 of Pascal's triangle is 1 4 6 4 1 → 1 1 0 1 1 mod 3; row 5: 1 5 10 10 5 1 → 1 2 1 1 2 1.
    expect([0, 1, 2, 3, 4].map((k) => binomial3(4, k))).toEqual([1, 1, 0, 1, 1]);
    expect([0, 1, 2, 3, 4, 5].map((k) => binomial3(5, k))).toEqual([1, 2, 1, 1, 2, 1]);
    expect(binomial3(2, 1)).toBe(2);
    expect(binomial3(1, 2)).toBe(0);
    expect(binomial3(0, 0)).toBe(1);
    expect(binomial3(2, 3)).toBe(0); // n's digits run out before k's: C(0, 1) = 0
    expect(binomial3(9, 3)).toBe(0); // 100 and 010 in base 3: C(0, 1) = 0
    expect(binomial3(8, 4)).toBe(70 % 3);
  });

  it('the preview is unmoved; strata frames start at the centre, then the Faure points by hand', () => {
    expect(offset(1, 10)).toEqual([0, 0]);
    // 3 × 3: point i's cells (x, y) = (a₀, a₀ + a₁ mod 3), each digit d → d + 1 mod 3; cell c's centre is (c + ½)/3 − ½.
    const cells = [[1, 1], [2, 2], [0, 0], [1, 2], [2, 0], [0, 1], [1, 0], [2, 1], [0, 2]];
    for (let i = 0; i < 9; i++) expectClose(offset(i + 2, 10), cells[i].map((c) => (c + 0.5) / 3 - 0.5), 1e-15);
    // Past the ninth stratum the sequence starts again; fractions count by their whole part; below 2 the centre.
    expectClose(offset(11, 10), offset(2, 10), 0);
    expectClose(offset(3.7, 10), offset(3, 10), 0);
    expect(offset(0, 10)).toEqual([0, 0]);
    // 9 × 9: point 1 (digits 1, 0) has x digits (2, 1), y digits (1 + 0 + 1, 0 + 1) = (2, 1): cell 7 of 9 on both axes.
    expectClose(offset(3, 82), [7.5 / 9 - 0.5, 7.5 / 9 - 0.5], 1e-15);
    // Point 3 (digits 0, 1): x (1, 2) → cell 5; y: b₀ = 0 + 1 = 1, b₁ = 1 → (2, 2) → cell 8.
    expectClose(offset(5, 82), [5.5 / 9 - 0.5, 8.5 / 9 - 0.5], 1e-15);
  });

  it('side² strata frames fill every stratum once, and every run of 9 fills the 3 × 3 cells', () => {
    for (const [frames, side] of [[10, 3], [82, 9], [730, 27]]) {
      const seen = new Set<string>();
      for (let k = 2; k <= frames; k++) {
        const [x, y] = offset(k, frames);
        const cx = Math.round((x + 0.5) * side - 0.5), cy = Math.round((y + 0.5) * side - 0.5);
        expect(Math.abs((cx + 0.5) / side - 0.5 - x)).toBeLessThan(1e-12);
        seen.add(`${cx},${cy}`);
      }
      expect(seen.size).toBe(side * side);
    }
    for (let start = 2; start < 82; start += 9) {
      const coarse = new Set<string>();
      for (let k = start; k < start + 9; k++) {
        const [x, y] = offset(k, 82);
        coarse.add(`${Math.floor((x + 0.5) * 3)},${Math.floor((y + 0.5) * 3)}`);
      }
      expect(coarse.size).toBe(9);
    }
  });

  it('the strata mean weighs frame k by 1/(k − 1); the shown picture lets the mean in linearly', () => {
    expect([2, 3, 5, 17].map(refinementWeight)).toEqual([1, 0.5, 0.25, 1 / 16]);
    expect(refinementWeight(1)).toBe(1);
    expect(refinementWeight(4.5)).toBe(1 / 3);
    // Four strata 1, 2, 3, 6 through the mean: (1 + 2 + 3 + 6) / 4.
    let mean = 0;
    [1, 2, 3, 6].forEach((v, i) => { const w = refinementWeight(i + 2); mean = (1 - w) * mean + w * v; });
    expect(mean).toBe(3);
    expect([1, 2, 6, 10, 11].map((k) => meanShare(k, 10))).toEqual([0, 1 / 9, 5 / 9, 1, 1]);
    expect(meanShare(3, 1)).toBe(0);
    expect(meanShare(0, 10)).toBe(0);
    expect(meanShare(0.5, 10)).toBe(0);
    expect(meanShare(2, 2)).toBe(1);
    expect(meanShare(2.5, 3)).toBe(0.5);
    expect(MAX_REFINEMENT).toBe(1024);
  });

  it('only a final picture in linear light refines, from frame 1 on; strata frames draw finer', () => {
    const s = defaultFrameState({ refinement: 1, refinementFrames: 82 });
    expect(refines(s)).toBe(true);
    expect(refines({ ...s, refinement: 0 })).toBe(false);
    expect(refines({ ...s, refinement: undefined })).toBe(false);
    expect(refines({ ...s, refinement: 0.5 })).toBe(false);
    expect(refines({ ...s, view: 'scene' })).toBe(false);
    expect(refines({ ...s, view: 'fresnel' })).toBe(false);
    expect(refines({ ...s, colorSpace: 'none' })).toBe(false);
    expect(refinementScale(s)).toBe(1);
    expect(refinementScale({ ...s, refinement: 2 })).toBe(9);
    expect(refinementScale({ ...s, refinement: 2, refinementFrames: 10 })).toBe(3);
    expect(refinementScale({ ...s, refinement: 2, refinementFrames: undefined })).toBe(1);
    expect(refinementScale({ ...s, refinement: 2, view: 'scene' })).toBe(1);
  });
});

describe('refinement: rough glass’s gather', () => {
  it('strata frames place each ring sample at another stratum of its sector, the order 7·i mod side²', () => {
    const out = new Float64Array(3);
    const at = (refinement: number, refinementFrames = 10) => {
      gatherJitter(defaultFrameState({ refinement, refinementFrames }), out);
      return Array.from(out);
    };
    expect(at(1)).toEqual([0.5, 0.5, 0]); // the preview: the gather as it is alone
    expect(at(0)).toEqual([0.5, 0.5, 0]);
    expectClose(at(2), [0.5, 0.5, -Math.log2(3)], 1e-15); // point 0: the centre stratum
    expectClose(at(3), [5 / 6, 0.5, -Math.log2(3)], 1e-15); // point 7: cell (2, 1)
    expectClose(at(4), [1 / 6, 0.5, -Math.log2(3)], 1e-15); // point 14 mod 9 = 5: cell (0, 1)
    expectClose(at(3, 82).slice(2), [-Math.log2(9)], 1e-15);
    gatherJitter(defaultFrameState({ refinement: 3, refinementFrames: 10, view: 'scene' }), out);
    expect(Array.from(out)).toEqual([0.5, 0.5, 0]);
    // Nine strata frames of a 10-frame view: nine distinct strata.
    const seen = new Set<string>();
    for (let k = 2; k <= 10; k++) seen.add(at(k).slice(0, 2).map((x) => x.toFixed(6)).join(','));
    expect(seen.size).toBe(9);
  });
});

describe('refinement: the grid moves', () => {
  it('jitterClip moves every point by dx, dy pixels in either projection', () => {
    // A perspective-like matrix (w = −z) and an orthographic one (w = 1), column-major.
    const perspective = new Float64Array([1.5, 0, 0, 0, 0, 2, 0, 0, 0.1, 0.2, -1.2, -1, 0.3, 0.4, -0.5, 0]);
    const orthographic = new Float64Array([0.5, 0, 0, 0, 0, 0.25, 0, 0, 0, 0, -0.1, 0, 0.2, -0.3, -0.4, 1]);
    const toNdc = (m: Float64Array, p: number[]) => {
      const c = [0, 1, 3].map((r) => m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r]);
      return [c[0] / c[2], c[1] / c[2]];
    };
    for (const m of [perspective, orthographic]) {
      for (const p of [[0.3, -0.7, -2], [1, 2, -5]]) {
        const before = toNdc(m, p), moved = Float64Array.from(m);
        jitterClip(moved, 0.5, -0.25, 200, 100);
        // ½ pixel of 200 is 2·½/200 = 0.005 in NDC; −¼ of 100 is −0.005.
        expectClose(toNdc(moved, p), [before[0] + 0.005, before[1] - 0.005], 1e-14);
        // z and w are what they were.
        for (const i of [2, 3, 6, 7, 10, 11, 14, 15]) expect(moved[i]).toBe(m[i]);
      }
    }
    const zero = new Float64Array(16).fill(0);
    zero[15] = 1;
    jitterClip(zero, 1, 1, 0, 0); // a 0 × 0 frame counts as 1 × 1
    expect([zero[12], zero[13]]).toEqual([2, 2]);
  });

  it('FrameSetup moves both eyes by frame k’s offset, and only a refining frame', () => {
    const scene = defaultScene(0.75, 0);
    const still = new FrameSetup(), moved = new FrameSetup();
    const base = defaultFrameState({ width: 320, height: 180, time: 0 });
    still.update(base, scene);
    moved.update({ ...base, refinement: 3, refinementFrames: 10 }, scene); // stratum (2, 2) of 3: (⅓, ⅓) pixel
    const expected = Float64Array.from(still.viewProjection);
    jitterClip(expected, 1 / 3, 1 / 3, 320, 180);
    expectClose(Array.from(moved.viewProjection), Array.from(expected), 1e-15);
    const mirrored = Float64Array.from(still.mirroredViewProjection);
    jitterClip(mirrored, 1 / 3, 1 / 3, 320, 180);
    expectClose(Array.from(moved.mirroredViewProjection), Array.from(mirrored), 1e-15);
    // Frame 1, the debug views and color-space none draw the unmoved grid.
    for (const s of [{ refinement: 1 }, { refinement: 2 }, { refinement: 3, refinementFrames: 10, view: 'scene' as const }, { refinement: 3, refinementFrames: 10, colorSpace: 'none' as const }]) {
      moved.update({ ...base, ...s }, scene);
      expect(Array.from(moved.viewProjection)).toEqual(Array.from(still.viewProjection));
    }
  });
});

describe('refinement: the software renderer’s running mean', () => {
  it('keeps the preview, averages strata frames with weight 1/(k − 1), and blends them by the mean’s share', () => {
    const mean = new RunningMean();
    // A 2 × 3 frame; the band is row 1, drawn with 2 × 2 samples per pixel (a 4 × 2 grid of RGB samples); 4 frames.
    const frame = (values: number[]) => Float32Array.from(values.flatMap((v) => [v, 2 * v, 3 * v]));
    const a = mean.add(frame([1, 3, 5, 7, 1, 3, 5, 7]), 2, 3, 1, 2, 2, 1, 4);
    expect(Array.from(a)).toEqual([2, 4, 6, 6, 12, 18]); // the preview: (1 + 3 + 1 + 3) / 4, (5 + 7 + 5 + 7) / 4
    // Strata frame 2 (the mean is it), shown with share 1/3: (2·2 + 8)/3 = 4, (2·6 + 2)/3 = 14/3.
    const b = mean.add(frame([8, 8, 2, 2, 8, 8, 2, 2]), 2, 3, 1, 2, 2, 2, 4);
    expectClose(Array.from(b), [4, 8, 12, 14 / 3, 28 / 3, 14], 1e-6);
    // Frame 3: mean (8 + 2)/2 = 5 and (2 + 4)/2 = 3; share 2/3: (2 + 2·5)/3 = 4, (6 + 2·3)/3 = 4.
    const c = mean.add(frame([2, 2, 4, 4, 2, 2, 4, 4]), 2, 3, 1, 2, 2, 3, 4);
    expectClose(Array.from(c), [4, 8, 12, 4, 8, 12], 1e-6);
    // Frame 4, the last: the mean alone, (8 + 2 + 5)/3 = 5 and (2 + 4 + 0)/3 = 2.
    const d = mean.add(frame([5, 5, 0, 0, 5, 5, 0, 0]), 2, 3, 1, 2, 2, 4, 4);
    expectClose(Array.from(d), [5, 10, 15, 2, 4, 6], 1e-6);
    // One sample per pixel, a new preview: it replaces the old one; a new strata frame 2 replaces the old mean.
    expect(Array.from(mean.add(frame([9, 8]), 2, 3, 1, 2, 1, 1, 2))).toEqual([9, 18, 27, 8, 16, 24]);
    expect(Array.from(mean.add(frame([1, 2]), 2, 3, 1, 2, 1, 2, 2))).toEqual([1, 2, 3, 2, 4, 6]);
    // Row 0's preview was never written: frame 2 over it shows the half of the strata's share (2 frames: share 1).
    expect(Array.from(mean.add(frame([1, 1]), 2, 3, 0, 1, 1, 2, 3))).toEqual([0.5, 1, 1.5, 0.5, 1, 1.5]);
  });

  it('a band of two rows, 2 × 2 samples a pixel: each pixel its own samples, through three frames', () => {
    const mean = new RunningMean();
    // Pixels (row, column) = 1, 2 / 3, 4, each of its 2 × 2 samples alike; 4 × 4 samples, RGB = v, 2v, 3v.
    const frame = (scale: number) => {
      const rows = [[1, 1, 2, 2], [1, 1, 2, 2], [3, 3, 4, 4], [3, 3, 4, 4]];
      return Float32Array.from(rows.flat().flatMap((v) => [scale * v, 2 * scale * v, 3 * scale * v]));
    };
    const red = (a: Float32Array) => Array.from(a).filter((_, i) => i % 3 === 0);
    expect(red(mean.add(frame(1), 2, 2, 0, 2, 2, 1, 3))).toEqual([1, 2, 3, 4]);
    expect(red(mean.add(frame(10), 2, 2, 0, 2, 2, 2, 3))).toEqual([5.5, 11, 16.5, 22]); // share ½ of the mean 10, 20, 30, 40
    expect(red(mean.add(frame(20), 2, 2, 0, 2, 2, 3, 3))).toEqual([15, 30, 45, 60]); // the mean of 10·v and 20·v, all of it
  });
});
