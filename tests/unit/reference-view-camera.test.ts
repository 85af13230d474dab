// The GPU camera as rays (src/reference/view-camera.ts): the basis from yaw and pitch, the perspective fan and the
// orthographic sheet of parallel rays, the course camera (and its looking-away form), each ray worked out by hand.
import { describe, expect, it } from 'vitest';
import { Ray } from '../../src/reference/ray';
import { ViewCamera } from '../../src/reference/view-camera';
import type { CourseCamera } from '../../src/math/course-camera';
import { defaultFrameState } from './helpers/frame-state';
import { expectClose } from './helpers/math';

const S3 = Math.sqrt(3) / 2;
/** tan 45° = 1 up to rounding: fov 90 gives half-height 1 at depth 1. */
const state = (over: Parameters<typeof defaultFrameState>[0] = {}) =>
  defaultFrameState({
    width: 200, height: 100, fov: 90, cameraPosition: [1, 2, 3], yaw: 0, pitch: 0, projection: 'perspective', courseCamera: null, target: null,
    ...over,
  });

/** A ray with every differential set, so that what rayThrough zeroes shows. */
function dirty(): Ray {
  const r = new Ray();
  for (const a of [r.origin, r.direction, r.ddx, r.ddy, r.odx, r.ody]) a.fill(9);
  return r;
}

describe('ViewCamera: the basis', () => {
  it('yaw 0, pitch 0 looks along +x with +z to the right', () => {
    const c = new ViewCamera(state());
    expect(c.orthographic).toBe(false);
    expectClose(c.eye, [1, 2, 3]);
    expectClose(c.forward, [1, 0, 0]);
    expectClose(c.right, [0, 0, 1]);
    expectClose(c.up, [0, 1, 0]);
  });

  it('pitch −30°: forward (cos 30°, −sin 30°, 0), up tilted towards it', () => {
    const c = new ViewCamera(state({ pitch: -30 }));
    expectClose(c.forward, [S3, -0.5, 0]);
    expectClose(c.right, [0, 0, 1]);
    expectClose(c.up, [0.5, S3, 0]);
  });

  it('yaw 90° looks along +z with −x to the right', () => {
    const c = new ViewCamera(state({ yaw: 90 }));
    expectClose(c.forward, [0, 0, 1]);
    expectClose(c.right, [-1, 0, 0]);
    expectClose(c.up, [0, 1, 0]);
  });
});

describe('ViewCamera: perspective rays', () => {
  it('from the eye through forward + x·tan(fov/2)·aspect·right + y·tan(fov/2)·up; differentials of the direction only', () => {
    // Aspect 2, fov 90: NDC x scales by 2, y by 1. Pitch −30°: f = (√3/2, −½, 0), r = (0, 0, 1), u = (½, √3/2, 0).
    const c = new ViewCamera(state({ pitch: -30 }));
    const r = dirty();
    expect(c.rayThrough(r, 0.5, -0.25, 0.1, 0.2)).toBe(r);
    expectClose(r.origin, [1, 2, 3]);
    // f + 1·r − 0.25·u
    expectClose(r.direction, [S3 - 0.125, -0.5 - 0.25 * S3, 1]);
    // ∂/∂x = 0.1·2·r; ∂/∂row = −0.2·1·u.
    expectClose(r.ddx, [0, 0, 0.2]);
    expectClose(r.ddy, [-0.1, -0.2 * S3, 0]);
    expect([...r.odx, ...r.ody]).toEqual([0, 0, 0, 0, 0, 0]);
  });

  it('the aspect is width / max(1, height)', () => {
    const wide = new ViewCamera(state({ width: 3, height: 0 }));
    const r = wide.rayThrough(new Ray(), 1, 1, 0, 0);
    // aspect 3: direction f + 3·r + 1·u.
    expectClose(r.direction, [1, 1, 3]);
    const square = new ViewCamera(state({ width: 50, height: 50 }));
    expectClose(square.rayThrough(new Ray(), 1, -1, 0, 0).direction, [1, -1, 1]);
  });

  it('a narrower fov: tan(30°) per NDC unit', () => {
    const t = Math.tan(Math.PI / 6);
    const c = new ViewCamera(state({ fov: 60, width: 100, height: 100 }));
    expectClose(c.rayThrough(new Ray(), 1, 0.5, 0, 0).direction, [1, 0.5 * t, t]);
  });
});

describe('ViewCamera: orthographic rays', () => {
  it('parallel to forward from origins over the view rectangle; the glass centre sizes it', () => {
    // Eye (1, 2, 3) looking along +x; glass centre (6, 2, 3): depth 5, half-height 5·tan 45° = 5, half-width 10.
    const c = new ViewCamera(state({ projection: 'orthographic' }), [6, 2, 3]);
    expect(c.orthographic).toBe(true);
    const r = dirty();
    c.rayThrough(r, 0.5, -0.25, 0.1, 0.2);
    // eye + 0.5·10·r − 0.25·5·u
    expectClose(r.origin, [1, 2 - 1.25, 3 + 5]);
    expectClose(r.direction, [1, 0, 0]);
    // ∂origin/∂x = 0.1·10·r, ∂origin/∂row = −0.2·5·u; no spread of the direction.
    expectClose(r.odx, [0, 0, 1]);
    expectClose(r.ody, [0, -1, 0]);
    expect([...r.ddx, ...r.ddy]).toEqual([0, 0, 0, 0, 0, 0]);
  });

  it('without a glass the origin sizes it, and a target before either', () => {
    // Origin at depth −1 from the eye along +x: clamped to the near 0.1, half-height 0.1.
    const none = new ViewCamera(state({ projection: 'orthographic' }));
    expectClose(none.rayThrough(new Ray(), 0, 1, 0, 0).origin, [1, 2.1, 3]);
    const far = new ViewCamera(state({ projection: 'orthographic', cameraPosition: [-3, 2, 3] }));
    expectClose(far.rayThrough(new Ray(), 0, 1, 0, 0).origin, [-3, 5, 3]);
    const target = new ViewCamera(state({ projection: 'orthographic', target: [3, 0, 0] }), [6, 2, 3]);
    expectClose(target.rayThrough(new Ray(), 0, 1, 0, 0).origin, [1, 4, 3]);
  });
});

describe('ViewCamera: the course camera', () => {
  // Eye (1, 2, 3) looking along −z, U = +x, V = +y, d = 2, hx = 0.5, hy = 0.25: NDC x steps 0.25·U, y 0.125·V.
  const cam: CourseCamera = { c: [1, 2, 3], n: [0, 0, -1], u: [1, 0, 0], v: [0, 1, 0], d: 2, hx: 0.5, hy: 0.25 };

  it('N + x·(hx/d)·U + y·(hy/d)·V from C, whatever the view state says', () => {
    const c = new ViewCamera(state({ courseCamera: cam, projection: 'orthographic', yaw: 40 }));
    expect(c.orthographic).toBe(false);
    expectClose(c.eye, [1, 2, 3]);
    expectClose(c.forward, [0, 0, -1]);
    expectClose(c.right, [0.25, 0, 0]);
    expectClose(c.up, [0, 0.125, 0]);
    const r = dirty();
    c.rayThrough(r, 0.4, -0.8, 0.1, 0.2);
    expectClose(r.origin, [1, 2, 3]);
    expectClose(r.direction, [0.1, -0.1, -1]);
    expectClose(r.ddx, [0.025, 0, 0]);
    expectClose(r.ddy, [0, -0.025, 0]);
    expect([...r.odx, ...r.ody]).toEqual([0, 0, 0, 0, 0, 0]);
    const withRange = new ViewCamera(state({ courseCamera: cam }), null, { near: 1, far: 2, behind: false });
    expectClose(withRange.forward, [0, 0, -1]);
  });

  it('looking away (behind): the same NDC along the opposite direction', () => {
    const c = new ViewCamera(state({ courseCamera: cam }), null, { near: 1, far: 2, behind: true });
    expectClose(c.forward, [0, 0, 1]);
    expectClose(c.right, [-0.25, 0, 0]);
    expectClose(c.up, [0, -0.125, 0]);
    expectClose(c.rayThrough(new Ray(), 0.4, -0.8, 0, 0).direction, [-0.1, 0.1, 1]);
  });
});
