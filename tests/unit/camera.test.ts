// Camera pose → forward, view and projection (docs/default-scene.md#the-camera).
import { describe, expect, it } from 'vitest';
import { apply, expectClose } from './helpers/math';
import {
  clampPitch, forwardFromYawPitch, PITCH_LIMIT, projectionMatrix, rotationOnlyView, setPose, tanHalfFov, viewerSide, wrapYaw,
  type CameraPose,
} from '../../src/math/camera';

describe('forwardFromYawPitch', () => {
  it('yaw −90, pitch 0 looks down −Z', () => {
    expectClose(forwardFromYawPitch(new Float64Array(3), -90, 0), [0, 0, -1]);
  });

  it('yaw 0 looks down +X, yaw 90 down +Z, yaw 180 down −X', () => {
    expectClose(forwardFromYawPitch(new Float64Array(3), 0, 0), [1, 0, 0]);
    expectClose(forwardFromYawPitch(new Float64Array(3), 90, 0), [0, 0, 1]);
    expectClose(forwardFromYawPitch([0, 0, 0], 180, 0), [-1, 0, 0]);
  });

  it('pitch 30 tilts up by sin 30 and stays unit length', () => {
    const f = forwardFromYawPitch(new Float64Array(3), -90, 30);
    expectClose(f, [0, 0.5, -Math.sqrt(3) / 2]);
    expect(Math.hypot(f[0], f[1], f[2])).toBeCloseTo(1, 14);
  });

  it('clamps pitch before use', () => {
    const f = forwardFromYawPitch(new Float64Array(3), -90, 120);
    expect(f[1]).toBeCloseTo(Math.sin((PITCH_LIMIT * Math.PI) / 180), 14);
    expect(f[2]).toBeLessThan(0);
  });
});

describe('tanHalfFov', () => {
  it('is half the view height at unit depth: 90° → 1, 60° → 1/√3, 120° → √3', () => {
    expect(tanHalfFov(90)).toBeCloseTo(1, 15);
    expect(tanHalfFov(60)).toBeCloseTo(1 / Math.sqrt(3), 15);
    expect(tanHalfFov(120)).toBeCloseTo(Math.sqrt(3), 14);
  });
});

describe('wrapYaw', () => {
  it('wraps into [−180, 180): 180 and −180 both become −180, 179.5 stays', () => {
    expect(wrapYaw(180)).toBe(-180);
    expect(wrapYaw(-180)).toBe(-180);
    expect(wrapYaw(540)).toBe(-180);
    expect(wrapYaw(179.5)).toBe(179.5);
    expect(wrapYaw(-179.5)).toBe(-179.5);
    expect(wrapYaw(370)).toBe(10);
    expect(wrapYaw(-190)).toBe(170);
    expect(wrapYaw(-90)).toBe(-90);
  });
});

describe('clampPitch', () => {
  it('clamps to ±89.9 and passes values inside', () => {
    expect(PITCH_LIMIT).toBe(89.9);
    expect(clampPitch(95)).toBe(89.9);
    expect(clampPitch(-1000)).toBe(-89.9);
    expect(clampPitch(45)).toBe(45);
    expect(clampPitch(-89.9)).toBe(-89.9);
  });
});

describe('rotationOnlyView', () => {
  const cases = [
    { yaw: -90, pitch: 0 },
    { yaw: -120, pitch: -8 },
    { yaw: 37, pitch: 60 },
    { yaw: 179, pitch: -89.9 },
  ] as const;

  for (const { yaw, pitch } of cases) {
    it(`maps forward to (0,0,−1) and keeps the origin: ${yaw} ${pitch}`, () => {
      const view = rotationOnlyView(new Float64Array(16), yaw, pitch, new Float64Array(3));
      expectClose(apply(view, [0, 0, 0]), [0, 0, 0, 1], 1e-12);
      const f = forwardFromYawPitch(new Float64Array(3), yaw, pitch);
      expectClose(apply(view, f), [0, 0, -1, 1], 1e-12);
    });
  }

  it('keeps world up in the upper half of the view (no roll)', () => {
    const view = rotationOnlyView(new Float64Array(16), -90, 0, new Float64Array(3));
    expectClose(apply(view, [0, 1, 0]), [0, 1, 0, 1]);
    expectClose(apply(view, [1, 0, 0]), [1, 0, 0, 1]); // +X is to the right looking down −Z
  });
});

describe('projectionMatrix', () => {
  const near = 0.1;
  const far = 100;
  const proj = projectionMatrix(new Float64Array(16), 60, 16 / 9, near, far);
  const ndcZ = (z: number) => {
    const c = apply(proj, [0, 0, z]);
    return c[2] / c[3];
  };

  it('maps the near plane to z_ndc = −1 and the far plane to +1', () => {
    expect(ndcZ(-near)).toBeCloseTo(-1, 12);
    expect(ndcZ(-far)).toBeCloseTo(1, 9);
    expect(ndcZ(-1)).toBeGreaterThan(-1);
    expect(ndcZ(-1)).toBeLessThan(1);
  });

  it('puts the top of the vertical fov at y_ndc = 1 and respects the aspect', () => {
    const z = -5;
    const h = -z * Math.tan((30 * Math.PI) / 180);
    const top = apply(proj, [0, h, z]);
    expect(top[1] / top[3]).toBeCloseTo(1, 12);
    const right = apply(proj, [h * (16 / 9), 0, z]);
    expect(right[0] / right[3]).toBeCloseTo(1, 12);
  });
});

describe('setPose', () => {
  it('copies a pose in: yaw wrapped, pitch clamped', () => {
    const p: CameraPose = { position: [0, 0, 0], yaw: 0, pitch: 0 };
    setPose(p, [1, -2, 3.5], 190, 95);
    expect(p).toEqual({ position: [1, -2, 3.5], yaw: -170, pitch: PITCH_LIMIT });
  });

  it('a non-finite component leaves the old value, each on its own', () => {
    const p: CameraPose = { position: [1, 2, 3], yaw: 10, pitch: 20 };
    setPose(p, [NaN, 5, Infinity], NaN, -30);
    expect(p).toEqual({ position: [1, 5, 3], yaw: 10, pitch: -30 });
    setPose(p, [7, -Infinity, 8], 45, NaN);
    expect(p).toEqual({ position: [7, 5, 8], yaw: 45, pitch: -30 });
  });
});

describe('viewerSide', () => {
  // The plane through the origin with unit normal (0, 0.6, 0.8); the eye 5 behind it (−5·n), so
  // only the orthographic rule can answer +1.
  const plane = [0, 0.6, 0.8, 0] as const;
  const behind = [0, -3, -4] as const;

  it('orthographic: the side −forward points to, wherever the eye is', () => {
    // n·f = 0.6·0.5 + 0.8·(−0.625) = 0.3 − 0.5 = −0.2 < 0: the camera sees the normal's side.
    expect(viewerSide(plane, behind, [0, 0.5, -0.625], 'orthographic')).toBe(1);
    // The same with the axes' roles swapped: n·f = 0.8·(−0.625) + 0.6·0.5 = −0.2.
    expect(viewerSide([0, 0.8, 0.6, 0], [0, -4, -3], [0, -0.625, 0.5], 'orthographic')).toBe(1);
    // Forward along the normal: the back, even with the eye in front.
    expect(viewerSide(plane, [0, 3, 4], [0, 0.6, 0.8], 'orthographic')).toBe(-1);
  });

  it('orthographic with forward in the plane, and perspective: the eye\'s side', () => {
    expect(viewerSide(plane, [0, 3, 4], [1, 0, 0], 'orthographic')).toBe(1);
    expect(viewerSide(plane, behind, [1, 0, 0], 'orthographic')).toBe(-1);
    expect(viewerSide(plane, behind, [0, 0.5, -0.625], 'perspective')).toBe(-1);
  });
});
