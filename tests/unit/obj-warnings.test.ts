// The OBJ reader's warnings word for word (docs/scene-model.md#obj-and-mtl): each fault of a v, vt, vn or f
// statement and each statement not drawn, with its line, from text and from bytes alike.
import { describe, expect, it } from 'vitest';
import { parseObj, parseObjBytes, type ObjResult } from '../../src/loaders/obj';

const TRI = 'v 0 0 0\nv 1 0 0\nv 0 1 0\n';

/** The warnings of `text` read as text and as bytes (the same, or the test fails). */
function warnings(text: string): [number, string][] {
  const fromText = parseObj(text, { url: 'w.obj' });
  const fromBytes = parseObjBytes(new TextEncoder().encode(text), { url: 'w.obj' });
  expect(fromBytes.warnings).toEqual(fromText.warnings);
  return fromText.warnings.map((w) => [w.line, w.message]);
}

function parsed(text: string): ObjResult {
  return parseObj(text, { url: 'w.obj' });
}

describe('OBJ warnings: elements', () => {
  it('a vertex with a bad or missing coordinate, quoting the line', () => {
    expect(warnings(`${TRI}v 1 x 2\nv 1 2\nf 1 2 3\n`)).toEqual([
      [4, 'vertex with a coordinate that is not a number ("v 1 x 2"); faces using it are dropped'],
      [5, 'vertex with 2 of its 3 coordinates; faces using it are dropped'],
    ]);
    expect(warnings(`${TRI}v\nf 1 2 3\n`)).toEqual([[4, 'vertex with 0 of its 3 coordinates; faces using it are dropped']]);
    // A letter right after an exponent's digits, or after a number's.
    expect(warnings(`${TRI}v 1e5x 0 0\nv 0 2: 0\nf 1 2 3\n`)).toEqual([
      [4, 'vertex with a coordinate that is not a number ("v 1e5x 0 0"); faces using it are dropped'],
      [5, 'vertex with a coordinate that is not a number ("v 0 2: 0"); faces using it are dropped'],
    ]);
  });

  it('quotes at most the last 60 characters of a long bad vertex line', () => {
    const line = `v 1 2 ${'9'.repeat(70)}x`;
    expect(warnings(`${TRI}${line}\nf 1 2 3\n`)).toEqual([
      [4, `vertex with a coordinate that is not a number (${JSON.stringify(`${line.slice(-60).slice(0, 40)}…`)}); faces using it are dropped`],
    ]);
  });

  it('a vertex with more than x y z r g b and one more', () => {
    const r = parsed(`${TRI}v 1 2 3 0.5 0.5 0.5 1\nv 1 2 3 0.5 0.5 0.5 1 2\nf 1 2 3\n`);
    expect(r.warnings).toEqual([{ line: 5, message: 'vertex with 8 values; those after x y z r g b ignored' }]);
    expect(warnings(`${TRI}v 1 2 3 4 5 6 7 8 9 10\nf 1 2 3\n`)).toEqual([[4, 'vertex with 10 values; those after x y z r g b ignored']]);
  });

  it('a texture coordinate or normal that is not a number, or a normal with too few values', () => {
    expect(warnings(`${TRI}vt x\nvt\nvn 1 x 0\nvn 1 0\nvn\nf 1 2 3\n`)).toEqual([
      [4, 'texture coordinate that is not a number ("vt x"); faces using it are dropped'],
      [5, 'texture coordinate that is not a number ("vt"); faces using it are dropped'],
      [6, 'normal with a value that is not a number; faces using it are dropped'],
      [7, 'normal with 2 of its 3 values; faces using it are dropped'],
      [8, 'normal with 0 of its 3 values; faces using it are dropped'],
    ]);
  });
});

describe('OBJ warnings: faces', () => {
  it('a face of fewer than 3 corners, counted', () => {
    expect(warnings(`${TRI}f 1 2\nf 1\nf\nf 1 2 3\n`)).toEqual([
      [4, 'face with 2 vertices (a face needs 3); face dropped'],
      [5, 'face with 1 vertex (a face needs 3); face dropped'],
      [6, 'face with 0 vertices (a face needs 3); face dropped'],
    ]);
  });

  it('a corner that is not one, quoted', () => {
    expect(warnings(`${TRI}f 1 2 x\nf 1 2/y 3\nf 1/ 2 3a\nf 1 2 3\n`)).toEqual([
      [4, '"x" is not a face corner; face dropped'],
      [5, '"2/y" is not a face corner; face dropped'],
      [6, '"3a" is not a face corner; face dropped'],
    ]);
  });

  it('an index outside the elements read so far, for each kind, named as written', () => {
    expect(warnings(`${TRI}vt 0 0\nvn 0 0 1\nf 1 2 4\nf 1/2 2/1 3/1\nf 1//2 2//1 3//1\nf -4 1 2\nf 1/-2 2/1 3/1\nf 1 2 3\n`)).toEqual([
      [6, 'vertex index 4 is outside the 3 vertices read so far; face dropped'],
      [7, 'texture coordinate index 2 is outside the 1 read so far; face dropped'],
      [8, 'normal index 2 is outside the 1 read so far; face dropped'],
      [9, 'vertex index -4 is outside the 3 vertices read so far; face dropped'],
      [10, 'texture coordinate index -2 is outside the 1 read so far; face dropped'],
    ]);
  });

  it('a corner on a bad element, naming the element and the line that made it unusable', () => {
    const text = `${TRI}v 1 x 1\nvt 0 0\nvt y\nvn 0 0 1\nvn z 0 1\nf 1 2 4\nf 1/2 2/1 3/1\nf 1//2 2//1 3//1\nf 1/1/1 2/1/1 3/1/1\n`;
    expect(warnings(text)).toEqual([
      [4, 'vertex with a coordinate that is not a number ("v 1 x 1"); faces using it are dropped'],
      [6, 'texture coordinate that is not a number ("vt y"); faces using it are dropped'],
      [8, 'normal with a value that is not a number; faces using it are dropped'],
      [9, 'vertex 4 (line 4) is not usable; face dropped'],
      [10, 'texture coordinate 2 (line 6) is not usable; face dropped'],
      [11, 'normal 2 (line 8) is not usable; face dropped'],
    ]);
    expect([...parsed(text).indices]).toEqual([0, 1, 2]);
  });

  it('a corner whose normal index is not a number, quoted as written', () => {
    expect(warnings(`${TRI}vn 0 0 1\nf 1//x 2//1 3//1\nf 1//1 2//1 3//1\n`)).toEqual([[5, '"1//x" is not a face corner; face dropped']]);
  });

  it('a corner on the first texture coordinate or normal, when that one is bad', () => {
    const text = `${TRI}vt y\nvn z 0 1\nvt 0 0\nvn 0 0 1\nf 1/1 2/2 3/2\nf 1//1 2//2 3//2\nf 1/2/2 2/2/2 3/2/2\n`;
    expect(warnings(text)).toEqual([
      [4, 'texture coordinate that is not a number ("vt y"); faces using it are dropped'],
      [5, 'normal with a value that is not a number; faces using it are dropped'],
      [8, 'texture coordinate 1 (line 4) is not usable; face dropped'],
      [9, 'normal 1 (line 5) is not usable; face dropped'],
    ]);
    expect([...parsed(text).indices]).toEqual([0, 1, 2]);
  });

  it('a polygon of no area, with its corner count', () => {
    expect(warnings(`${TRI}v 2 0 0\nv 3 0 0\nf 1 2 4 5\nf 1 2 3\n`)).toEqual([
      [6, 'face of 4 vertices with no area (its corners are repeated or on one line); face dropped'],
    ]);
  });
});

describe('OBJ warnings: statements not drawn', () => {
  it('says an unsupported statement once, and an unknown one once, each by its keyword', () => {
    expect(warnings(`${TRI}l 1 2\np 1\nl 2 3\ncurv 0 1\nfoo\nfoo 2\nf 1 2 3\n`)).toEqual([
      [4, '"l" statements are not supported; ignored'],
      [5, '"p" statements are not supported; ignored'],
      [7, '"curv" statements are not supported; ignored'],
      [8, 'unknown statement "foo"; ignored'],
    ]);
  });

  it('reads vp, and two-letter keywords ending as vt or vn does, by their whole keyword', () => {
    expect(warnings(`${TRI}vp 0.5 0.5\nxt 0 0\nxn 0 0 1\nf 1 2 3\n`)).toEqual([
      [4, '"vp" statements are not supported; ignored'],
      [5, 'unknown statement "xt"; ignored'],
      [6, 'unknown statement "xn"; ignored'],
    ]);
  });

  it('reads a bare v ended by a CR or by the end of the file, and a v followed by a vertical tab, as vertices', () => {
    expect(warnings(`${TRI}v\r\nf 1 2 3\nv`)).toEqual([
      [4, 'vertex with 0 of its 3 coordinates; faces using it are dropped'],
      [6, 'vertex with 0 of its 3 coordinates; faces using it are dropped'],
    ]);
    expect(warnings(`${TRI}v\v1 1 0\nf 1 2 4\n`)).toEqual([]);
  });

  it('counts unknown keywords by their first 64 characters (a binary file read as OBJ warns once per prefix)', () => {
    const long = 'k'.repeat(64);
    const got = warnings(`${TRI}${long}a 1\n${long}b 2\n${'k'.repeat(63)}c\nf 1 2 3\n`);
    expect(got.map(([line]) => line)).toEqual([4, 6]);
  });

  it('reads o, g, s, usemtl and mtllib without a warning', () => {
    expect(warnings(`o a\ng b c\ns 1\ns off\nusemtl m\nmtllib a.mtl\n${TRI}f 1 2 3\n`)).toEqual([]);
  });
});
