// Polygons and generated normals: ear clipping of concave faces, smoothing groups, area weights.
import { describe, expect, it } from 'vitest';
import { parseObj } from '../../src/loaders/obj';
import { instrumented } from './helpers/collections';
import {
  cross, dot, insidePolygon, length, normal, polygonArea, polygonObj, position, star, sub, triangleNormal,
  triangles, unit, type V3,
} from './helpers/obj';

/** Lays 2D points into 3D on the plane through `origin` spanned by the orthonormal `u`, `w`. */
function plane(origin: V3, u: V3, w: V3): { to3: (p: [number, number]) => V3; to2: (p: V3) => [number, number] } {
  return {
    to3: ([x, y]) => [origin[0] + x * u[0] + y * w[0], origin[1] + x * u[1] + y * w[1], origin[2] + x * u[2] + y * w[2]],
    to2: (p) => [dot(sub(p, origin), u), dot(sub(p, origin), w)],
  };
}

/** Asserts the triangulation of `polygon2d` (laid out by `layout`) covers exactly the polygon. */
function expectExactCover(polygon2d: [number, number][], layout: ReturnType<typeof plane>, facing: V3): void {
  const r = parseObj(polygonObj(polygon2d.map(layout.to3)));
  expect(r.warnings).toEqual([]);
  const tris = triangles(r);
  expect(tris.length).toBe(polygon2d.length - 2);
  let area = 0;
  for (const t of tris) {
    const n = triangleNormal(t);
    area += length(n) / 2;
    // Same winding as the polygon: no triangle flips its face.
    expect(dot(n, facing)).toBeGreaterThan(0);
    const c = layout.to2([(t[0][0] + t[1][0] + t[2][0]) / 3, (t[0][1] + t[1][1] + t[2][1]) / 3, (t[0][2] + t[1][2] + t[2][2]) / 3]);
    expect(insidePolygon(c, polygon2d), `centroid ${c} of a triangle`).toBe(true);
  }
  expect(area).toBeCloseTo(Math.abs(polygonArea(polygon2d)), 5);
}

const XY = plane([0, 0, 0], [1, 0, 0], [0, 1, 0]);

describe('triangulation', () => {
  it('splits a concave quad along the diagonal from its reflex corner', () => {
    const dart: [number, number][] = [[0, 0], [1, 0.5], [2, 0], [1, 2]];
    expectExactCover(dart, XY, [0, 0, 1]);
  });

  it('ear-clips a star whose fan from the first vertex would leave the polygon', () => {
    // Starting at a tip: the fan from there crosses outside the star (checked first).
    const polygon = star(5, 0.4);
    const fanOutside = polygon.slice(1, -1).some((_, i) => {
      const [a, b, c] = [polygon[0], polygon[i + 1], polygon[i + 2]];
      return !insidePolygon([(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3], polygon);
    });
    expect(fanOutside).toBe(true);
    expectExactCover(polygon, XY, [0, 0, 1]);
  });

  it('ear-clips an L-shape and a comb', () => {
    expectExactCover([[2, 0], [2, 1], [1, 1], [1, 2], [0, 2], [0, 0]], XY, [0, 0, 1]);
    const comb: [number, number][] = [[0, 0], [5, 0], [5, 3], [4, 3], [4, 1], [3, 1], [3, 3], [2, 3], [2, 1], [1, 1], [1, 3], [0, 3]];
    expectExactCover([...comb.slice(3), ...comb.slice(0, 3)], XY, [0, 0, 1]);
  });

  it('ear-clips a clockwise star on a tilted plane, projected on its Newell normal', () => {
    const u = unit([1, -1, 0]);
    const w = unit([1, 1, -2]);
    const layout = plane([3, -2, 5], u, w);
    const clockwise = star(6, 0.3).reverse();
    expectExactCover(clockwise, layout, cross(w, u));
  });

  it('drops a polygon of no area with a warning naming its line, and keeps the rest', () => {
    // Collinear corners, or one point repeated: every triangle made of them has zero area.
    const line = parseObj('v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nv 4 0 0\nv 0 1 0\nf 1 2 3 4 5\nf 1 2 6\n');
    expect([...line.indices]).toEqual([0, 1, 2]);
    expect(line.warnings).toEqual([{ line: 7, message: expect.stringMatching(/^face of 5 vertices with no area .*; face dropped$/) }]);
    expect(() => parseObj('v 1 1 1\nf 1 1 1 1 1 1\n')).toThrow(/line 2: no faces to draw: 1 face dropped/);
    // A triangle is kept as written, even of zero area.
    expect(parseObj('v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n').indices.length).toBe(3);
  });

  it('keeps only the triangles with area from a polygon that walks over its corners again', () => {
    // A unit square walked 1000 times: all 4000 corners turn left, so it is fanned from the
    // first corner: (1, k, k+1) for k = 2 … 3999. Of those, only (1 2 3) and (1 3 4) of each lap
    // have area (the others hold vertex 1 twice): 2 × 1000 triangles of area 1/2, not 3998.
    const laps = instrumented ? 100 : 1000; // StrykerJS: fewer, for its time a mutant
    const r = parseObj(`v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf${' 1 2 3 4'.repeat(laps)}\n`);
    expect(r.warnings).toEqual([]);
    const tris = triangles(r);
    expect(tris.length).toBe(2 * laps);
    for (const t of tris) expect(length(triangleNormal(t)) / 2).toBe(0.5);
  });

  it('fans a bowtie (a polygon whose Newell normal is zero), keeping its triangles of area', () => {
    const bowtie = parseObj('v 0 0 0\nv 1 1 0\nv 1 0 0\nv 0 1 0\nv 0.5 2 0\nf 1 2 3 4 5\n');
    expect(bowtie.indices.length).toBe(9);
    expect([...bowtie.normals.slice(0, 3)].every(Number.isFinite)).toBe(true);
  });
});

const CUBE_V = 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n';
const CUBE_F = ['f 1 4 3 2', 'f 5 6 7 8', 'f 1 2 6 5', 'f 3 4 8 7', 'f 1 5 8 4', 'f 2 3 7 6'];

function expectFlat(r: ReturnType<typeof parseObj>): void {
  expect(r.positions.length / 3).toBe(24);
  for (let t = 0; t < r.indices.length; t += 3) {
    const face = unit(triangleNormal([0, 1, 2].map((k) => position(r, r.indices[t + k]))));
    for (let k = 0; k < 3; k++) expect(normal(r, r.indices[t + k]).map((c) => c + 0)).toEqual(face.map((c) => c + 0));
  }
}

describe('generated normals and smoothing groups', () => {
  it('averages normals at shared corners of a cube in one smoothing group', () => {
    const r = parseObj(`${CUBE_V}s 1\n${CUBE_F.join('\n')}\n`);
    expect(r.positions.length / 3).toBe(8);
    expect(r.indices.length).toBe(36);
    for (let i = 0; i < 8; i++) {
      const expected = unit(sub(position(r, i), [0.5, 0.5, 0.5]));
      normal(r, i).forEach((c, k) => expect(c).toBeCloseTo(expected[k], 6));
    }
  });

  it('gives flat face normals to a cube with s off (and s 0)', () => {
    expectFlat(parseObj(`${CUBE_V}s off\n${CUBE_F.join('\n')}\n`));
    expectFlat(parseObj(`${CUBE_V}s 1\ns 0\n${CUBE_F.join('\n')}\n`));
  });

  it('gives flat normals to a cube with a different smoothing group per face', () => {
    expectFlat(parseObj(CUBE_V + CUBE_F.map((f, i) => `s ${i + 1}\n${f}`).join('\n')));
  });

  it('smooths only within a group: two groups meeting at an edge keep that edge sharp', () => {
    // Top and front in group 1, the rest in group 2: the edge between them is shared within group 1.
    const text = `${CUBE_V}s 1\n${CUBE_F[1]}\n${CUBE_F[2]}\ns 2\n${[0, 3, 4, 5].map((i) => CUBE_F[i]).join('\n')}\n`;
    const r = parseObj(text);
    // Corner (0,0,1) of group 1 averages top (+z) and front (-y) only.
    let found = 0;
    for (let i = 0; i < r.positions.length / 3; i++) {
      const p = position(r, i);
      const n = normal(r, i);
      if (p[0] === 0 && p[1] === 0 && p[2] === 1 && Math.abs(n[0]) < 1e-6) {
        expect(n[1]).toBeCloseTo(-Math.SQRT1_2, 6);
        expect(n[2]).toBeCloseTo(Math.SQRT1_2, 6);
        found++;
      }
    }
    expect(found).toBe(1);
    // Group 1 uses 6 positions, group 2 all 8: a position gets one vertex per group it is in.
    expect(r.positions.length / 3).toBe(6 + 8);
  });

  it('smooths a file with no s statement as one group', () => {
    const r = parseObj(`${CUBE_V}${CUBE_F.join('\n')}\n`);
    expect(r.positions.length / 3).toBe(8);
  });

  it('weights the faces around a vertex by their area', () => {
    // At vertex 1: a triangle of area 0.5 facing +z and one of area 2 facing +x.
    const r = parseObj('v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 2 0\nv 0 0 2\nf 1 2 3\nf 1 4 5\n');
    const expected = unit([2, 0, 0.5]);
    normal(r, 0).forEach((c, k) => expect(c).toBeCloseTo(expected[k], 6));
    expect(normal(r, 1)).toEqual([0, 0, 1]);
    expect(normal(r, 4)).toEqual([1, 0, 0]);
  });
});
