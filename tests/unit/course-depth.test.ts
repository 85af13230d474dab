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

describe('courseSceneRange: each kind of object, seen obliquely', () => {
  const R3 = Math.sqrt(3), R2 = Math.SQRT2;
  const still = { rotation: [0, 0, 0] as Vec3, scale: [1, 1, 1] as Vec3, spin: 0 };

  it('a mesh: the vertices its faces use (each once), through T · Rz · Rx · S', () => {
    // Camera at the origin looking along (1, 1, −1)/√3: depth = (x + y − z)/√3.
    // S (2, 1, 1), Rx 90° (x, y, z) → (x, −z, y), Rz 90° (x, y, z) → (−y, x, z), T (0, 0, −10):
    // (1, 0, 0) → (0, 2, −10): 12; (0, 2, 0) → (0, 0, −8): 8; (0, 0, 3) → (3, 0, −10): 13.
    // The unused (100, 100, 100) would be at (100, 200, 90): 210.
    const cam = camera([0, 0, 0], [1, 1, -1]);
    const data = {
      positions: new Float32Array([1, 0, 0, 0, 2, 0, 0, 0, 3, 100, 100, 100]),
      normals: new Float32Array(12), uvs: new Float32Array(8), indices: new Uint16Array([0, 1, 2, 2, 1, 0]),
    };
    const range = courseSceneRange(cam, scene([{
      geometry: { kind: 'mesh', key: 'm', data }, transform: { position: [0, 0, -10], rotation: [90, 0, 90], scale: [2, 1, 1], spin: 0 },
    }], null), 0);
    expect(range.near).toBeCloseTo((8 / R3) * 0.999, 12);
    expect(range.far).toBeCloseTo((13 / R3) * 1.001, 12);
  });

  it('a Gaussian: its bounding box, x and z in ±2, y from e⁻⁸ to 1', () => {
    // Along (1, 0, −1)/√2 from (−10, 0.5, 10): depth = (x − z + 20)/√2, x − z ∈ [−4, 4].
    const gaussian = (cam: CourseCamera) => courseSceneRange(cam, scene([{
      geometry: { kind: 'gaussian', resolution: 8 }, transform: { position: [0, 0, 0], ...still },
    }], null), 0);
    const side = gaussian(camera([-10, 0.5, 10], [-9, 0.5, 9]));
    expect(side.near).toBeCloseTo((16 / R2) * 0.999, 12);
    expect(side.far).toBeCloseTo((24 / R2) * 1.001, 12);
    // Along (0, −1, −1)/√2 from (0, 10, 10): depth = (20 − y − z)/√2, y + z ∈ [e⁻⁸ − 2, 3].
    const top = gaussian(camera([0, 10, 10], [0, 9, 9]));
    expect(top.near).toBeCloseTo((17 / R2) * 0.999, 12);
    expect(top.far).toBeCloseTo(((22 - Math.exp(-8)) / R2) * 1.001, 12);
  });

  it('a box\'s eight corners and a sphere\'s extremes along N, obliquely, with the glass\'s mirror images', () => {
    // Along (1, 1, −1)/√3 from (−5, −5, 5): depth = (x + y − z + 15)/√3. Box edge 2 at (1, 1, 1):
    // x + y − z ∈ [1 − 3, 1 + 3]: depths 13 and 19. No glass.
    const cam = camera([-5, -5, 5], [-4, -4, 4]);
    const box = courseSceneRange(cam, scene([{ geometry: { kind: 'box', size: 2 }, transform: { position: [1, 1, 1], ...still } }], null), 0);
    expect(box.near).toBeCloseTo((13 / R3) * 0.999, 12);
    expect(box.far).toBeCloseTo((19 / R3) * 1.001, 12);
    // A sphere r = 1 at (1, 1, 1): its centre at depth 16/√3, ± 1.
    const sphere = courseSceneRange(cam, scene([{ geometry: { kind: 'sphere', radius: 1 }, transform: { position: [1, 1, 1], ...still } }], null), 0);
    expect(sphere.near).toBeCloseTo((16 / R3 - 1) * 0.999, 12);
    expect(sphere.far).toBeCloseTo((16 / R3 + 1) * 1.001, 12);
    // With the glass z = 0 (corners x ∈ ±4, y ∈ −1..3): the box mirrored to z ∈ [−2, 0] gives
    // x + y − z up to 2 + 2 + 2 = 6: 21; the corners (4, 3, 0) 22, and (−4, −1, 0) the nearest: 10.
    const glassy = courseSceneRange(cam, scene([{ geometry: { kind: 'box', size: 2 }, transform: { position: [1, 1, 1], ...still } }], GLASS), 0);
    expect(glassy.near).toBeCloseTo((10 / R3) * 0.999, 12);
    expect(glassy.far).toBeCloseTo((22 / R3) * 1.001, 12);
    // A box farther off the glass: at (1, 1, 5), mirrored to z ∈ [−6, −4]: 2 + 2 + 6 + 15 = 25.
    const far = courseSceneRange(cam, scene([{ geometry: { kind: 'box', size: 2 }, transform: { position: [1, 1, 5], ...still } }], GLASS), 0);
    expect(far.far).toBeCloseTo((25 / R3) * 1.001, 12);
  });

  it('a camera looking away from everything, with a glass: far covers the mirror images behind it too', () => {
    // At (0, 1, 6) looking +Z: the sphere (r 0.5 at z = 4) 1.5..2.5 behind, the glass 6 behind;
    // mirrored, the sphere is at z = −4: 9.5..10.5 behind.
    const cam = camera([0, 1, 6], [0, 1, 7]);
    const range = courseSceneRange(cam, scene([{
      geometry: { kind: 'sphere', radius: 0.5 }, transform: { position: [0, 1, 4], ...still },
    }], GLASS), 0);
    expect(range.behind).toBe(true);
    expect(range.near).toBeCloseTo(1.5 * 0.999, 12);
    expect(range.far).toBeCloseTo(10.5 * 1.001, 12);
  });

  it('spin·time turns the object (time 2, not 1), and an angle that overflows turns it not at all', () => {
    // Box scale (3, 1, 1) at the origin, camera at (6, 1, 0) looking −X: depth = 6 − x.
    // spin π/4 for 2 s: a quarter turn, x ∈ ±0.5: 5.5..6.5. Overflow (1e308 · 2 = ∞): x ∈ ±1.5.
    const cam = camera([6, 1, 0], [0, 1, 0]);
    const box = (spin: number) => courseSceneRange(cam, scene([{
      geometry: { kind: 'box', size: 1 }, transform: { position: [0, 1, 0], rotation: [0, 0, 0], scale: [3, 1, 1], spin },
    }], null), 2);
    expect(box(Math.PI / 4).near).toBeCloseTo(5.5 * 0.999, 12);
    expect(box(Math.PI / 4).far).toBeCloseTo(6.5 * 1.001, 12);
    expect(box(1e308).near).toBeCloseTo(4.5 * 0.999, 12);
    expect(box(1e308).far).toBeCloseTo(7.5 * 1.001, 12);
  });
});
