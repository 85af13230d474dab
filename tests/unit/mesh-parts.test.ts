// ObjResult → scene mesh parts (one per material), bounding spheres, and the sniffed formats
// that are load errors before any parsing.
import { describe, expect, it } from 'vitest';
import { parseObj } from '../../src/loaders/obj';
import { boundingSphere, meshParts } from '../../src/element/children/mesh-parts';
import { formatProblem } from '../../src/element/children/model-parse';
import { sniffModel } from '../../src/loaders/sniff';

const TWO_MATERIALS = `mtllib m.mtl
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
usemtl red
f 1/1 2/2 3/3
usemtl blue
f 1/1 3/3 4/4
`;

describe('meshParts', () => {
  it('splits a model into one part per usemtl range, sharing the vertex arrays', () => {
    const obj = parseObj(TWO_MATERIALS);
    const parts = meshParts(obj, 'http://x/m.obj');
    expect(parts.map((p) => p.material)).toEqual(['red', 'blue']);
    expect(parts.map((p) => p.geometry.key)).toEqual(['http://x/m.obj#0', 'http://x/m.obj#1']);
    for (const p of parts) {
      expect(p.geometry.kind).toBe('mesh');
      expect(p.geometry.data.positions).toBe(obj.positions);
      expect(p.geometry.data.indices).toHaveLength(3);
      expect(p.hasUvs).toBe(true);
    }
    const all = [...parts[0].geometry.data.indices, ...parts[1].geometry.data.indices];
    expect(all).toEqual([...obj.indices]);
  });

  it('gives a model without vt zero UVs, and says so (spherical mapping by default)', () => {
    const obj = parseObj('v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n');
    const [part] = meshParts(obj, 'k');
    expect(part.hasUvs).toBe(false);
    expect(part.material).toBeNull();
    expect(part.geometry.data.uvs).toEqual(new Float32Array(6));
    expect(part.geometry.data.indices).toBe(obj.indices);
  });

  it('bounds every vertex with a sphere centred on the bounding box', () => {
    const b = boundingSphere(new Float32Array([-1, 0, 0, 3, 0, 0, 1, 2, 0]));
    expect(b.center).toEqual([1, 1, 0]);
    // The farthest vertices are (−1, 0) and (3, 0), √5 away; never less than that.
    expect(b.radius).toBeCloseTo(Math.sqrt(5), 5);
    expect(b.radius).toBeGreaterThanOrEqual(Math.sqrt(5));
    expect(boundingSphere(new Float32Array(0)).radius).toBe(0);
  });
});

describe('formats that are load errors', () => {
  it('rejects HTML and binary bytes before parsing, passes OBJ and the course\'s .byu', () => {
    const bytes = (s: string) => new TextEncoder().encode(s);
    expect(formatProblem(sniffModel(bytes('<!doctype html><html></html>')))).toMatch(/HTML/);
    expect(formatProblem(sniffModel(new Uint8Array([0x89, 0x50, 0x4e, 0x47, 0, 0, 0, 1, 2, 3, 0, 0])))).toMatch(/binary/);
    expect(formatProblem(sniffModel(bytes('3 1\n0 0 0\n1 0 0\n0 1 0\n1 2 3\n')))).toBeNull();
    expect(formatProblem(sniffModel(bytes('1 1\n4\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n')))).toBeNull();
    expect(formatProblem(sniffModel(bytes(TWO_MATERIALS)))).toBeNull();
  });
});
