// Shared assertions for the float64 math tests.
import { expect } from 'vitest';
import { mat4, vec4 } from 'gl-matrix';
import { projectionMatrix } from '../../../src/math/camera';

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

/** The default camera's view matrix (docs/default-scene.md#the-camera), lookAt(position, position + forward, +Y), for tests that need a whole camera. */
export function lookAtView(position: readonly [number, number, number] | ArrayLike<number>, yaw: number, pitch: number): Float64Array {
  const d = Math.PI / 180;
  const f = [Math.cos(pitch * d) * Math.cos(yaw * d), Math.sin(pitch * d), Math.cos(pitch * d) * Math.sin(yaw * d)];
  const eye = [position[0], position[1], position[2]] as [number, number, number];
  const out = new Float64Array(16);
  mat4.lookAt(out as unknown as mat4, eye, [eye[0] + f[0], eye[1] + f[1], eye[2] + f[2]], [0, 1, 0]);
  return out;
}

/** A camera as the reference takes it: size, fov, position, yaw and pitch (degrees). */
export interface PixelCamera {
  width: number;
  height: number;
  fov: number;
  cameraPosition: ArrayLike<number>;
  yaw: number;
  pitch: number;
}

/** Pixel coordinates (x right, y down, pixel centres at +0.5) where the camera projects `p`. */
export function projectToPixels(s: PixelCamera, p: ArrayLike<number>): [number, number] {
  const view = lookAtView(s.cameraPosition, s.yaw, s.pitch);
  const proj = projectionMatrix(new Float64Array(16), s.fov, s.width / s.height, 0.1, 100);
  const c = new Float64Array(4);
  vec4.transformMat4(c as unknown as vec4, [p[0], p[1], p[2], 1], view as unknown as mat4);
  vec4.transformMat4(c as unknown as vec4, c as unknown as vec4, proj as unknown as mat4);
  return [((c[0] / c[3] + 1) / 2) * s.width, ((1 - c[1] / c[3]) / 2) * s.height];
}
