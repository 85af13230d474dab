// An environment image (src/math/environment-image.ts, docs/pbr.md#an-image): reduced by area to at most 512 × 256, and read
// as light from a direction the way three.js and model-viewer read an equirectangular image — the centre column toward +x, a
// quarter of the way toward −z, the top row toward +y — bilinear between texel centres. Values worked by hand.
import { describe, expect, it } from 'vitest';
import { imageRadiance, imageDirection, type EnvironmentImage } from '../../src/math/environment-image';
import { reduceImage } from '../../src/math/reduce-image';

/** A w × h image whose texel (i, j) is (i, j, 10·j + i) (red the column, green the row). */
function ramp(w: number, h: number): EnvironmentImage {
  const rgb = new Float32Array(w * h * 3);
  for (let j = 0; j < h; j++) for (let i = 0; i < w; i++) rgb.set([i, j, 10 * j + i], 3 * (j * w + i));
  return { width: w, height: h, rgb };
}

function read(img: EnvironmentImage, d: readonly number[]): number[] {
  const out = new Float64Array(3);
  imageRadiance(img)(out, d[0], d[1], d[2]);
  return Array.from(out);
}

describe('reading an environment image', () => {
  it('looks the way three.js looks: +x at the centre column, −z a quarter in, +z three quarters, −x at the seam', () => {
    // 8 × 4: the centre column's left edge is u = ½, x = u·8 − ½ = 3.5 between columns 3 and 4.
    const img = ramp(8, 4), c = Math.SQRT1_2;
    // Along the equator (v = ½: between rows 1 and 2, green 1.5).
    expect(read(img, [1, 0, 0])).toEqual([3.5, 1.5, 18.5]);
    expect(read(img, [0, 0, -1])).toEqual([1.5, 1.5, 16.5]);
    expect(read(img, [0, 0, 1])).toEqual([5.5, 1.5, 20.5]);
    // −x: u = 0 (or 1), x = −½, between the last column (7) and the first (0), wrapped: red (7 + 0)/2.
    expect(read(img, [-1, 0, 0])).toEqual([3.5, 1.5, 18.5]);
    // At a texel's centre: column 6 is u = 6.5/8, atan2(z, x) = 2π(6.5/8 − ½) = 5π/8; row 0's centre is θ = π/8.
    const phi = (5 * Math.PI) / 8, theta = Math.PI / 8;
    const d = [Math.sin(theta) * Math.cos(phi), Math.cos(theta), Math.sin(theta) * Math.sin(phi)];
    read(img, d).forEach((x, k) => expect(x).toBeCloseTo([6, 0, 6][k], 12));
    // Straight up and down: held at the first and last rows' centres; halfway between +x and +z: u = 5/8, x = 4.5.
    expect(read(img, [c, 0, c])).toEqual([4.5, 1.5, 19.5]);
    expect(read(img, [0, 1, 0])).toEqual([3.5, 0, 3.5]);
    expect(read(img, [0, -1, 0])).toEqual([3.5, 3, 33.5]);
    // 45° up toward +x: θ = π/4, v = ¼, y = ½ between rows 0 and 1.
    expect(read(img, [c, c, 0])).toEqual([3.5, 0.5, 8.5]);
  });

  it('the direction of a point (u, v) of the image is the one read back there', () => {
    const img = ramp(16, 8), out = new Float64Array(3);
    for (const [u, v] of [[0.1, 0.2], [0.55, 0.5], [0.9, 0.77]]) {
      imageDirection(out, u, v);
      expect(Math.hypot(out[0], out[1], out[2])).toBeCloseTo(1, 14);
      const got = read(img, Array.from(out));
      expect(got[0]).toBeCloseTo(u * 16 - 0.5, 9);
      expect(got[1]).toBeCloseTo(v * 8 - 0.5, 9);
    }
  });

  it('reduces by the mean of the texels each new one covers, and leaves a small image as it is', () => {
    const img = ramp(4, 2);
    expect(reduceImage(img, 8)).toBe(img);
    const half = reduceImage(img, 2);
    // Columns {0, 1} and {2, 3}, rows {0, 1}: red 0.5, 2.5; green 0.5; blue 5.5, 7.5.
    expect([half.width, half.height]).toEqual([2, 1]);
    expect(Array.from(half.rgb)).toEqual([0.5, 0.5, 5.5, 2.5, 0.5, 7.5]);
    // 3 → 2 across: the middle texel split half and half: (0 + ½·1)/1.5 and (½·1 + 2)/1.5.
    const third = reduceImage(ramp(3, 1), 2);
    expect([third.width, third.height]).toEqual([2, 1]);
    expect(third.rgb[0]).toBeCloseTo(0.5 / 1.5, 6);
    expect(third.rgb[3]).toBeCloseTo(2.5 / 1.5, 6);
  });

  it('keeps the light: a reduced image has the mean of the original, and a 2:1 image stays 2:1', () => {
    const w = 1536, h = 768, rgb = new Float32Array(w * h * 3);
    let seed = 7;
    for (let k = 0; k < rgb.length; k++) rgb[k] = (seed = (seed * 16807) % 2147483647) / 2147483647;
    const small = reduceImage({ width: w, height: h, rgb }, 512);
    expect([small.width, small.height]).toEqual([512, 256]);
    const mean = (a: Float32Array) => a.reduce((s, x) => s + x, 0) / a.length;
    expect(mean(small.rgb)).toBeCloseTo(mean(rgb), 5);
  });
});

describe('the edges of the read and the reduction', () => {
  /** w × h, green j² by row (not linear: an extrapolation from the wrong two rows shows), red the column. */
  const squares = (w: number, h: number): EnvironmentImage => {
    const rgb = new Float32Array(w * h * 3);
    for (let j = 0; j < h; j++) for (let i = 0; i < w; i++) rgb.set([i, j * j, 0], 3 * (j * w + i));
    return { width: w, height: h, rgb };
  };

  it('rows: the top and bottom held, between rows 2 and 3 their mean, one row and two rows read whole', () => {
    const img = squares(8, 4);
    expect(read(img, [0, 1, 0])[1]).toBe(0);
    expect(read(img, [0, -1, 0])[1]).toBe(9);
    // θ = 3π/4: v = ¾, y = 2.5: halfway between rows 2 and 3: (4 + 9)/2.
    expect(read(img, [Math.SQRT1_2, -Math.SQRT1_2, 0])[1]).toBeCloseTo(6.5, 9);
    // A direction a rounding past unit length: held, not NaN.
    expect(read(img, [0, 1 + 2e-16, 0])[1]).toBe(0);
    expect(read(img, [0, -1 - 2e-16, 0])[1]).toBe(9);
    const one = squares(8, 1);
    for (const y of [1, 0.3, -0.7, -1]) expect(read(one, [0, y, Math.sqrt(1 - y * y)])[1]).toBe(0);
    const two = squares(8, 2);
    expect(read(two, [0, -1, 0])[1]).toBe(1);
    expect(read(two, [1, 0, 0])[1]).toBeCloseTo(0.5, 12);
  });

  it('a tall image is reduced by its height: 4 × 8 at most 8 wide is 2 × 4', () => {
    const small = reduceImage(ramp(4, 8), 8);
    expect([small.width, small.height]).toEqual([2, 4]);
  });
});
