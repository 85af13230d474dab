// Small rules of src/scene checked against values by hand (or, for the turn's matrix, against
// gl-matrix's own quaternion rotation): a UV sphere's pole UVs, the index type's boundary, the
// mapping scale of empty bounds, an off-centre cylinder, the turn about a centre, boundsCenter at
// the edge of the doubles, and a turn by nothing giving back the very same value.
import { mat4, quat, vec3 } from 'gl-matrix';
import { describe, expect, it } from 'vitest';
import { boundsCenter, rotateLight, rotateScene } from '../../src/scene/group-rotation';
import { indexArray } from '../../src/scene/geometry/mesh-data';
import { sphereMesh } from '../../src/scene/geometry/sphere';
import { boundsScale, cylindricalUV } from '../../src/scene/mapping';
import { defaultScene, DEFAULT_LIGHT } from '../../src/scene/default-scene';
import type { SceneObject } from '../../src/scene/scene';
import { isIdentity, turnMatrix } from '../../src/scene/turn';
import { expectClose } from './helpers/math';

describe('sphereMesh UVs', () => {
  it('a pole\'s vertices take the middle of their quad column, (i + ½)/n, the last one 1; other rings i/n', () => {
    const n = 8, rings = 4;
    const m = sphereMesh(1, n);
    const u = (j: number, i: number) => m.uvs[2 * (j * (n + 1) + i)];
    for (let i = 0; i <= n; i++) {
      const pole = Math.min(i + 0.5, n) / n;
      expect(u(0, i)).toBeCloseTo(pole, 7);
      expect(u(rings, i)).toBeCloseTo(pole, 7);
      expect(u(1, i)).toBeCloseTo(i / n, 7);
      expect(u(rings - 1, i)).toBeCloseTo(i / n, 7);
    }
  });
});

describe('indexArray', () => {
  it('16-bit indices up to 65,535 vertices (the largest index 65,534), 32-bit above', () => {
    expect(indexArray(6, 65535)).toBeInstanceOf(Uint16Array);
    expect(indexArray(6, 65536)).toBeInstanceOf(Uint32Array);
    expect(indexArray(6, 65536).length).toBe(6);
  });
});

describe('mappings', () => {
  it('bounds of radius 0 or less map at scale 1', () => {
    expect(boundsScale({ center: [0, 0, 0], radius: 0 })).toBe(1);
    expect(boundsScale({ center: [0, 0, 0], radius: -2 })).toBe(1);
    expect(boundsScale({ center: [0, 0, 0], radius: 0.25 })).toBe(0.25);
  });

  it('cylindrical about an axis off the origin: x − c.x', () => {
    // Centre (3, 1, −2), r = 2: the point (4, 2, −2) is +X of the axis (u = ¾), 1 above (v = ½ + 1/4).
    expectClose(cylindricalUV([0, 0], [4, 2, -2], { center: [3, 1, -2], radius: 2 }), [0.75, 0.75]);
  });
});

describe('the turn about a centre', () => {
  it('isIdentity: only a quaternion with no vector part', () => {
    expect(isIdentity([0, 0, 0, 1])).toBe(true);
    expect(isIdentity([1, 0, 0, 0])).toBe(false);
    expect(isIdentity([0, 1, 0, 0])).toBe(false);
    expect(isIdentity([0, 0, 1, 0])).toBe(false);
  });

  it('turnMatrix(q, c) maps p to c + q·(p − c), as gl-matrix rotates', () => {
    // In float64 throughout (gl-matrix's create() makes float32).
    const f64 = <T>(...xs: number[]) => new Float64Array(xs) as unknown as T;
    const q = quat.normalize(f64<quat>(0, 0, 0, 0), f64<quat>(0.3, -0.5, 0.2, 0.79));
    const c = [1.5, -2, 3.25];
    const m = turnMatrix(new Float64Array(16) as unknown as mat4, q, c);
    for (const p of [[0, 0, 0], [1, 2, 3], [-4, 0.5, 7]]) {
      const got = vec3.transformMat4(f64<vec3>(0, 0, 0), f64<vec3>(p[0], p[1], p[2]), m);
      const rel = vec3.transformQuat(f64<vec3>(0, 0, 0), f64<vec3>(p[0] - c[0], p[1] - c[1], p[2] - c[2]), q);
      expectClose(Array.from(got), [rel[0] + c[0], rel[1] + c[1], rel[2] + c[2]], 1e-12);
    }
  });
});

describe('boundsCenter and turns by nothing', () => {
  const at = (x: number, radius = 0): SceneObject => ({
    ...defaultScene(0, 0).objects[1], transform: { position: [x, 0, 0], rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0 },
    bounds: { center: [0, 0, 0], radius },
  });

  it('the box\'s middle even where its width overflows a double (−1e308 … 1.5e308: 0.25e308)', () => {
    expectClose(Array.from(boundsCenter([at(-1e308), at(1.5e308)], new Float64Array(3))), [0.25e308, 0, 0]);
    expect(Array.from(boundsCenter([], [7, 7, 7]))).toEqual([0, 0, 0]);
  });

  it('a turn by the identity gives back the same light and the same scene, not copies', () => {
    const none = [0, 0, 0, 1] as const;
    expect(rotateLight(DEFAULT_LIGHT, none, [1, 2, 3])).toBe(DEFAULT_LIGHT);
    const scene = defaultScene(0.75, 0);
    expect(rotateScene(scene, none, none)).toBe(scene);
    // Turning only the light leaves the objects' values as they were.
    const s = Math.SQRT1_2;
    const lit = rotateScene(scene, none, [0, s, 0, s]);
    expect(lit).not.toBe(scene);
    expect(lit.objects).toBe(scene.objects);
  });
});
