// OBJ statements and syntax as found in the wild (docs/scene-model.md#obj-and-mtl): one `it` per item, exact numbers.
import { describe, expect, it } from 'vitest';
import { normalizeObj, parseObj, parseObjBytes } from '../../src/loaders/obj';
import { normal, position } from './helpers/obj';
import { instrumented } from './helpers/collections';

const TRI = 'v 0 0 0\nv 1 0 0\nv 0 1 0\n';
const f32 = (xs: number[]): number[] => xs.map(Math.fround);

describe('parseObj: statements', () => {
  it('reads v and a triangle f into typed arrays', () => {
    const r = parseObj(`${TRI}f 1 2 3\n`);
    expect(r.positions).toBeInstanceOf(Float32Array);
    expect([...r.positions]).toEqual([0, 0, 0, 1, 0, 0, 0, 1, 0]);
    expect(r.indices).toBeInstanceOf(Uint16Array);
    expect([...r.indices]).toEqual([0, 1, 2]);
    expect([...r.normals]).toEqual([0, 0, 1, 0, 0, 1, 0, 0, 1]);
    expect(r.uvs).toBeNull();
    expect(r.colors).toBeNull();
    expect(r.groups).toEqual([{ material: null, start: 0, count: 3 }]);
    expect(r.bounds).toEqual({ min: [0, 0, 0], max: [1, 1, 0] });
    expect(r.warnings).toEqual([]);
  });

  it('reads vertex colours after the coordinates (and 1 1 1 for vertices without)', () => {
    const r = parseObj('v 0 0 0 1 0 0\nv 1 0 0 0 0.5 0\nv 0 1 0\nf 1 2 3\n');
    expect([...r.colors!]).toEqual(f32([1, 0, 0, 0, 0.5, 0, 1, 1, 1]));
    expect([...r.positions]).toEqual([0, 0, 0, 1, 0, 0, 0, 1, 0]);
    // The first colour on the second vertex: white for the one before.
    expect([...parseObj('v 0 0 0\nv 1 0 0 0 0.5 0\nv 0 1 0\nf 1 2 3\n').colors!]).toEqual(f32([1, 1, 1, 0, 0.5, 0, 1, 1, 1]));
  });

  it('reads a w after x y z as no colour', () => {
    const r = parseObj('v 0 0 0 1\nv 1 0 0 1\nv 0 1 0 1\nf 1 2 3\n');
    expect(r.colors).toBeNull();
    expect(r.warnings).toEqual([]);
  });

  it('reads vt with f v/vt', () => {
    const r = parseObj(`${TRI}vt 0 0\nvt 1 0\nvt 0.25 0.75 0\nf 1/1 2/2 3/3\n`);
    expect([...r.uvs!]).toEqual([0, 0, 1, 0, 0.25, 0.75]);
  });

  it('reads a vt with only u as v = 0', () => {
    const r = parseObj(`${TRI}vt 0.5\nf 1/1 2/1 3/1\n`);
    expect([...r.uvs!]).toEqual([0.5, 0, 0.5, 0, 0.5, 0]);
  });

  it('reads vn with f v//vn, normalised, instead of generating', () => {
    const r = parseObj(`${TRI}vn 0 0 -2\nf 1//1 2//1 3//1\n`);
    expect([...r.normals]).toEqual([0, 0, -1, 0, 0, -1, 0, 0, -1]);
    expect(r.uvs).toBeNull();
  });

  it('reads f v/vt/vn', () => {
    const r = parseObj(`${TRI}vt 0 0\nvt 1 1\nvn 1 0 0\nvn 0 1 0\nf 1/1/1 2/2/2 3/1/2\n`);
    expect([...r.uvs!]).toEqual([0, 0, 1, 1, 0, 0]);
    expect([...r.normals]).toEqual([1, 0, 0, 0, 1, 0, 0, 1, 0]);
  });

  it('resolves negative indices against the elements read so far', () => {
    const r = parseObj(`${TRI}vt 0.5 0.5\nf -3/-1 -2/-1 -1/-1\nv 5 0 0\nv 6 0 0\nv 5 1 0\nf -3 -2 -1\n`);
    expect(r.warnings).toEqual([]);
    expect([...r.positions]).toEqual([0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 0, 0, 6, 0, 0, 5, 1, 0]);
    expect([...r.indices]).toEqual([0, 1, 2, 3, 4, 5]);
  });

  it('resolves negative vt and vn indices against the coordinates and normals read so far, each list apart', () => {
    // Two vt and three vn before the face: -1 is the last of each, -2 the one before.
    const r = parseObj(`${TRI}vt 0.25 0.5\nvt 0.75 1\nvn 1 0 0\nvn 0 1 0\nvn 0 0 1\nf 1/-2/-3 2/-1/-1 3/-1/-2\n`);
    expect(r.warnings).toEqual([]);
    expect([...r.uvs!]).toEqual([0.25, 0.5, 0.75, 1, 0.75, 1]);
    expect([...r.normals]).toEqual([1, 0, 0, 0, 0, 1, 0, 1, 0]);
  });

  it('splits a convex quad into two triangles over its 4 vertices', () => {
    const r = parseObj('v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n');
    expect(r.positions.length / 3).toBe(4);
    expect([...r.indices]).toEqual([0, 1, 2, 0, 2, 3]);
  });

  it('keeps o names and g names (several on one g line, names with spaces on o)', () => {
    const r = parseObj(`o My Object\ng left right\n${TRI}f 1 2 3\ng left\no Other\nf 1 2 3\n`);
    expect(r.objects).toEqual(['My Object', 'Other']);
    expect(r.groupNames).toEqual(['left', 'right']);
  });

  it('gives one draw range per usemtl material, in order of first use', () => {
    const r = parseObj(`${TRI}f 1 2 3\nusemtl red\nf 1 3 2\nusemtl blue glass\nf 2 1 3\nusemtl red\nf 3 2 1\n`);
    expect(r.groups).toEqual([
      { material: null, start: 0, count: 3 },
      { material: 'red', start: 3, count: 6 },
      { material: 'blue glass', start: 9, count: 3 },
    ]);
    // The two red faces are adjacent in the index buffer, in file order.
    expect([...r.indices.slice(3, 9)]).toEqual([0, 2, 1, 2, 1, 0]);
  });

  it('reads mtllib: several names, a name with spaces, backslashes, repeated lines', () => {
    const r = parseObj(
      `mtllib a.mtl b.MTL\nmtllib my model.mtl other.mtl\nmtllib tex\\sub\\c.mtl\nmtllib a.mtl\nmtllib plain names\n${TRI}f 1 2 3\n`,
    );
    expect(r.mtllibs).toEqual(['a.mtl', 'b.MTL', 'my model.mtl', 'other.mtl', 'tex/sub/c.mtl', 'plain', 'names']);
  });

  it('reads a bare o, g or mtllib as no name, and a name ends only at a token ending in .mtl', () => {
    const r = parseObj(`o\ng\nmtllib\nmtllib  \no  \n${TRI}f 1 2 3\n`);
    expect([r.objects, r.groupNames, r.mtllibs]).toEqual([[], [], []]);
    expect(parseObj(`mtllib old.mtl.bak b.mtl\n${TRI}f 1 2 3\n`).mtllibs).toEqual(['old.mtl.bak b.mtl']);
    expect(parseObj(`o a\ng x y\no b\ng y z\no a\n${TRI}f 1 2 3\n`)).toMatchObject({ objects: ['a', 'b'], groupNames: ['x', 'y', 'z'] });
  });

  it('ends a name at a # right after the keyword or after a blank (space, tab, vertical tab, form feed), not inside it', () => {
    const r = parseObj(`o#c\ng a\t#c\nusemtl red #c\n${TRI}f 1 2 3\nusemtl blue\v#c\nf 1 2 3\nusemtl red#1\f#c\nf 1 2 3\n`);
    expect([r.objects, r.groupNames]).toEqual([[], ['a']]);
    expect(r.groups.map((g) => g.material)).toEqual(['red', 'blue', 'red#1']);
  });

  it('ignores # comments, whole-line and after a statement', () => {
    const r = parseObj(`# v 9 9 9\n${TRI}f 1 2 3 # f 3 2 1\n  # indented comment\n`);
    expect(r.positions.length).toBe(9);
    expect([...r.indices]).toEqual([0, 1, 2]);
    expect(r.warnings).toEqual([]);
  });
});

describe('parseObj: syntax', () => {
  it('joins lines ending in \\ and keeps counting physical lines', () => {
    const r = parseObj('v 0 0 0\nv 1 0 \\\n0\nv 0 1 0\nf 1 \\\r\n2 3\nf 1 2 9\n');
    expect([...r.positions]).toEqual([0, 0, 0, 1, 0, 0, 0, 1, 0]);
    expect([...r.indices]).toEqual([0, 1, 2]);
    expect(r.warnings.map((w) => w.line)).toEqual([7]);
  });

  it('reads CRLF files as LF files, with the same line numbers', () => {
    const lf = 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 7\n';
    const a = parseObj(lf);
    const b = parseObj(lf.replace(/\n/g, '\r\n'));
    expect([...b.positions]).toEqual([...a.positions]);
    expect([...b.indices]).toEqual([...a.indices]);
    expect(b.warnings).toEqual(a.warnings);
    expect(b.warnings[0].line).toBe(5);
  });

  it('reads a file without a final newline', () => {
    const r = parseObj(`${TRI}f 1 2 3`);
    expect([...r.indices]).toEqual([0, 1, 2]);
  });

  it('takes tabs and runs of spaces as separators, leading and trailing too', () => {
    const r = parseObj('\tv\t0   0 \t 0  \n  v 1\t\t0 0\nv    0 1    0\t\nf\t1  2\t\t3 \n');
    expect([...r.positions]).toEqual([0, 0, 0, 1, 0, 0, 0, 1, 0]);
    expect([...r.indices]).toEqual([0, 1, 2]);
    expect(r.warnings).toEqual([]);
  });

  it('takes form feeds and vertical tabs as separators too, after numbers and indices', () => {
    // One vertical tab only: two in so short a file would be sniffed as binary (sniff.ts).
    const r = parseObj('v\f0\f0 0\nv 1\v0\f0\nv 0\f1 0\nf 1\f2\f3\n');
    expect([...r.positions]).toEqual([0, 0, 0, 1, 0, 0, 0, 1, 0]);
    expect([...r.indices]).toEqual([0, 1, 2]);
    expect(r.warnings).toEqual([]);
  });

  it('reads numbers like .5, 2., 1e-5, 1E+2, +1, -.5, -0.25e1', () => {
    const r = parseObj('v .5 2. 1e-5\nv 1E+2 +1 -0.25e1\nv -.5 -2. 1.5E-3\nf 1 2 3\n');
    expect([...r.positions]).toEqual(f32([0.5, 2, 1e-5, 100, 1, -2.5, -0.5, -2, 1.5e-3]));
    expect(r.warnings).toEqual([]);
  });

  it('reads long decimals to float32 exactly as parseFloat does', () => {
    const xs = ['0.123456789012345678', '-12345.6789e-3', '-3.4028234e38', '1e-45', '-0.7071067811865475', '123456789012345678901'];
    const r = parseObj(`v ${xs[0]} ${xs[1]} ${xs[2]}\nv ${xs[3]} ${xs[4]} ${xs[5]}\nv 0 0 0\nf 1 2 3\n`);
    expect([...r.positions.slice(0, 6)]).toEqual(f32(xs.map(Number)));
  });

  it('skips a UTF-8 BOM, in a string and in bytes', () => {
    const text = `\uFEFF${TRI}f 1 2 3\n`;
    expect([...parseObj(text).indices]).toEqual([0, 1, 2]);
    const bytes = new TextEncoder().encode(text);
    expect(bytes[0]).toBe(0xef);
    const r = parseObjBytes(bytes);
    expect([...r.positions]).toEqual([0, 0, 0, 1, 0, 0, 0, 1, 0]);
    expect(r.warnings).toEqual([]);
  });

  it('reads UTF-16 LE and BE with a BOM, from an ArrayBuffer too', () => {
    const text = `o Zoë\n${TRI}f 1 2 3\n`;
    for (const littleEndian of [true, false]) {
      const bytes = new Uint8Array(2 + 2 * text.length);
      const view = new DataView(bytes.buffer);
      view.setUint16(0, 0xfeff, littleEndian);
      for (let i = 0; i < text.length; i++) view.setUint16(2 + 2 * i, text.charCodeAt(i), littleEndian);
      const r = parseObjBytes(bytes.buffer);
      expect([...r.indices]).toEqual([0, 1, 2]);
      expect(r.objects).toEqual(['Zoë']);
    }
  });
});

describe('parseObj: vertices and indices', () => {
  it('shares a vertex between faces only when v, vt and vn all match', () => {
    const quad = 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n';
    const same = parseObj(`${quad}f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n`);
    expect(same.positions.length / 3).toBe(4);
    expect([...same.indices]).toEqual([0, 1, 2, 0, 2, 3]);
    const seam = parseObj(`${quad}f 1/1 2/2 3/3\nf 1/5 3/3 4/4\n`);
    expect(seam.positions.length / 3).toBe(5);
    expect([...seam.indices]).toEqual([0, 1, 2, 3, 2, 4]);
    expect([...seam.uvs!.slice(6, 8)]).toEqual([0.5, 0.5]);
  });

  it('smooths across a UV seam: both copies of a position get the same generated normal', () => {
    const r = parseObj('v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvt 1 1\nf 1/1 2/1 3/1\nf 1/2 4/1 2/1\n');
    expect(r.positions.length / 3).toBe(5);
    const copies = [0, 1, 2, 3, 4].filter((i) => position(r, i).every((c) => c === 0));
    expect(copies.length).toBe(2);
    expect(normal(r, copies[0])).toEqual(normal(r, copies[1]));
    const s = Math.SQRT1_2;
    expect(normal(r, copies[0]).map((c) => c.toFixed(6))).toEqual([0, s, s].map((c) => c.toFixed(6)));
  });

  it('mixes given and generated normals within one face', () => {
    const r = parseObj(`${TRI}vn 1 0 0\nf 1//1 2 3\n`);
    expect([...r.normals]).toEqual([1, 0, 0, 0, 0, 1, 0, 0, 1]);
  });

  it('outputs only the vertices faces use, and bounds of those alone', () => {
    const r = parseObj(`v 100 100 100\n${TRI}v -50 0 0\nf 2 3 4\n`);
    expect(r.positions.length / 3).toBe(3);
    expect(r.bounds).toEqual({ min: [0, 0, 0], max: [1, 1, 0] });
  });

  // 65,536 vertices twice: seconds for each mutant it covers under StrykerJS, skipped there.
  it.skipIf(instrumented)('uses 16-bit indices up to 65535 vertices and 32-bit above', () => {
    const grid = (n: number): string => {
      const lines: string[] = [];
      for (let i = 0; i < n; i++) lines.push(`v ${i} ${i % 3} 0`);
      // Triangles over every vertex; the last one overlaps the one before when n % 3 ≠ 0.
      for (let i = 1; i <= n; i += 3) lines.push(`f ${Math.min(i, n - 2)} ${Math.min(i, n - 2) + 1} ${Math.min(i, n - 2) + 2}`);
      return lines.join('\n');
    };
    const small = parseObj(grid(65535));
    expect(small.positions.length / 3).toBe(65535);
    expect(small.indices).toBeInstanceOf(Uint16Array);
    const big = parseObj(grid(65536));
    expect(big.positions.length / 3).toBe(65536);
    expect(big.indices).toBeInstanceOf(Uint32Array);
    expect(big.indices[big.indices.length - 1]).toBe(65535);
  });
});

describe('normalizeObj', () => {
  it('centres the bounds on the origin and scales the longest side to 2, leaving the input alone', () => {
    const r = parseObj('v 1 2 3\nv 5 4 3\nv 1 4 3\nf 1 2 3\n');
    const n = normalizeObj(r);
    expect([...n.positions]).toEqual([-1, -0.5, 0, 1, 0.5, 0, -1, 0.5, 0]);
    expect(n.bounds).toEqual({ min: [-1, -0.5, 0], max: [1, 0.5, 0] });
    expect(n.indices).toBe(r.indices);
    expect(n.normals).toBe(r.normals);
    expect([...r.positions]).toEqual([1, 2, 3, 5, 4, 3, 1, 4, 3]);
  });

  it('only centres a model with no extent (no division by zero)', () => {
    const n = normalizeObj(parseObj('v 2 2 2\nv 2 2 2\nv 2 2 2\nf 1 2 3\n'));
    expect([...n.positions]).toEqual([0, 0, 0, 0, 0, 0, 0, 0, 0]);
  });
});
