// Near and far for a course camera (src/scene/course-depth.ts), which the frame setup of both
// renderers and the float64 reference share: ranges worked out by hand, with the 0.1% margins
// of courseDepthRange (near·0.999, far·1.001).
import { describe, expect, it } from 'vitest';
import { courseBasis, type CourseCamera, type Vec3 } from '../../src/math/course-camera';
import { courseSceneRange } from '../../src/scene/course-depth';
import type { Scene, SceneObject } from '../../src/scene/scene';
import { DEFAULT_LIGHT } from '../../src/scene/default-scene';

function camera(c: Vec3, look: Vec3): CourseCamera {
  const basis = courseBasis([look[0] - c[0], look[1] - c[1], look[2] - c[2]], [0, 1, 0]);
  if (typeof basis === 'string') throw new Error(basis);
  return { c, ...basis, d: 1, hx: 1, hy: 1 };
}

const MATERIAL: SceneObject['material'] = {
  ambient: [0.2, 0.2, 0.2], diffuse: [0.8, 0.8, 0.8], specular: [0.5, 0.5, 0.5], shininess: 32, opacity: 1,
  texture: { kind: 'procedural' }, mapping: 'uv',
};

function scene(objects: Pick<SceneObject, 'geometry' | 'transform'>[], glass: Scene['glass']): Scene {
  return {
    glass, lights: [DEFAULT_LIGHT], background: [0, 0, 0],
    objects: objects.map((o) => ({ ...o, material: MATERIAL, bounds: { center: [0, 0, 0], radius: 1 } })),
  };
}

const GLASS: Scene['glass'] = { center: [0, 1, 0], normal: [0, 0, 1], size: [8, 4] };

describe('courseSceneRange', () => {
  it('a sphere before the glass: near from the sphere, far from its mirror image behind the glass', () => {
    // Camera at (0, 1, 6) looking down −Z: depth = 6 − z. Sphere r = 0.5 (scale 1) at z = 4:
    // depths 1.5 and 2.5; the glass corners 6; the sphere mirrored to z = −4: depths 9.5 and 10.5.
    const cam = camera([0, 1, 6], [0, 1, 0]);
    const range = courseSceneRange(cam, scene([{
      geometry: { kind: 'sphere', radius: 0.5 }, transform: { position: [0, 1, 4], rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0 },
    }], GLASS), 0);
    expect(range.behind).toBe(false);
    expect(range.near).toBeCloseTo(1.5 * 0.999, 12);
    expect(range.far).toBeCloseTo(10.5 * 1.001, 12);
  });

  it('a sphere scaled by (1, 2, 0.5) reaches radius × the largest scale along N', () => {
    // r = 0.5·2 = 1: depths 1 and 3 directly, 9 and 11 mirrored.
    const cam = camera([0, 1, 6], [0, 1, 0]);
    const range = courseSceneRange(cam, scene([{
      geometry: { kind: 'sphere', radius: 0.5 }, transform: { position: [0, 1, 4], rotation: [0, 0, 0], scale: [1, 2, 0.5], spin: 0 },
    }], GLASS), 0);
    expect(range.near).toBeCloseTo(1 * 0.999, 12);
    expect(range.far).toBeCloseTo(11 * 1.001, 12);
  });

  it('a long box rotated (0°, 90°, 90°): rotations applied X, then Y, then Z (docs/scene-model.md#glass-object)', () => {
    // Edge 1, scale (1, 1, 3): x, y ∈ ±0.5, z ∈ ±1.5. Ry(90°) takes z to x, then Rz(90°) takes x
    // to y: the long side ends up along Y and x stays within ±0.5. Camera at (6, 1, 0) looking
    // down −X: depth = 6 − x ∈ [5.5, 6.5]. (Z before Y would leave the long side along X: 4.5..7.5.)
    const cam = camera([6, 1, 0], [0, 1, 0]);
    const range = courseSceneRange(cam, scene([{
      geometry: { kind: 'box', size: 1 }, transform: { position: [0, 1, 0], rotation: [0, 90, 90], scale: [1, 1, 3], spin: 0 },
    }], null), 0);
    expect(range.near).toBeCloseTo(5.5 * 0.999, 12);
    expect(range.far).toBeCloseTo(6.5 * 1.001, 12);
  });

  it('spin turns the box about its own Y after the rotation: a quarter turn swaps x and z', () => {
    // scale (3, 1, 1): x ∈ ±1.5. spin·t = π/2 about Y takes x to −z: x ∈ ±0.5 again.
    const cam = camera([6, 1, 0], [0, 1, 0]);
    const box = (spin: number) => courseSceneRange(cam, scene([{
      geometry: { kind: 'box', size: 1 }, transform: { position: [0, 1, 0], rotation: [0, 0, 0], scale: [3, 1, 1], spin },
    }], null), 1);
    expect(box(0).near).toBeCloseTo(4.5 * 0.999, 12);
    expect(box(Math.PI / 2).near).toBeCloseTo(5.5 * 0.999, 12);
  });
});
