// The mesh builder past its first allocations (src/loaders/obj/build-mesh.ts): more output
// vertices than positions (flat shading: one vertex a corner) and polygons of more corners
// than its scratch list holds, with every normal and triangle checked.
import { describe, expect, it } from 'vitest';
import { parseObj, type ObjResult } from '../../src/loaders/obj';
import { F64List, I32List } from '../../src/loaders/obj/growable';
import { normal, polygonArea, position, triangleNormal, triangles, unit, type V3 } from './helpers/obj';

/** A 6 × 6 grid on z = x² + y²/2: 36 positions, 50 triangles of different normals. */
function paraboloid(head: string): string {
  const lines: string[] = [];
  for (let j = 0; j < 6; j++) for (let i = 0; i < 6; i++) lines.push(`v ${i} ${j} ${i * i + (j * j) / 2}`);
  lines.push(head);
  for (let j = 0; j < 5; j++) {
    for (let i = 0; i < 5; i++) {
      const a = 6 * j + i + 1, b = a + 1, c = a + 7, d = a + 6;
      lines.push(`f ${a} ${b} ${c}`, `f ${a} ${c} ${d}`);
    }
  }
  return `${lines.join('\n')}\n`;
}

function expectFaceNormals(r: ObjResult): void {
  for (let t = 0; t < r.indices.length; t += 3) {
    const face = unit(triangleNormal([0, 1, 2].map((k) => position(r, r.indices[t + k]))));
    for (let k = 0; k < 3; k++) normal(r, r.indices[t + k]).forEach((c, a) => expect(c, `triangle ${t / 3}`).toBeCloseTo(face[a], 6));
  }
}

describe('buildMesh past its first allocations', () => {
  it('gives 150 flat vertices of 36 positions each its own face normal (s off)', () => {
    const r = parseObj(paraboloid('s off'));
    expect(r.positions.length / 3).toBe(150);
    expect(r.indices.length).toBe(150);
    expectFaceNormals(r);
  });

  it('gives 150 vertices of a smoothing group per face each its face normal', () => {
    const text = paraboloid('').replace(/^f /gm, (() => { let k = 0; return () => `s ${++k}\nf `; })());
    const r = parseObj(text);
    expect(r.positions.length / 3).toBe(150);
    expectFaceNormals(r);
  });

  it('gives 150 vertices with a uv a corner each their position and uv', () => {
    const text = paraboloid('').replace(/^f (\d+) (\d+) (\d+)$/gm, (_, a, b, c) => `vt ${a} 0\nvt ${b} 1\nvt ${c} 2\nf ${a}/-3 ${b}/-2 ${c}/-1`);
    const r = parseObj(text);
    expect(r.positions.length / 3).toBe(150);
    for (let o = 0; o < 150; o++) {
      // Each vertex's uv names its position (u: the 1-based index) and its place in the face (v).
      const p = position(r, o);
      const index = 6 * p[1] + p[0] + 1;
      expect(r.uvs![2 * o], `vertex ${o}`).toBe(index);
    }
  });

  it('triangulates a convex 100-gon (more corners than the scratch list starts with), with and without uvs', () => {
    const n = 100;
    const ring: [number, number][] = Array.from({ length: n }, (_, k) => [Math.cos((2 * Math.PI * k) / n), Math.sin((2 * Math.PI * k) / n)]);
    const vs = ring.map(([x, y]) => `v ${x} ${y} 0`).join('\n');
    const face = Array.from({ length: n }, (_, k) => k + 1);
    for (const text of [`${vs}\nf ${face.join(' ')}\n`, `${vs}\nvt 0 0\nf ${face.map((k) => `${k}/1`).join(' ')}\n`]) {
      const r = parseObj(text);
      expect(r.indices.length / 3).toBe(n - 2);
      let area = 0;
      for (const t of triangles(r)) {
        const z = triangleNormal(t)[2];
        expect(z).toBeGreaterThan(0);
        area += z / 2;
      }
      expect(area).toBeCloseTo(polygonArea(ring), 6); // positions are float32
      // Every corner of the polygon is used.
      const used = new Set(triangles(r).flat().map((p: V3) => `${p[0]},${p[1]}`));
      expect(used.size).toBe(n);
    }
  });
});

describe('the growable lists the readers fill (src/loaders/obj/growable.ts)', () => {
  it('keeps every value pushed one, three or reserved at a time past any starting capacity', () => {
    for (const capacity of [1, 2, 3, 4, 1024]) {
      const f = new F64List(capacity), i = new I32List(capacity);
      const wantF: number[] = [], wantI: number[] = [];
      for (let k = 0; k < 700; k++) {
        if (k % 3 === 0) { f.push(k / 4); i.push(k); wantF.push(k / 4); wantI.push(k); }
        else { f.push3(k, -k, k / 2); i.push3(k, -k, 2 * k); wantF.push(k, -k, k / 2); wantI.push(k, -k, 2 * k); }
      }
      expect([...f.data.subarray(0, f.length)], `F64List(${capacity})`).toEqual(wantF);
      expect([...i.data.subarray(0, i.length)], `I32List(${capacity})`).toEqual(wantI);
      const ones = new F64List(capacity), onesI = new I32List(capacity);
      for (let k = 0; k < 3000; k++) { ones.push(k + 0.5); onesI.push(k); }
      expect([...ones.data.subarray(0, ones.length)]).toEqual(Array.from({ length: 3000 }, (_, k) => k + 0.5));
      expect([...onesI.data.subarray(0, onesI.length)]).toEqual(Array.from({ length: 3000 }, (_, k) => k));
      const at = i.length;
      const room = i.reserve(10_000);
      expect(room.length - at, `I32List(${capacity}).reserve`).toBeGreaterThanOrEqual(10_000);
      expect([...room.subarray(0, at)]).toEqual([...i.data.subarray(0, at)]);
      i.clear();
      expect(i.length).toBe(0);
    }
  });
});
