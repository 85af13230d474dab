// CourseProjection (src/frame/course-projection.ts): near and far are a walk over every vertex,
// so they are kept while the camera, the scene value, the clock (when something spins) and the
// trackball's turn stay, and worked out again when any of them changes; and the winding a
// negative half-size or a camera looking away mirrors.
import { describe, expect, it } from 'vitest';
import { CourseProjection, type CourseProjectionTarget } from '../../src/frame/course-projection';
import { courseBasis, type CourseCamera, type Vec3 } from '../../src/math/course-camera';
import { courseSceneRange } from '../../src/scene/course-depth';
import { defaultScene } from '../../src/scene/default-scene';
import type { Scene } from '../../src/scene/scene';
import type { SceneTurn } from '../../src/scene/turn';

function camera(c: Vec3, look: Vec3, hx = 1, hy = 1): CourseCamera {
  const basis = courseBasis([look[0] - c[0], look[1] - c[1], look[2] - c[2]], [0, 1, 0]);
  if (typeof basis === 'string') throw new Error(basis);
  return { c, ...basis, d: 1, hx, hy };
}
const target = (): CourseProjectionTarget => ({ viewProjection: new Float64Array(16), projection: new Float64Array(16), mirrorsWinding: false, courseRange: null });
const CAM = camera([0, 1, 6], [0, 1, 0]);
const still = (): Scene => defaultScene(0.75, 0);
const turn = (objects: number[]): SceneTurn => ({ objects: objects as unknown as SceneTurn['objects'], light: [0, 0, 0, 1], center: [0, 1, 0] });

describe('CourseProjection: when near and far are worked out again', () => {
  it('kept while camera, scene and turn stay; a still scene keeps them as the clock runs', () => {
    const p = new CourseProjection(), out = target(), scene = still();
    p.apply(out, CAM, scene, 0, null);
    const first = out.courseRange;
    expect(first).toEqual(courseSceneRange(CAM, scene, 0));
    p.apply(out, CAM, scene, 0, null);
    expect(out.courseRange).toBe(first);
    p.apply(out, CAM, scene, 5, null);
    expect(out.courseRange).toBe(first);
  });

  it('a spinning object: a new range when the clock moves', () => {
    const p = new CourseProjection(), out = target(), scene = defaultScene(0.75, 0.8);
    p.apply(out, CAM, scene, 0, null);
    const first = out.courseRange;
    p.apply(out, CAM, scene, 0, null);
    expect(out.courseRange).toBe(first);
    p.apply(out, CAM, scene, 1, null);
    expect(out.courseRange).not.toBe(first);
    expect(out.courseRange).toEqual(courseSceneRange(CAM, scene, 1));
  });

  it('another scene value or another camera: worked out again', () => {
    const p = new CourseProjection(), out = target(), scene = still();
    p.apply(out, CAM, scene, 0, null);
    const first = out.courseRange;
    p.apply(out, CAM, still(), 0, null);
    expect(out.courseRange).not.toBe(first);
    const second = out.courseRange;
    const other = camera([0, 1, 8], [0, 1, 0]);
    p.apply(out, other, still(), 0, null);
    expect(out.courseRange).not.toBe(second);
  });

  it('the trackball\'s turn: each of its four components changing is a new turn; the same turn keeps', () => {
    const p = new CourseProjection(), out = target(), scene = still();
    const base = [0.1, 0.2, 0.3, 0.927];
    p.apply(out, CAM, scene, 0, turn(base));
    let last = out.courseRange;
    expect(last).toEqual(courseSceneRange(CAM, scene, 0, turn(base)));
    p.apply(out, CAM, scene, 0, turn([...base]));
    expect(out.courseRange).toBe(last);
    for (let k = 0; k < 4; k++) {
      const q = [...base];
      q[k] += 0.05;
      p.apply(out, CAM, scene, 0, turn(q));
      expect(out.courseRange, `component ${k}`).not.toBe(last);
      last = out.courseRange;
      p.apply(out, CAM, scene, 0, turn(base));
      expect(out.courseRange).not.toBe(last);
      last = out.courseRange;
    }
    // No turn after a turn: the identity, a change too.
    p.apply(out, CAM, scene, 0, null);
    expect(out.courseRange).not.toBe(last);
  });
});

describe('CourseProjection: mirrored winding', () => {
  it('one negative half-size mirrors, two do not; looking away flips that again', () => {
    const winding = (cam: CourseCamera) => {
      const out = target();
      new CourseProjection().apply(out, cam, still(), 0, null);
      return out.mirrorsWinding;
    };
    expect(winding(camera([0, 1, 6], [0, 1, 0], 1, 1))).toBe(false);
    expect(winding(camera([0, 1, 6], [0, 1, 0], -1, 1))).toBe(true);
    expect(winding(camera([0, 1, 6], [0, 1, 0], 1, -1))).toBe(true);
    expect(winding(camera([0, 1, 6], [0, 1, 0], -1, -1))).toBe(false);
    // Looking away from everything (+Z from z = 6): the picture is mirrored by z < 0.
    expect(winding(camera([0, 1, 6], [0, 1, 7], 1, 1))).toBe(true);
    expect(winding(camera([0, 1, 6], [0, 1, 7], -1, 1))).toBe(false);
  });
});
