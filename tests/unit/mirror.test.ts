// Mirror math: points, directions, the reflection matrix and the mirrored view (docs/rendering.md#pass-1-reflection).
import { describe, expect, it } from 'vitest';
import { apply, expectClose } from './helpers/math';
import { mat4, vec4 } from 'gl-matrix';
import { eyeRelativePlane, reflectDirection, reflectionMatrix, reflectPoint, signedDistance, type Plane } from '../../src/math/mirror';

const Z0: Plane = [0, 0, 1, 0];
// Unit normal (0.6, 0, 0.8), points with 0.6x + 0.8z = 2.
const OBLIQUE: Plane = [0.6, 0, 0.8, -2];
// Unit normal (2/3, 1/3, 2/3), offset 1.
const OBLIQUE2: Plane = [2 / 3, 1 / 3, 2 / 3, 1];

describe('reflectPoint', () => {
  it('mirrors across z = 0', () => {
    expectClose(reflectPoint(new Float64Array(3), [1, 2, 3], Z0), [1, 2, -3]);
    expectClose(reflectPoint(new Float64Array(3), [-4, 0.5, -0.25], Z0), [-4, 0.5, 0.25]);
  });

  it('mirrors across an oblique plane (hand-computed)', () => {
    // distance of (1,1,1) = 0.6 + 0.8 − 2 = −0.6 → p − 2(−0.6)n = (1.72, 1, 1.96)
    expectClose(reflectPoint(new Float64Array(3), [1, 1, 1], OBLIQUE), [1.72, 1, 1.96]);
    // origin is at distance 1 from OBLIQUE2 → −2n
    expectClose(reflectPoint(new Float64Array(3), [0, 0, 0], OBLIQUE2), [-4 / 3, -2 / 3, -4 / 3]);
  });

  it('negates the signed distance and keeps points on the plane fixed', () => {
    const p = [0.3, -7, 11] as const;
    const r = reflectPoint(new Float64Array(3), p, OBLIQUE);
    expect(signedDistance(OBLIQUE, r)).toBeCloseTo(-signedDistance(OBLIQUE, p), 12);
    const onPlane = [2 / 0.6 - (0.8 / 0.6) * 1, 5, 1] as const; // 0.6x + 0.8·1 = 2
    expectClose(reflectPoint(new Float64Array(3), onPlane, OBLIQUE), onPlane);
  });

  it('works with out aliasing the input', () => {
    const p = new Float64Array([1, 1, 1]);
    const r = reflectPoint(p, p, OBLIQUE);
    expect(r).toBe(p);
    expectClose(p, [1.72, 1, 1.96]);
  });

  it('reflecting twice is the identity', () => {
    const p = new Float64Array([-3.5, 2.25, 9]);
    const r = reflectPoint(new Float64Array(3), p, OBLIQUE2);
    expectClose(reflectPoint(new Float64Array(3), r, OBLIQUE2), p, 1e-12);
  });
});

describe('reflectDirection', () => {
  it('flips z across z = 0 and ignores the offset', () => {
    expectClose(reflectDirection(new Float64Array(3), [1, 2, 3], Z0), [1, 2, -3]);
    expectClose(reflectDirection(new Float64Array(3), [1, 2, 3], [0, 0, 1, 5]), [1, 2, -3]);
  });

  it('mirrors across an oblique plane (hand-computed)', () => {
    // d = +X: n·d = 0.6 → d − 1.2n = (0.28, 0, −0.96); the offset −2 plays no part.
    expectClose(reflectDirection(new Float64Array(3), [1, 0, 0], OBLIQUE), [0.28, 0, -0.96]);
  });

  it('works with out aliasing the input and round-trips', () => {
    const d = new Float64Array([0.2, -0.4, 0.9]);
    reflectDirection(d, d, OBLIQUE2);
    expect(Math.abs(d[0] - 0.2)).toBeGreaterThan(1e-3); // it did change
    reflectDirection(d, d, OBLIQUE2);
    expectClose(d, [0.2, -0.4, 0.9]);
  });
});

describe('eyeRelativePlane', () => {
  it('is sign·(n, n·eye + d): the oblique plane seen from eye (5, 1, 0), points relative to it', () => {
    // n·eye + d = 0.6·5 − 2 = 1: the eye stands 1 in front of the plane.
    const p = eyeRelativePlane(new Float64Array(4), OBLIQUE, [5, 1, 0], 1);
    expectClose(p, [0.6, 0, 0.8, 1]);
    expectClose(eyeRelativePlane(new Float64Array(4), OBLIQUE, [5, 1, 0], -1), [-0.6, 0, -0.8, -1]);
    // rel = (−5, 0, 2.5) is the point (0, 1, 2.5) on the plane: the value there is 0.
    expect(p[0] * -5 + p[2] * 2.5 + p[3]).toBeCloseTo(0, 14);
    // Eye (8, 1, 0): 0.6·8 − 2 = 2.8 in front; seen from the back, −2.8.
    expectClose(eyeRelativePlane(new Float64Array(4), OBLIQUE, [8, 1, 0], -1), [-0.6, 0, -0.8, -2.8]);
  });
});

describe('reflectionMatrix', () => {
  for (const [name, plane] of [['z = 0', Z0], ['oblique', OBLIQUE], ['oblique 2', OBLIQUE2]] as const) {
    it(`${name}: R·R = I and det R = −1`, () => {
      const r = reflectionMatrix(new Float64Array(16), plane);
      const rr = mat4.multiply(new Float64Array(16) as unknown as mat4, r as unknown as mat4, r as unknown as mat4);
      expectClose(rr, mat4.identity(new Float64Array(16) as unknown as mat4), 1e-12);
      expect(mat4.determinant(r as unknown as mat4)).toBeCloseTo(-1, 12);
    });

    it(`${name}: agrees with reflectPoint and reflectDirection`, () => {
      const r = reflectionMatrix(new Float64Array(16), plane);
      const p = [1.5, -2, 0.75] as const;
      const mp = apply(r, p);
      expectClose(mp.subarray(0, 3), reflectPoint(new Float64Array(3), p, plane));
      expect(mp[3]).toBe(1);
      const md = new Float64Array(4);
      vec4.transformMat4(md as unknown as vec4, [p[0], p[1], p[2], 0], r as unknown as mat4);
      expectClose(md.subarray(0, 3), reflectDirection(new Float64Array(3), p, plane));
    });
  }
});
