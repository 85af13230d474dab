// Shared assertions for the float64 math tests.
import { expect } from 'vitest';
import { vec4, type mat4 } from 'gl-matrix';

/** Every component of `actual` within `eps` of `expected` (same length). */
export function expectClose(actual: ArrayLike<number>, expected: ArrayLike<number>, eps = 1e-12): void {
  expect(actual.length).toBe(expected.length);
  for (let i = 0; i < expected.length; i++) {
    expect(Math.abs(actual[i] - expected[i]), `component ${i}: ${actual[i]} vs ${expected[i]}`).toBeLessThanOrEqual(eps);
  }
}

/** m · (p, 1), undivided: affine matrices keep w = 1. */
export function apply(m: ArrayLike<number>, p: ArrayLike<number>): Float64Array {
  const out = new Float64Array(4);
  vec4.transformMat4(out as unknown as vec4, [p[0], p[1], p[2], 1], m as mat4);
  return out;
}
