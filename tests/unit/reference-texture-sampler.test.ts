// The reference's texture sampler on small textures (src/reference/texture-sampler.ts): texel wrapping (masks and
// remainders), bilinear values, and the box filter's exact means, worked out by hand — on a texture whose bilinear
// reconstruction is the polynomial x·y + 3x − y, whose mean over a parallelogram centred at c with edges e1, e2 is
// cx·cy + (e1s·e1t + e2s·e2t)/12 + 3cx − cy (the mean of a² and of b² over [−½, ½] is 1/12).
import { describe, expect, it } from 'vitest';
import { proceduralGrey, TextureSampler } from '../../src/reference/texture-sampler';
import { texel } from '../../src/scene/procedural-texture';
import { srgbToLinear } from '../../src/math/srgb';

/** W×H texels with value f(i, j). */
function sampler(w: number, h: number, f: (i: number, j: number) => number): TextureSampler {
  const grey = new Float64Array(w * h);
  for (let j = 0; j < h; j++) for (let i = 0; i < w; i++) grey[j * w + i] = f(i, j);
  return new TextureSampler(grey, w, h);
}

/** (u, v) of texel-centre coordinates (s, t): s = u·W − ½. */
const uv = (s: number, t: number, w: number, h: number): [number, number] => [(s + 0.5) / w, (t + 0.5) / h];

describe('TextureSampler.texel', () => {
  it('wraps by masking for powers of two, by remainder otherwise, negative coordinates included', () => {
    const p = sampler(4, 2, (i, j) => 10 * j + i);
    expect(p.width).toBe(4);
    expect(p.height).toBe(2);
    expect([p.texel(0, 0), p.texel(3, 1), p.texel(-1, 0), p.texel(5, -1), p.texel(-4, 2), p.texel(7, 3)]).toEqual([0, 13, 3, 11, 0, 13]);
    const q = sampler(3, 5, (i, j) => 10 * j + i);
    expect([q.texel(2, 4), q.texel(-1, -1), q.texel(4, 7), q.texel(-3, -5), q.texel(3, 5), q.texel(-7, 12)]).toEqual([42, 42, 21, 0, 0, 22]);
    // Mixed: a power of two across, not down, and the other way round.
    const r = sampler(2, 3, (i, j) => 10 * j + i);
    expect([r.texel(-1, -1), r.texel(3, 4), r.texel(2, 3)]).toEqual([21, 11, 0]);
    const s = sampler(3, 2, (i, j) => 10 * j + i);
    expect([s.texel(-1, -1), s.texel(4, 3), s.texel(3, 2)]).toEqual([12, 11, 0]);
    // One texel: every coordinate.
    const one = sampler(1, 1, () => 7);
    expect([one.texel(0, 0), one.texel(-3, 5)]).toEqual([7, 7]);
  });

  it('with no texels given, the 512² procedural texture as stored', () => {
    const t = new TextureSampler();
    expect([t.width, t.height]).toEqual([512, 512]);
    for (const [x, y] of [[0, 0], [1, 0], [37, 200], [511, 511]]) expect(t.texel(x, y)).toBe(texel(x, y) / 255);
    expect(t.texel(-1, 0)).toBe(t.texel(511, 0));
  });

  it('proceduralGrey: the red byte of each texel of the procedural texture, by level', () => {
    const none = proceduralGrey('none'), srgb = proceduralGrey('srgb');
    expect(none.length).toBe(512 * 512);
    for (const [x, y] of [[0, 0], [5, 0], [300, 17], [511, 511]]) {
      expect(none[y * 512 + x]).toBe(texel(x, y) / 255);
      expect(srgb[y * 512 + x]).toBeCloseTo(srgbToLinear(texel(x, y) / 255), 12);
    }
  });
});

describe('TextureSampler.bilinear', () => {
  // 2×2: t00 = 0, t10 = 1, t01 = 2, t11 = 4: f = x + 2y + xy on the cell between the texel centres.
  const t = sampler(2, 2, (i, j) => [[0, 1], [2, 4]][j][i]);

  it('a texel at its centre, the patch a + bx + cy + dxy between', () => {
    expect(t.bilinear(...uv(0, 0, 2, 2))).toBe(0);
    expect(t.bilinear(...uv(1, 1, 2, 2))).toBe(4);
    // (0.5, 0.5): 0.5 + 1 + 0.25 = 1.75; (0.25, 0.75): 0.25 + 1.5 + 0.1875 = 1.9375.
    expect(t.bilinear(...uv(0.5, 0.5, 2, 2))).toBe(1.75);
    expect(t.bilinear(...uv(0.25, 0.75, 2, 2))).toBe(1.9375);
  });

  it('repeats: between the last texel and the first', () => {
    // s = −0.5: halfway between texel 1 (−1 wrapped) and texel 0, at row 0: (1 + 0)/2.
    expect(t.bilinear(0, 0.25)).toBe(0.5);
    // s = 1.5, t = 1.5: the four texels, wrapped: mean 1.75.
    expect(t.bilinear(1, 1)).toBe(1.75);
    expect(t.bilinear(...uv(0.5, 0.5 + 2, 2, 2))).toBe(1.75);
  });

  it('on a texture of more rows: the rows above and below are the right ones', () => {
    // 16×16 texels i·j + 3i − j: the bilinear value is s·t + 3s − t.
    const poly = sampler(16, 16, (i, j) => i * j + 3 * i - j);
    for (const [s, t] of [[5.25, 7.5], [2.75, 9.25], [10.5, 3.125]]) expect(poly.bilinear(...uv(s, t, 16, 16))).toBeCloseTo(s * t + 3 * s - t, 12);
  });

  it('rectangular textures scale u by W and v by H', () => {
    const r = sampler(4, 2, (i, j) => i + 10 * j);
    // s = 1.25, t = 0.5: 1.25 + 5.
    expect(r.bilinear(...uv(1.25, 0.5, 4, 2))).toBe(6.25);
  });
});

describe('TextureSampler.boxFilter', () => {
  // 16×16 texels i·j + 3i − j: the polynomial x·y + 3x − y exactly, away from the seam.
  const poly = sampler(16, 16, (i, j) => i * j + 3 * i - j);
  const mean = (cx: number, cy: number, e1: [number, number], e2: [number, number]) =>
    cx * cy + (e1[0] * e1[1] + e2[0] * e2[1]) / 12 + 3 * cx - cy;
  const box = (t: TextureSampler, cx: number, cy: number, e1: [number, number], e2: [number, number]) =>
    t.boxFilter(...uv(cx, cy, t.width, t.height), e1[0], e1[1], e2[0], e2[1]);

  it('inside one cell: the closed form', () => {
    const cases: [number, number, [number, number], [number, number]][] = [
      [5.5, 7.5, [0.4, 0.2], [-0.1, 0.3]],
      [2.3, 9.6, [0.2, -0.1], [0.1, 0.25]],
    ];
    for (const [cx, cy, e1, e2] of cases) {
      expect(box(poly, cx, cy, e1, e2)).toBeCloseTo(mean(cx, cy, e1, e2), 12);
      // Either orientation, either order.
      expect(box(poly, cx, cy, e2, e1)).toBeCloseTo(mean(cx, cy, e1, e2), 12);
      expect(box(poly, cx, cy, [-e1[0], -e1[1]], e2)).toBeCloseTo(mean(cx, cy, e1, e2), 12);
    }
  });

  it('across many cells, turned and sheared: exact', () => {
    const cases: [number, number, [number, number], [number, number]][] = [
      [6.3, 7.1, [3.3, 1.1], [-0.8, 2.5]],
      [8, 8, [4, 0], [0, 4]],
      [4.2, 10.7, [0.5, -2.2], [1.7, 0.6]],
      [9.9, 3.4, [5.5, 0.3], [0.2, -0.9]],
      [7.5, 7.5, [2, 2], [-2, 2]],
    ];
    for (const [cx, cy, e1, e2] of cases) {
      expect(box(poly, cx, cy, e1, e2), `${cx}, ${cy}`).toBeCloseTo(mean(cx, cy, e1, e2), 10);
      expect(box(poly, cx, cy, e2, e1), `${cx}, ${cy} swapped`).toBeCloseTo(mean(cx, cy, e1, e2), 10);
    }
  });

  // 2×2: t00 = 0, t10 = 1, t01 = 2, t11 = 4.
  const t = sampler(2, 2, (i, j) => [[0, 1], [2, 4]][j][i]);

  it('a whole cell, a whole period, and a sheared period: the mean of the texels', () => {
    // The cell [0, 1]²: ∫ x + 2y + xy = ½ + 1 + ¼.
    expect(box(t, 0.5, 0.5, [1, 0], [0, 1])).toBeCloseTo(1.75, 14);
    expect(box(t, 1, 1, [2, 0], [0, 2])).toBeCloseTo(1.75, 14);
    expect(box(t, 0.3, 0.7, [2, 0], [1, 2])).toBeCloseTo(1.75, 14);
  });

  it('half cells on either side of a texel column, and across the seam', () => {
    // [0.5, 1.5] × [0, 1]: ∫ over x ∈ [½, 1] of x + 2y + xy = 1.0625, and over the next cell's x ∈ [0, ½] of
    // 1 − x + 3y − xy (corners 1, 0, 4, 2) = 1.0625: 2.125.
    expect(box(t, 1, 0.5, [1, 0], [0, 1])).toBeCloseTo(2.125, 14);
    // [−0.5, 0.5] × [0, 1]: the wrapped cell −1 over x ∈ [½, 1] (0.6875) and cell 0 over [0, ½] (0.6875).
    expect(box(t, 0, 0.5, [1, 0], [0, 1])).toBeCloseTo(1.375, 14);
    // Up and down: [0, 1] × [−0.5, 0.5]: ∫ over y ∈ [½, 1] of the wrapped cell (0, −1) (corners 2, 4, 0, 1:
    // 2 + 2x − 2y − xy) = ∫ 0.25 + 0.625x = 0.5625, and over y ∈ [0, ½] of x + 2y + xy = ∫ 0.25 + 0.625x = 0.5625.
    expect(box(t, 0.5, 0, [1, 0], [0, 1])).toBeCloseTo(1.125, 14);
    // A non-power-of-two texture across its seam: 3×1 of 0, 3, 6: [−0.5, 0.5]: halves of the cells (6 → 0) and (0 → 3):
    // ∫_{½}^{1} 6 − 6x + ∫_0^{½} 3x = 0.75 + 0.375.
    const three = sampler(3, 1, (i) => 3 * i);
    expect(box(three, 0, 0, [1, 0], [0, 1])).toBeCloseTo(1.125, 14);
  });

  it('a footprint across a column only, or a row only, of a texture that is not one bilinear patch', () => {
    // [0.5, 1.5] × [0.2, 0.8]: ∫ over x ∈ [½, 1] of x + 2y + xy (0.6375) and over the next cell's x ∈ [0, ½] of
    // 1 − x + 3y − xy (0.6375): 1.275 over 0.6.
    expect(box(t, 1, 0.5, [1, 0], [0, 0.6])).toBeCloseTo(2.125, 14);
    // [0.2, 0.8] × [0.5, 1.5]: ∫ over y ∈ [½, 1] of x + 2y + xy (0.7125) and over the cell above's y ∈ [0, ½] of
    // 2 + 2x − 2y − xy (0.7125): 1.425 over 0.6.
    expect(box(t, 0.5, 1, [0.6, 0], [0, 1])).toBeCloseTo(2.375, 14);
  });

  it('no area (or not a number): the bilinear value', () => {
    const [u, v] = uv(0.25, 0.75, 2, 2);
    expect(t.boxFilter(u, v, 0, 0, 0, 0)).toBe(1.9375);
    expect(t.boxFilter(u, v, 1, 2, 2, 4)).toBe(1.9375);
    expect(t.boxFilter(u, v, NaN, 0, 0, 1)).toBe(1.9375);
    // An area of exactly 1e-12 is still a point: a thin diagonal of a cell would average its line otherwise.
    expect(t.boxFilter(u, v, 1, 1, 0, 1e-12)).toBe(1.9375);
    // A tiny one is filtered, and tends to the point value.
    expect(t.boxFilter(u, v, 1e-3, 0, 0, 1e-3)).toBeCloseTo(1.9375, 9);
  });
});
