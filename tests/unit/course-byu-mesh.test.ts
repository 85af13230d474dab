// The course's mesh .byu (docs/course-files.md#mesh-byu): header counts, trailing content, faces out of range,
// load errors with their lines, and the course's vertex normals.
import { describe, expect, it } from 'vitest';
import { courseVertexNormals, parseByuMesh } from '../../src/loaders/course/byu-mesh';
import { makeChalice } from '../data/course/make-chalice';
import { cross, dot, length, sub, unit, type V3 } from './helpers/obj';
import { expectLoadError, sample, xyz } from './helpers/course';

const S3 = 1 / Math.sqrt(3);

// Parsed in each test, not once per describe: StrykerJS counts code run outside a test as
// run by none, and a mutant in it then meets only the unmutated result.
const tetra = () => parseByuMesh(sample('tetra.byu'), { url: 'tetra.byu' });

describe('parseByuMesh: the tetrahedron', () => {
  it('reads NV vertices and NT 1-based faces, in file order', () => {
    const r = tetra();
    expect(r.vertexCount).toBe(4);
    expect(r.declaredFaceCount).toBe(4);
    expect(r.faceCount).toBe(4);
    expect([...r.mesh.positions]).toEqual([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]);
    expect([...r.mesh.indices]).toEqual([0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3]);
    expect(r.mesh.indices).toBeInstanceOf(Uint16Array);
    expect([...r.mesh.uvs]).toEqual(new Array(8).fill(0));
    expect(r.bounds).toEqual({ min: [0, 0, 0], max: [1, 1, 1] });
    expect(r.warnings).toEqual([]);
  });

  it('gives each vertex the normalised sum of its faces\' unit normals, not the area-weighted one', () => {
    const r = tetra();
    expect(xyz(r.mesh.normals, 0).map((c) => c / -S3)).toEqual([1, 1, 1].map(() => expect.closeTo(1, 6)));
    // Vertex 2 touches −z, −y and the slanted face (1, 1, 1)/√3 of area √3/2: weighting by
    // area would give exactly +x.
    const want = unit([S3, S3 - 1, S3 - 1]);
    xyz(r.mesh.normals, 1).forEach((c, k) => expect(c).toBeCloseTo(want[k], 6));
    expect(Math.abs(r.mesh.normals[4])).toBeGreaterThan(0.4);
  });

  it('reads the CRLF + BOM + blank lines + tabs + exponents variant and the one without a final newline alike', () => {
    const r = tetra();
    for (const [name, low, top] of [['tetra-crlf-bom.byu', -1e-14, 0.95], ['tetra-no-final-newline.byu', 0, 1]] as const) {
      const v = parseByuMesh(sample(name), { url: name });
      expect(v.warnings).toEqual([]);
      expect([...v.mesh.indices]).toEqual([...r.mesh.indices]);
      // -1.0E-14, +1., 1e0, .0 and 9.5e-001 among them.
      expect([...v.mesh.positions]).toEqual([0, 0, low, 1, 0, 0, 0, 1, 0, 0, 0, top].map(Math.fround));
    }
  });
});

describe('parseByuMesh: faults', () => {
  it('ignores content after the counted lines with ONE warning naming its first line', () => {
    const r = parseByuMesh(sample('tetra-trailing.byu'), { url: 't.byu' });
    expect(r.vertexCount).toBe(4);
    expect(r.faceCount).toBe(4);
    expect(r.mesh.positions.length).toBe(12);
    expect(r.warnings).toEqual([{ line: 11, message: expect.stringMatching(/^5 lines after the 4 vertices and 4 faces.*ignored/) }]);
  });

  it('drops a face with an index outside 1..NV, warning with its line, and keeps the rest', () => {
    const r = parseByuMesh(sample('tetra-out-of-range.byu'), { url: 'o.byu' });
    expect(r.faceCount).toBe(3);
    expect(r.declaredFaceCount).toBe(4);
    expect([...r.mesh.indices]).toEqual([0, 2, 1, 0, 3, 2, 1, 2, 3]);
    expect(r.warnings).toEqual([{ line: 7, message: expect.stringMatching(/face 2: index 9 is outside 1\.\.4/) }]);
    for (const bad of ['0 2 3', '1 -2 3', '1 2 5', '1 2 -5', '1 2 1.5', '1 2 -0']) {
      const w = parseByuMesh(`4 2\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n${bad}\n1 2 3\n`).warnings;
      expect(w.map((x) => x.line), bad).toEqual([6]);
    }
    expect(parseByuMesh('4 2\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 2 -5\n1 2 3\n').warnings[0].message).toMatch(/index -5 is outside 1\.\.4/);
  });

  it('reads a classic BYU face ending in a negative index as that corner and keeps the face (docs/course-files.md#mesh-byu)', () => {
    const r = parseByuMesh('4 4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 3 -2\n1 2 -4\n1 4 -3\n2 3 -4\n', { url: 'classic.byu' });
    expect(r.warnings).toEqual([]);
    expect(r.faceCount).toBe(4);
    expect([...r.mesh.indices]).toEqual([...parseByuMesh(sample('tetra.byu')).mesh.indices]);
  });

  it('is a load error when every face is dropped', () => {
    expectLoadError(() => parseByuMesh('3 2\n0 0 0\n1 0 0\n0 1 0\n1 2 4\n\n4 2 1\n', { url: 'x.byu' }), 'x.byu', 5, /no faces to draw/);
  });

  it('is a load error, with its line, for fewer lines than counted', () => {
    expectLoadError(() => parseByuMesh(sample('mesh-truncated.byu'), { url: 'm.byu' }), 'm.byu', 8, /ends here, after 3 of the 4 faces/);
    expectLoadError(() => parseByuMesh('4 1\n0 0 0\n\n1 0 0\n\n', { url: 'm.byu' }), 'm.byu', 4, /after 2 of the 4 vertices/);
  });

  it('is a load error, with its line, for a missing count or a token that is not a number', () => {
    expectLoadError(() => parseByuMesh(sample('mesh-missing-count.byu'), { url: 'c.byu' }), 'c.byu', 1, /face count is missing/);
    expectLoadError(() => parseByuMesh(sample('mesh-bad-token.byu'), { url: 'b.byu' }), 'b.byu', 4, /vertex 3: "1,5" is not a number/);
    expectLoadError(() => parseByuMesh('4 2\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 2 3\n1 x 3\n', { url: 'b.byu' }), 'b.byu', 7, /face 2: "x"/);
    expectLoadError(() => parseByuMesh('4 two\n', { url: 'b.byu' }), 'b.byu', 1, /face count NT: "two" is not a number/);
    expectLoadError(() => parseByuMesh('4.5 1\n', { url: 'b.byu' }), 'b.byu', 1, /not a whole number/);
    expectLoadError(() => parseByuMesh('3 1\n0 0\n', { url: 'b.byu' }), 'b.byu', 2, /vertex 1 needs 3 numbers, the line has 2/);
    expectLoadError(() => parseByuMesh('3 1\n0 0 1e999\n', { url: 'b.byu' }), 'b.byu', 2, /too large/);
    expectLoadError(() => parseByuMesh('', { url: 'e.byu' }), 'e.byu', 1, /no header/);
  });

  it('warns once about extra values on vertex lines and once on face lines', () => {
    const r = parseByuMesh('3 1 7\n0 0 0 9\n1 0 0 9\n0 1 0\n1 2 3 4\n');
    expect(r.warnings.map((w) => w.line)).toEqual([1, 2, 5]);
  });

  it('does not allocate what the header claims before the lines are there', () => {
    expectLoadError(() => parseByuMesh('1000000000000 1\n0 0 0\n', { url: 'big.byu' }), 'big.byu', 2, /after 1 of the 1000000000000 vertices/);
  });
});

describe('courseVertexNormals', () => {
  it('counts every face alike: a vertex between a big and a tiny face gets the bisector', () => {
    // Two faces meeting along the x axis at 90°: normals +z and +y, areas 5 and 0.005.
    const positions = [0, 0, 0, 1, 0, 0, 0, 10, 0, 0, 0, 0.01];
    const n = courseVertexNormals(positions, [0, 1, 2, 0, 3, 1]);
    const want = unit([0, 1, 1]);
    xyz(n, 0).forEach((c, k) => expect(c).toBeCloseTo(want[k], 6));
  });

  it('gives +z to a vertex with no face or with faces that cancel, and skips zero-area faces', () => {
    const positions = [0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 5, 5];
    const n = courseVertexNormals(positions, [0, 1, 2, 0, 2, 1, 0, 0, 1]);
    expect(xyz(n, 0)).toEqual([0, 0, 1]);
    expect(xyz(n, 3)).toEqual([0, 0, 1]);
  });
});

describe('the generated chalice', () => {
  // Its parse time is in `npm run bench` (bench/parse-course.md), not asserted here.
  const chalice = makeChalice();
  const parsed = () => parseByuMesh(chalice.text, { url: 'chalice.byu' });

  it('has the counts of its header, a few thousand triangles, no warnings', () => {
    const r = parsed();
    expect(r.vertexCount).toBe(chalice.vertexCount);
    expect(r.faceCount).toBe(chalice.faceCount);
    expect(r.faceCount).toBeGreaterThan(3000);
    expect(r.warnings).toEqual([]);
  });

  it('has unit normals pointing to the outer side of the sheet: down under the foot, out on the stem', () => {
    const r = parsed();
    for (let k = 0; k < r.vertexCount; k++) expect(length(xyz(r.mesh.normals, k))).toBeCloseTo(1, 5);
    expect(xyz(r.mesh.normals, 0).map((c) => Math.round(c * 1e6) / 1e6 + 0)).toEqual([0, -1, 0]);
    const stem = chalice.rings.findIndex(([radius, y]) => radius === 0.15 && y > 0.6 && y < 1);
    expect(stem).toBeGreaterThan(0);
    for (let s = 0; s < chalice.segments; s += 7) {
      const k = 1 + stem * chalice.segments + s;
      const p = xyz(r.mesh.positions, k);
      const radial = unit([p[0], 0, p[2]]);
      expect(dot(xyz(r.mesh.normals, k), radial)).toBeGreaterThan(0.99);
    }
    // And every face is wound the way its vertices' normals point (no sheet turned inside out).
    const idx = r.mesh.indices;
    let agree = 0;
    for (let t = 0; t < idx.length; t += 3) {
      const [a, b, c] = [idx[t], idx[t + 1], idx[t + 2]].map((k) => xyz(r.mesh.positions, k) as V3);
      const face = cross(sub(b, a), sub(c, a));
      if (dot(face, xyz(r.mesh.normals, idx[t])) > 0) agree++;
    }
    expect(agree / (idx.length / 3)).toBeGreaterThan(0.97);
  });
});
