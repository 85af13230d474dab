// Triangle meshes in the reference (src/reference/mesh-tracer.ts): the nearest kept triangle, its point, the geometric
// and the interpolated (viewer-facing) normals, UVs and their gradients, checked against the triangle's own geometry
// (points built from barycentric weights; a UV gradient is the vector g with g·e1 = Δu1, g·e2 = Δu2 in the plane).
import { describe, expect, it } from 'vitest';
import { bvhOf, MeshTracer } from '../../src/reference/mesh-tracer';
import { ObjectFrame } from '../../src/reference/object-frame';
import { Ray } from '../../src/reference/ray';
import { SurfaceHit } from '../../src/reference/surface-hit';
import type { MeshData } from '../../src/scene/geometry/mesh-data';
import type { Transform } from '../../src/scene/scene';
import { expectClose } from './helpers/math';

type V = [number, number, number];
const sub = (a: ArrayLike<number>, b: ArrayLike<number>): V => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a: ArrayLike<number>, b: ArrayLike<number>) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a: ArrayLike<number>, b: ArrayLike<number>): V => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const scale = (a: ArrayLike<number>, k: number): V => [a[0] * k, a[1] * k, a[2] * k];
const unit = (a: ArrayLike<number>): V => scale(a, 1 / Math.hypot(a[0], a[1], a[2]));
const mix = (w: number[], vs: V[]): V => [0, 1, 2].map((k) => w[0] * vs[0][k] + w[1] * vs[1][k] + w[2] * vs[2][k]) as V;

const frame = (over: Partial<Transform> = {}) =>
  new ObjectFrame({ position: [0, 0, 0], rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0, ...over }, 0);

function ray(o: ArrayLike<number>, d: ArrayLike<number>): Ray {
  const r = new Ray();
  r.origin.set(o);
  r.direction.set(d);
  return r;
}

/** A tilted triangle with normals and UVs of its own at each corner. */
const P: V[] = [[0.3, -0.2, 0.1], [2.1, 0.4, -0.5], [0.5, 1.7, 0.9]];
const NORMALS: V[] = [[0.1, 0.2, 0.97], [0.5, -0.1, 0.8], [-0.3, 0.4, 0.85]];
const UVS: [number, number][] = [[0.1, 0.2], [0.9, 0.3], [0.4, 0.8]];
function triangle(over: Partial<MeshData> = {}): MeshData {
  return {
    positions: new Float32Array(P.flat()), normals: new Float32Array(NORMALS.flat()), uvs: new Float32Array(UVS.flat()),
    indices: new Uint16Array([0, 1, 2]), ...over,
  };
}
/** The corners as float32 stores them. */
const corners = (m: MeshData): V[] => [0, 1, 2].map((i) => [m.positions[3 * i], m.positions[3 * i + 1], m.positions[3 * i + 2]]);

/** Checks g·e1 = d1, g·e2 = d2 (and g in the plane, when `inPlane`). */
function expectGradient(g: ArrayLike<number>, e1: V, e2: V, d1: number, d2: number, n: V | null) {
  expect(dot(g, e1)).toBeCloseTo(d1, 6);
  expect(dot(g, e2)).toBeCloseTo(d2, 6);
  if (n) expect(dot(g, n)).toBeCloseTo(0, 6);
}

describe('MeshTracer: one tilted triangle', () => {
  const W = [0.2, 0.5, 0.3];
  const D: V = [0.1, -0.2, -1];

  it('the hit at barycentric weights (0.2, 0.5, 0.3): point, t, normals, UVs and gradients', () => {
    const mesh = triangle();
    const f = frame();
    const tracer = new MeshTracer(f, mesh, 2, 5);
    const [v0, v1, v2] = corners(mesh);
    const p = mix(W, [v0, v1, v2]);
    const hit = new SurfaceHit();
    expect(tracer.hit(ray(sub(p, scale(D, 3)), D), 0, 0, null, hit)).toBe(true);
    expect([hit.surface, hit.object]).toEqual([5, 2]);
    expect(hit.frame).toBe(f);
    expect(hit.t).toBeCloseTo(3, 6);
    expectClose(hit.p, p, 1e-6);
    expectClose(hit.q, p, 1e-6);
    const e1 = sub(v1, v0), e2 = sub(v2, v0), N = cross(e1, e2);
    expectClose(hit.ng, unit(N), 1e-12);
    const nq = unit(mix(W, NORMALS.map((_, i) => [mesh.normals[3 * i], mesh.normals[3 * i + 1], mesh.normals[3 * i + 2]] as V)));
    expectClose(hit.nq, nq, 1e-6);
    // Seen from the side N points to (D·N < 0): the shading normal as interpolated.
    expect(dot(D, N)).toBeLessThan(0);
    expectClose(hit.n, nq, 1e-6);
    const uv = [0, 1, 2].map((i) => [mesh.uvs[2 * i], mesh.uvs[2 * i + 1]]);
    expect(hit.u).toBeCloseTo(W[0] * uv[0][0] + W[1] * uv[1][0] + W[2] * uv[2][0], 6);
    expect(hit.v).toBeCloseTo(W[0] * uv[0][1] + W[1] * uv[1][1] + W[2] * uv[2][1], 6);
    expectGradient(hit.gu, e1, e2, uv[1][0] - uv[0][0], uv[2][0] - uv[0][0], N);
    expectGradient(hit.gv, e1, e2, uv[1][1] - uv[0][1], uv[2][1] - uv[0][1], N);
  });

  it('from the back: the shading normal is turned to face the ray, the geometric one is not', () => {
    const mesh = triangle();
    const [v0, v1, v2] = corners(mesh);
    const p = mix(W, [v0, v1, v2]);
    const hit = new SurfaceHit();
    const back = scale(D, -1);
    expect(new MeshTracer(frame(), mesh, 0, 1).hit(ray(sub(p, scale(back, 2)), back), 0, 0, null, hit)).toBe(true);
    expect(hit.t).toBeCloseTo(2, 6);
    const N = cross(sub(v1, v0), sub(v2, v0));
    expectClose(hit.ng, unit(N), 1e-12);
    expectClose(hit.n, scale(hit.nq, -1), 1e-15);
    expect(dot(hit.n, back)).toBeLessThan(0);
  });

  it('no normals, or normals that cancel out or are not numbers: the face normal, facing the ray', () => {
    const [v0, v1, v2] = corners(triangle());
    const p = mix(W, [v0, v1, v2]);
    const N = unit(cross(sub(v1, v0), sub(v2, v0)));
    for (const normals of [new Float32Array(0), new Float32Array(6), new Float32Array(9), new Float32Array(9).fill(NaN)]) {
      const hit = new SurfaceHit();
      expect(new MeshTracer(frame(), triangle({ normals }), 0, 1).hit(ray(sub(p, scale(D, 3)), D), 0, 0, null, hit)).toBe(true);
      expectClose(hit.nq, N, 1e-6);
      expectClose(hit.n, N, 1e-6);
      // From the back: turned.
      expect(new MeshTracer(frame(), triangle({ normals }), 0, 1).hit(ray(sub(p, scale(D, -3)), scale(D, -1)), 0, 0, null, hit)).toBe(true);
      expectClose(hit.n, scale(N, -1), 1e-6);
    }
  });

  it('no UVs (or too few): (0, 0) everywhere, zero gradients', () => {
    const [v0, v1, v2] = corners(triangle());
    const p = mix(W, [v0, v1, v2]);
    for (const uvs of [new Float32Array(0), new Float32Array([0.5, 0.5, 0.7, 0.7])]) {
      // The corners in the index order (0, 1, 2) and (2, 0, 1): the same triangle.
      for (const indices of [new Uint16Array([0, 1, 2]), new Uint16Array([2, 0, 1])]) {
        const hit = new SurfaceHit();
        hit.u = hit.v = 9;
        expect(new MeshTracer(frame(), triangle({ uvs, indices }), 0, 1).hit(ray(sub(p, scale(D, 3)), D), 0, 0, null, hit)).toBe(true);
        expect([hit.u, hit.v]).toEqual([0, 0]);
        expect([...hit.gu, ...hit.gv].every((x) => x === 0)).toBe(true);
      }
    }
  });

  it('kept: beyond tMin, within near and far, on the clip side', () => {
    const mesh = triangle();
    const [v0, v1, v2] = corners(mesh);
    const p = mix(W, [v0, v1, v2]);
    const tracer = new MeshTracer(frame(), mesh, 0, 1);
    const r = ray(sub(p, scale(D, 3)), D);
    expect(tracer.hit(r, 2.9, 0, null, new SurfaceHit())).toBe(true);
    expect(tracer.hit(r, 3.1, 0, null, new SurfaceHit())).toBe(false);
    // tMin beyond far: nothing left to search.
    expect(tracer.hit(r, 200, 0, null, new SurfaceHit())).toBe(false);
    expect(tracer.hit(ray(sub(p, scale(D, 0.05)), D), 0, 0, null, new SurfaceHit())).toBe(false); // nearer than near
    expect(tracer.hit(ray(sub(p, scale(D, 150)), D), 0, 0, null, new SurfaceHit())).toBe(false); // beyond far
    // The plane z = −2 has the whole triangle on its + side.
    expect(tracer.hit(r, 0, 1, [0, 0, 1, 2], new SurfaceHit())).toBe(true);
    expect(tracer.hit(r, 0, -1, [0, 0, 1, 2], new SurfaceHit())).toBe(false);
    // A miss beside it.
    expect(tracer.hit(ray([10, 10, 5], D), 0, 0, null, new SurfaceHit())).toBe(false);
  });

  it('turned, scaled and moved: t and p of the world ray, q in the object, world normals R·S⁻¹·n, UV gradients on world edges', () => {
    const mesh = triangle();
    const f = frame({ position: [1, -2, 3], rotation: [20, -35, 50], scale: [2, 0.5, 1.5] });
    const [v0, v1, v2] = corners(mesh);
    const toWorld = (q: V): V => {
      const m = f.matrix, s = [q[0] * 2, q[1] * 0.5, q[2] * 1.5];
      return [0, 1, 2].map((k) => m[k] * s[0] + m[4 + k] * s[1] + m[8 + k] * s[2] + m[12 + k]) as V;
    };
    const q = mix(W, [v0, v1, v2]), p = toWorld(q);
    const Dw: V = [-0.3, -0.4, -1];
    const hit = new SurfaceHit();
    expect(new MeshTracer(f, mesh, 0, 1).hit(ray(sub(p, scale(Dw, 4)), Dw), 0, 0, null, hit)).toBe(true);
    expect(hit.t).toBeCloseTo(4, 6);
    expectClose(hit.p, p, 1e-6);
    expectClose(hit.q, q, 1e-6);
    const E1 = sub(toWorld(v1), toWorld(v0)), E2 = sub(toWorld(v2), toWorld(v0)), Nw = unit(cross(E1, E2));
    // The world normal of the transformed triangle: ± the geometric normal, the same way round as R·S⁻¹·N (det S > 0: the same).
    expectClose(hit.ng, Nw, 1e-9);
    const nq = unit(mix(W, NORMALS.map((_, i) => [mesh.normals[3 * i], mesh.normals[3 * i + 1], mesh.normals[3 * i + 2]] as V)));
    expectClose(hit.nq, nq, 1e-6);
    const n = unit(f.gradientToWorld(new Float64Array(3), nq));
    expectClose(hit.n, dot(n, Dw) > 0 ? scale(n, -1) : n, 1e-6);
    expect(dot(hit.n, Dw)).toBeLessThan(0);
    expectGradient(hit.gu, E1, E2, UVS[1][0] - UVS[0][0], UVS[2][0] - UVS[0][0], null);
    expectGradient(hit.gv, E1, E2, UVS[1][1] - UVS[0][1], UVS[2][1] - UVS[0][1], null);
  });
});

describe('MeshTracer: a square of two triangles', () => {
  // (0, 0), (2, 0), (2, 2), (0, 2) in z = 0, UV = xy/2; triangles (3, 0, 1) and (1, 2, 3): corners in their own order.
  const square = (): MeshData => ({
    positions: new Float32Array([0, 0, 0, 2, 0, 0, 2, 2, 0, 0, 2, 0]), normals: new Float32Array([0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1]),
    uvs: new Float32Array([0, 0, 1, 0, 1, 1, 0, 1]), indices: new Uint32Array([3, 0, 1, 1, 2, 3]),
  });

  it('each triangle gives UV = xy/2 with gradients (½, 0, 0) and (0, ½, 0) and the normal +z', () => {
    const tracer = new MeshTracer(frame(), square(), 0, 1);
    for (const [x, y] of [[0.5, 0.3], [1.5, 1.6], [0.2, 1.7], [1.8, 0.1]]) {
      const hit = new SurfaceHit();
      expect(tracer.hit(ray([x, y, 2], [0, 0, -1]), 0, 0, null, hit), `${x}, ${y}`).toBe(true);
      expect(hit.t).toBe(2);
      expect(hit.u).toBeCloseTo(x / 2, 6);
      expect(hit.v).toBeCloseTo(y / 2, 6);
      expectClose(hit.gu, [0.5, 0, 0], 1e-12);
      expectClose(hit.gv, [0, 0.5, 0], 1e-12);
      expectClose(hit.ng, [0, 0, 1]);
      expectClose(hit.n, [0, 0, 1]);
    }
  });
});

describe('MeshTracer: the shading normal', () => {
  /** The triangle (0, 0), (2, 0), (0, 2) in z = 0 with every corner's normal `n`, and a fourth vertex unused. */
  /** Normals are stored as float32: compared to 1e-6. */
  const flat = (n: V, normals = 3): MeshData => ({
    positions: new Float32Array([0, 0, 0, 2, 0, 0, 0, 2, 0, 5, 5, 5]),
    normals: new Float32Array(Array.from({ length: normals }, () => n).flat()),
    uvs: new Float32Array(8), indices: new Uint16Array([0, 1, 2]),
  });
  const shade = (mesh: MeshData, d: V) => {
    const hit = new SurfaceHit();
    // Aimed at (0.5, 0.5, 0) from t = 2 back.
    expect(new MeshTracer(frame(), mesh, 0, 1).hit(ray(sub([0.5, 0.5, 0], scale(d, 2)), d), 0, 0, null, hit)).toBe(true);
    return hit;
  };

  it('is turned to face the ray whatever the face does: every component of n·d counts', () => {
    // n = (0.6, 0, 0.8), d = (1, 0, −0.5): n·d = 0.6 − 0.4 > 0: turned. d = (−1, 0, −0.5): −1 < 0: kept.
    expectClose(shade(flat([0.6, 0, 0.8], 4), [1, 0, -0.5]).n, [-0.6, 0, -0.8], 1e-6);
    expectClose(shade(flat([0.6, 0, 0.8], 4), [-1, 0, -0.5]).n, [0.6, 0, 0.8], 1e-6);
    // n = (0, 0.6, 0.8), d = (0, 1, −0.5): turned.
    expectClose(shade(flat([0, 0.6, 0.8], 4), [0, 1, -0.5]).n, [0, -0.6, -0.8], 1e-6);
  });

  it('a shading normal at right angles to the ray is left as it is', () => {
    expectClose(shade(flat([1, 0, 0], 4), [0, 0, -1]).n, [1, 0, 0], 1e-6);
  });

  it('normals for fewer vertices than the mesh has are not used, even at corners that have one', () => {
    // Normals for 3 of the 4 vertices: the face normal +z, not (0.6, 0, 0.8).
    expectClose(shade(flat([0.6, 0, 0.8], 3), [0, 0, -1]).n, [0, 0, 1], 1e-6);
    expectClose(shade(flat([0.6, 0, 0.8], 4), [0, 0, -1]).n, [0.6, 0, 0.8], 1e-6);
  });
});

describe('bvhOf', () => {
  it('one BVH per mesh value, built on first use', () => {
    const a = triangle(), b = triangle();
    expect(bvhOf(a)).toBe(bvhOf(a));
    expect(bvhOf(b)).not.toBe(bvhOf(a));
    expect(bvhOf(a).order.length).toBe(1);
    const tracer = new MeshTracer(frame(), a, 0, 1);
    expect((tracer as unknown as { bvh: unknown }).bvh).toBe(bvhOf(a));
  });
});
