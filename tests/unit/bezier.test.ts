// Bézier patches (docs/software-renderer.md#bezier-surfaces): de Casteljau against the Bernstein closed form, normals against
// finite differences, the degenerate edge, and the grid mesh's layout and winding.
import { describe, expect, it } from 'vitest';
import {
  bezierPatchMesh, bezierPatchNormal, checkBezierPatch, evaluateBezierPatch, type BezierPatch,
} from '../../src/scene/geometry/bezier';
import { cross, dot, length, sub, unit, type V3 } from './helpers/obj';

/** Deterministic numbers in [−1, 1) (a 32-bit LCG). */
function random(seed: number): () => number {
  let s = seed >>> 0;
  return () => {
    s = (Math.imul(s, 1664525) + 1013904223) >>> 0;
    return s / 2 ** 31 - 1;
  };
}

function randomPatch(m: number, n: number, seed: number): BezierPatch {
  const r = random(seed);
  return { degreeU: m, degreeV: n, points: Float64Array.from({ length: 3 * (m + 1) * (n + 1) }, r) };
}

function binomial(n: number, k: number): number {
  let c = 1;
  for (let i = 1; i <= k; i++) c = (c * (n - k + i)) / i;
  return c;
}

function bernstein(n: number, i: number, t: number): number {
  if (i < 0 || i > n) return 0;
  return binomial(n, i) * t ** i * (1 - t) ** (n - i);
}

/** d/dt of B(n, i) = n·(B(n−1, i−1) − B(n−1, i)). */
function bernsteinDerivative(n: number, i: number, t: number): number {
  return n * (bernstein(n - 1, i - 1, t) - bernstein(n - 1, i, t));
}

/** S, ∂S/∂u, ∂S/∂v as sums over the control points. */
function closedForm(p: BezierPatch, u: number, v: number): { point: V3; du: V3; dv: V3 } {
  const { degreeU: m, degreeV: n, points } = p;
  const point: V3 = [0, 0, 0], du: V3 = [0, 0, 0], dv: V3 = [0, 0, 0];
  for (let i = 0; i <= m; i++) {
    for (let j = 0; j <= n; j++) {
      const w = bernstein(m, i, u) * bernstein(n, j, v);
      const wu = bernsteinDerivative(m, i, u) * bernstein(n, j, v);
      const wv = bernstein(m, i, u) * bernsteinDerivative(n, j, v);
      for (let c = 0; c < 3; c++) {
        const x = points[3 * (i * (n + 1) + j) + c];
        point[c] += w * x; du[c] += wu * x; dv[c] += wv * x;
      }
    }
  }
  return { point, du, dv };
}

function expectNear(a: ArrayLike<number>, b: ArrayLike<number>, eps: number): void {
  for (let c = 0; c < b.length; c++) expect(Math.abs(a[c] - b[c]), `${Array.from(a)} vs ${Array.from(b)}`).toBeLessThanOrEqual(eps);
}

/** A height field over a grid (z random): no folds, so every triangle faces its normals' way. */
function heightPatch(m: number, n: number, seed: number): BezierPatch {
  const r = random(seed);
  const points: number[] = [];
  for (let i = 0; i <= m; i++) for (let j = 0; j <= n; j++) points.push(i / m, j / n, 0.3 * r());
  return { degreeU: m, degreeV: n, points };
}

const vec = (a: ArrayLike<number>, k: number): V3 => [a[3 * k], a[3 * k + 1], a[3 * k + 2]];

/** A dome over a quarter circle: row i = 0 is the apex repeated, so the edge u = 0 is one point. */
function dome(): BezierPatch {
  const rows = [[0, 1], [0.6, 1], [1, 0.6], [1, 0]]; // (radius, height) per i
  const angles = [0, Math.PI / 6, Math.PI / 3, Math.PI / 2];
  const points: number[] = [];
  for (const [r, h] of rows) for (const a of angles) points.push(r * Math.cos(a), r * Math.sin(a), h);
  return { degreeU: 3, degreeV: 3, points };
}

describe('evaluateBezierPatch', () => {
  for (const [m, n] of [[1, 1], [3, 3], [2, 5], [5, 2], [7, 1]]) {
    it(`matches the Bernstein closed form, point and both derivatives, degrees (${m}, ${n})`, () => {
      const r = random(m * 31 + n);
      for (let seed = 0; seed < 5; seed++) {
        const patch = randomPatch(m, n, 100 * m + 10 * n + seed);
        for (const [u, v] of [[0, 0], [1, 1], [0, 1], [0.5, 0.25], [(r() + 1) / 2, (r() + 1) / 2]]) {
          const got = evaluateBezierPatch(patch, u, v);
          const want = closedForm(patch, u, v);
          expectNear(got.point, want.point, 1e-12);
          expectNear(got.du, want.du, 1e-11);
          expectNear(got.dv, want.dv, 1e-11);
        }
      }
    });
  }

  it('interpolates the four corner control points', () => {
    const p = randomPatch(2, 5, 9);
    expectNear(evaluateBezierPatch(p, 0, 0).point, vec(p.points, 0), 0);
    expectNear(evaluateBezierPatch(p, 0, 1).point, vec(p.points, 5), 0);
    expectNear(evaluateBezierPatch(p, 1, 0).point, vec(p.points, 2 * 6), 0);
    expectNear(evaluateBezierPatch(p, 1, 1).point, vec(p.points, 2 * 6 + 5), 0);
  });

  it('rejects degree 0, fractional degrees and a point count that does not fit', () => {
    expect(() => checkBezierPatch({ degreeU: 0, degreeV: 3, points: new Float64Array(12) })).toThrow(RangeError);
    expect(() => checkBezierPatch({ degreeU: 1.5, degreeV: 1, points: new Float64Array(12) })).toThrow(RangeError);
    expect(() => checkBezierPatch({ degreeU: 1, degreeV: 1, points: new Float64Array(9) })).toThrow(/4 control points/);
    // Either degree alone, and what the messages say.
    expect(() => checkBezierPatch({ degreeU: 3, degreeV: 0, points: new Float64Array(12) }))
      .toThrow('glass-plane-scene: Bézier degrees must be integers ≥ 1, got (3, 0)');
    expect(() => checkBezierPatch({ degreeU: 1, degreeV: 1.5, points: new Float64Array(12) })).toThrow(/got \(1, 1\.5\)/);
    expect(() => checkBezierPatch({ degreeU: 1, degreeV: 2, points: new Float64Array(9) }))
      .toThrow('glass-plane-scene: a (1, 2) Bézier patch needs 6 control points, got 3');
    expect(() => checkBezierPatch({ degreeU: 1, degreeV: 2, points: new Float64Array(18) })).not.toThrow();
  });
});

describe('bezierPatchNormal', () => {
  it('is unit and orthogonal to finite-difference tangents, along ∂S/∂u × ∂S/∂v', () => {
    for (const [m, n] of [[1, 1], [3, 3], [2, 5]]) {
      const patch = randomPatch(m, n, 7 * m + n);
      const h = 1e-6;
      for (const [u, v] of [[0.3, 0.6], [0.5, 0.5], [0.8, 0.1], [0.1, 0.9]]) {
        const normal = bezierPatchNormal(patch, u, v) as V3;
        const at = (a: number, b: number): V3 => evaluateBezierPatch(patch, a, b).point;
        const tu = sub(at(u + h, v), at(u - h, v));
        const tv = sub(at(u, v + h), at(u, v - h));
        expect(length(normal)).toBeCloseTo(1, 12);
        expect(Math.abs(dot(normal, unit(tu)))).toBeLessThan(1e-6);
        expect(Math.abs(dot(normal, unit(tv)))).toBeLessThan(1e-6);
        expect(dot(normal, unit(cross(tu, tv)))).toBeGreaterThan(1 - 1e-9);
      }
    }
  });

  it('takes a nearby point\'s normal on a degenerate edge: finite, unit, the dome\'s axis', () => {
    const patch = dome();
    const { du, dv } = evaluateBezierPatch(patch, 0, 0.4);
    expect(length(dv as V3)).toBe(0); // the edge really is one point
    expect(length(du as V3)).toBeGreaterThan(0);
    for (const v of [0, 0.4, 1]) {
      const n = bezierPatchNormal(patch, 0, v);
      expect(n.every(Number.isFinite)).toBe(true);
      expect(length(n)).toBeCloseTo(1, 12);
      // Row 1 has the apex's height, so the tangent plane at the tip is horizontal.
      expect(Math.abs(n[2])).toBeGreaterThan(1 - 1e-6);
      // Same side as the normals just inside the patch.
      expect(dot(n, bezierPatchNormal(patch, 0.05, v))).toBeGreaterThan(0.9);
    }
  });

  it('on a degenerate edge takes exactly the normal 10⁻⁴ of the way towards the patch centre (½, ½)', () => {
    const patch = dome();
    for (const v of [0, 0.4, 1]) {
      // The first nearby step: (u + 1e-4·(½ − u), v + 1e-4·(½ − v)), not degenerate there.
      expect(bezierPatchNormal(patch, 0, v)).toEqual(bezierPatchNormal(patch, 0 + 1e-4 * 0.5, v + 1e-4 * (0.5 - v)));
    }
    // Off the edge it is the point's own normal, not a nearby one.
    expect(bezierPatchNormal(patch, 0.3, 0.4)).not.toEqual(bezierPatchNormal(patch, 0.3 + 1e-4 * 0.2, 0.4 + 1e-4 * 0.1));
  });

  it('is the same at any scale of the control net: the degeneracy bound grows with the net\'s size squared', () => {
    const scaled = (p: BezierPatch, k: number): BezierPatch => ({ ...p, points: Array.from(p.points, (x) => x * k) });
    const moved = (p: BezierPatch): BezierPatch => ({ ...p, points: Array.from(p.points, (x, i) => x + [3e3, -2e3, 1e3][i % 3]) });
    for (const patch of [dome(), heightPatch(3, 2, 4)]) {
      // Far from the origin: the bound comes from the net's extent, not its position.
      for (const [u, v] of [[0, 0.4], [0.3, 0.7]]) expectNear(bezierPatchNormal(moved(patch), u, v), bezierPatchNormal(patch, u, v), 1e-6);
      for (const k of [1e-6, 1e6]) {
        for (const [u, v] of [[0, 0.4], [0.3, 0.7], [1, 1], [0.5, 0]]) {
          expectNear(bezierPatchNormal(scaled(patch, k), u, v), bezierPatchNormal(patch, u, v), 1e-6);
        }
        expectNear(bezierPatchMesh(scaled(patch, k), 5).normals, bezierPatchMesh(patch, 5).normals, 1e-6);
      }
    }
  });

  it('gives (0, 0, 1) where the whole patch is degenerate (all control points on a line)', () => {
    const points = Array.from({ length: 4 }, (_, k) => [k, 2 * k, 0]).flat();
    expect(bezierPatchNormal({ degreeU: 1, degreeV: 1, points: [...points.slice(0, 6), ...points.slice(0, 6)] }, 0.5, 0.5))
      .toEqual([0, 0, 1]);
  });
});

describe('bezierPatchMesh', () => {
  it('has E² vertices at (a/(E−1), b/(E−1)), uv = (u, v), and (E−1)² quads of two triangles', () => {
    const patch = randomPatch(2, 5, 3);
    const e = 7;
    const mesh = bezierPatchMesh(patch, e);
    expect(mesh.positions.length).toBe(3 * e * e);
    expect(mesh.uvs.length).toBe(2 * e * e);
    expect(mesh.indices.length).toBe(6 * (e - 1) ** 2);
    expect(mesh.indices).toBeInstanceOf(Uint16Array);
    for (const [a, b] of [[0, 0], [6, 0], [0, 6], [3, 4], [6, 6]]) {
      const k = b * e + a;
      expect([mesh.uvs[2 * k], mesh.uvs[2 * k + 1]]).toEqual([Math.fround(a / 6), Math.fround(b / 6)]);
      expectNear(vec(mesh.positions, k), evaluateBezierPatch(patch, a / 6, b / 6).point, 1e-6);
      expectNear(vec(mesh.normals, k), bezierPatchNormal(patch, a / 6, b / 6), 1e-6);
    }
    expect(Math.max(...mesh.indices)).toBe(e * e - 1);
  });

  it('winds every triangle counter-clockwise about its vertices\' normals', () => {
    for (const patch of [heightPatch(3, 3, 1), heightPatch(2, 5, 2), dome()]) {
      const mesh = bezierPatchMesh(patch, 12);
      for (let t = 0; t < mesh.indices.length; t += 3) {
        const [a, b, c] = [0, 1, 2].map((k) => mesh.indices[t + k]);
        const face = cross(sub(vec(mesh.positions, b), vec(mesh.positions, a)), sub(vec(mesh.positions, c), vec(mesh.positions, a)));
        if (length(face) < 1e-9) continue; // a sliver at the dome's tip
        const mean = [a, b, c].reduce<V3>((s, k) => [s[0] + mesh.normals[3 * k], s[1] + mesh.normals[3 * k + 1], s[2] + mesh.normals[3 * k + 2]], [0, 0, 0]);
        expect(dot(unit(face), unit(mean))).toBeGreaterThan(0);
      }
    }
  });

  it('has no NaN and unit normals at the degenerate edge of the dome', () => {
    const mesh = bezierPatchMesh(dome(), 9);
    for (let k = 0; k < 81; k++) expect(length(vec(mesh.normals, k))).toBeCloseTo(1, 5);
  });

  it('clamps the resolution to 2..1024 and uses 32-bit indices above 65 535 vertices', () => {
    const patch = randomPatch(1, 1, 5);
    expect(bezierPatchMesh(patch, 1).positions.length).toBe(3 * 4);
    expect(bezierPatchMesh(patch, Number.NaN).positions.length).toBe(3 * 4);
    expect(bezierPatchMesh(patch, 300).indices).toBeInstanceOf(Uint32Array);
  });
});
