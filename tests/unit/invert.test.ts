// invert4 (math/invert.ts): rough glass's inverse of the eye-relative view-projection, tied down
// by inverses worked out by hand, M·M⁻¹ = I on random matrices, and singular matrices refused.
import { describe, expect, it } from 'vitest';
import { mat4 } from 'gl-matrix';
import { invert4 } from '../../src/math/invert';

/** Column-major 4×4 from rows, as written on paper. */
const rows = (...r: number[][]) => Array.from({ length: 16 }, (_, i) => r[i % 4][Math.floor(i / 4)]);

function product(a: ArrayLike<number>, b: ArrayLike<number>): number[] {
  const out: number[] = [];
  for (let c = 0; c < 4; c++) for (let r = 0; r < 4; r++) {
    let s = 0;
    for (let k = 0; k < 4; k++) s += a[k * 4 + r] * b[c * 4 + k];
    out.push(s);
  }
  return out;
}

describe('invert4', () => {
  it('inverts a scale and translation worked by hand', () => {
    // x' = 2x + 1, y' = 4y + 2, z' = 5z + 3 → x = (x' − 1)/2, y = (y' − 2)/4, z = (z' − 3)/5.
    const out = new Float64Array(16);
    expect(invert4(out, rows([2, 0, 0, 1], [0, 4, 0, 2], [0, 0, 5, 3], [0, 0, 0, 1]))).toBe(true);
    const want = rows([0.5, 0, 0, -0.5], [0, 0.25, 0, -0.5], [0, 0, 0.2, -0.6], [0, 0, 0, 1]);
    for (let i = 0; i < 16; i++) expect(out[i], `entry ${i}`).toBeCloseTo(want[i], 15);
  });

  it('inverts a matrix with every entry in play, worked by hand', () => {
    // det down the first column: 1·1 − 5·(2·3·4) = −119; the inverse is the adjugate over −119
    // (by exact elimination in fractions: every entry an integer over −119).
    const m = rows([1, 2, 0, 0], [0, 1, 3, 0], [0, 0, 1, 4], [5, 0, 0, 1]);
    const out = new Float64Array(16);
    expect(invert4(out, m)).toBe(true);
    const inv = rows(
      [1, -2, 6, -24],
      [-60, 1, -3, 12],
      [20, -40, 1, -4],
      [-5, 10, -30, 1],
    ).map((x) => x / -119);
    for (let i = 0; i < 16; i++) expect(out[i], `entry ${i}`).toBeCloseTo(inv[i], 14);
  });

  it('inverts a perspective projection: the near plane back to z = −near', () => {
    const p = mat4.perspective(mat4.create(), 0.8, 16 / 9, 0.1, 100) as unknown as Float64Array;
    const out = new Float64Array(16);
    expect(invert4(out, p)).toBe(true);
    // NDC (0, 0, −1, 1) is the near plane's centre: (0, 0, −0.1) after the divide.
    const x = [out[12] - out[8], out[13] - out[9], out[14] - out[10], out[15] - out[11]];
    expect(x[0] / x[3]).toBeCloseTo(0, 12);
    expect(x[2] / x[3]).toBeCloseTo(-0.1, 12);
  });

  it('gives M·M⁻¹ = I and M⁻¹·M = I on random matrices, and agrees with gl-matrix', () => {
    let seed = 7;
    const rand = () => ((seed = (seed * 16807) % 2147483647) / 2147483647) * 4 - 2;
    for (let n = 0; n < 200; n++) {
      const m = Array.from({ length: 16 }, rand);
      const out = new Float64Array(16);
      expect(invert4(out, m)).toBe(true);
      const i1 = product(m, out), i2 = product(out, m);
      for (let k = 0; k < 16; k++) {
        const want = k % 5 === 0 ? 1 : 0;
        expect(Math.abs(i1[k] - want), `M·M⁻¹ ${n}:${k}`).toBeLessThan(1e-9);
        expect(Math.abs(i2[k] - want), `M⁻¹·M ${n}:${k}`).toBeLessThan(1e-9);
      }
      const g = mat4.invert(new Float64Array(16) as unknown as mat4, m as unknown as mat4)!;
      for (let k = 0; k < 16; k++) expect(Math.abs(out[k] - g[k]), `gl-matrix ${n}:${k}`).toBeLessThanOrEqual(1e-12 * Math.max(1, Math.abs(g[k])));
    }
  });

  it('refuses a singular matrix and leaves out untouched', () => {
    const out = new Float64Array(16).fill(9);
    expect(invert4(out, rows([1, 2, 3, 4], [2, 4, 6, 8], [0, 1, 0, 1], [1, 0, 1, 0]))).toBe(false);
    expect(invert4(out, new Float64Array(16))).toBe(false);
    expect([...out]).toEqual(new Array(16).fill(9));
  });
});
