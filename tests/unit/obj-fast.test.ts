// The OBJ parser's fast paths: plain `v` and `f` lines read straight
// into the lists, the weld by position alone for a file of one smoothing group with neither uvs
// nor normals, and the byte scanner's reads past a file that ends without a line end. Each must
// give exactly what the general way gives: the bytes against the text (which never takes a fast
// path), the weld by position against the general weld. And the corner lists both ways write
// (corners.ts) by hand: a plain face added as `add` adds it, each corner's uv and normal index.
import { describe, expect, it, vi } from 'vitest';
import { decodeText } from '../../src/loaders/decode-text';
import { parseObj, parseObjBytes } from '../../src/loaders/obj';
import { buildMesh, newellNormal } from '../../src/loaders/obj/build-mesh';
import { CornerLists, resolve } from '../../src/loaders/obj/corners';
import { ByteScanner } from '../../src/loaders/obj/byte-scanner';
import { readPositionCorners } from '../../src/loaders/obj/position-corners';
import { readObj } from '../../src/loaders/obj/reader';
import { bunnyObj, dragonObj } from '../data/make-obj';
import { expectSameOutcome, outcomeOf } from './helpers/obj-same';
import { instrumented } from './helpers/collections';

const utf8 = (text: string): Uint8Array => new TextEncoder().encode(text);
const TRI = 'v 0 0 0\nv 1 0 0\nv 0 1 0\n';
const QUAD = 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n';

function expectBytesAsText(text: string, label: string): void {
  const bytes = utf8(text);
  const want = outcomeOf(() => parseObj(decodeText(bytes), { url: 'm.obj' }));
  expectSameOutcome(outcomeOf(() => parseObjBytes(bytes, { url: 'm.obj' })), want, label);
}

/** Plain lines (the fast path's) next to lines it must hand back to the general way. */
const CASES: [string, string][] = [
  ['negative indices', `${TRI}f -3 -2 -1\nv 1 1 0\nf -1 -2 -3\nf -4 2 3\n`],
  ['missing vt or vn, and f a//c', `${TRI}vt 0 0\nvt 1 0\nvn 0 0 1\nf 1 2 3\nf 1/1 2/2 3/1\nf 1//1 2//1 3//1\nf 1/1/1 2/2/1 3/1/1\nf 1 2/1 3//1\nf 3 2 1\n`],
  ['the first uv and the first normal on a plain face', `${TRI}f 1 2 3\nvt 0 0\nf 1/1 2/1 3/1\nvn 0 0 1\nf 1//1 2//1 3//1\nf 1 2 3\n`],
  ['polygons of 4, 5 and 64 to 66 corners', `${QUAD}f 1 2 3 4\nv 0.5 1.5 0\nf 1 2 3 5 4\n` +
    [64, 65, 66].map((n) => `f ${Array.from({ length: n }, (_, i) => 1 + (i % 4)).join(' ')}\nf 1 2 3 4\n`).join('')],
  ['exponents, signs and long numbers', `v 1e-3 -2.5E+2 +3e0\nv .5 2. -0\nv 1e23 8.5e-23 123456789012345678\nv 1e400 0 0\nv 0 1e-400 0\nv 1e 2 3\n${TRI}f -3 -2 -1\nf 1 2 3\nf 4 2 3\n`],
  ['trailing blanks and tabs', `v 0 0 0 \t\nv 1 0 0\t\nv\t0 1 0\nf 1 2 3 \t \nf\t1 2 3\nf 1\t2\t3\nf  1  2  3  \n`],
  ['comments mid-file and after a statement', `# a\n${TRI}# b\nf 1 2 3 # c\nf 1 2 3#d\nv 1 1 1#e\n# f\nf 2 3 4\n`],
  ['indices out of range, zero and past 9 digits', `${TRI}f 1 2 3\nf 1 2 4\nf 0 1 2\nf 1 2 999999999\nf 1 2 1234567890\nf 1/5 2 3\nf 1//2 2 3\nf 1 2 3\n`],
  ['faces after a bad vertex', `v 0 0 0\nv 1 x 0\nv 1 0 0\nv 0 1 0\nf 1 3 4\nf 1 2 3\nf 3 4 1\n`],
  ['too few corners and junk', `${TRI}f 1 2\nf\nf 1 2 x\nf 1/2/3/4 2 3\nf 1 2 3 \\\n 1\nf 1 2 3\n`],
  ['colours', `v 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0 0 0 1\nf 1 2 3\nv 1 1 1 0.5 0.5 0.5 1 2\nf 2 3 4\n`],
  ['a vertex and a face at the very end', `${TRI}f 1 2 3\nv 1 1 2.5`],
  ['a face at the very end', `${TRI}v 1 1 0\nf 2 3 4`],
  ['a corner cut by the end', `${TRI}f 1 2 3\nf 1 2 -`],
  // Bare position indices (position-corners.ts): each read as a double, checked against the vertices read so far.
  ['bare indices: leading zeros, the last vertex and one past, signs, long runs of digits', `${QUAD}f 001 02 0003\nf 2 3 4\nf 1 2 5\n` +
    `f +1 2 3\nf 1 2 ${'9'.repeat(400)}\nf 1 2 ${'0'.repeat(30)}3\nf 4 3 2 1\nv 2 2 0\nf 1 2 5\nf 1 2 0\n`],
  ['bare indices after the first uv', `${TRI}vt 0 0\nf 1/1 2/1 3/1\nf 1 2 3\n`],
  ['bare indices after the first normal', `${TRI}vn 0 0 1\nf 1//1 2//1 3//1\nf 3 2 1\n`],
  ['bare indices after a bad texture coordinate or normal', `${TRI}f 1 2 3\nvt x\nf 3 2 1\n${TRI}vn 0 0\nf 4 5 6\nf 1 2 3\n`],
];

const variants = (text: string): [string, string][] => [
  ['', text], [' (CRLF)', text.replace(/\n/g, '\r\n')], [' (CR)', text.replace(/\n/g, '\r')], [' (BOM)', `\uFEFF${text}`],
];

describe('OBJ fast paths: the same result as the general way', () => {
  it('reads plain lines, and the lines the fast path hands back, as the text parser reads them', () => {
    for (const [name, text] of CASES) for (const [how, t] of variants(text)) expectBytesAsText(t, name + how);
  });

  it('names the line of a face the fast path hands back with an index out of range', () => {
    const text = `${TRI}f 1 2 3\n\nf 1 2 999999999\nf 1 2 1234567890\n`;
    for (const [how, t] of variants(text)) {
      const r = parseObjBytes(utf8(t));
      expect(r.warnings, how).toEqual([
        { line: 6, message: 'vertex index 999999999 is outside the 3 vertices read so far; face dropped' },
        { line: 7, message: 'vertex index 1234567890 is outside the 3 vertices read so far; face dropped' },
      ]);
      expect(r.indices.length, how).toBe(3);
    }
  });

  it('reads each line once on the fast path, after a bad vertex too: never again for the statement', () => {
    // The scanner's fast reads, counted: a line the fast path gives up on is read the general
    // way, but no line is handed from one fast path to another to be read again.
    const faces = 100;
    const text = `v 0 0 0\nv 1 x 0\nv 1 0 0\nv 0 1 0\nvt x\nvn 0 0\n${'f 1 3 4\nf 4 3 1\n'.repeat(faces / 2)}f 1 2 3\nf 1 3 9\n`;
    const corners = vi.spyOn(ByteScanner.prototype, 'readPlainCorners');
    const numbers = vi.spyOn(ByteScanner.prototype, 'readPlainNumbers');
    try {
      const r = parseObjBytes(utf8(text));
      expect(r.indices.length).toBe(3 * faces);
      expect(r.warnings.map((w) => w.line)).toEqual([2, 5, 6, faces + 7, faces + 8]);
      expect(corners).toHaveBeenCalledTimes(faces + 2);
      expect(numbers).toHaveBeenCalledTimes(6);
    } finally {
      vi.restoreAllMocks();
    }
  });

  it('reads the last number of a file with no line end after it, and stops at its end', () => {
    const r = parseObjBytes(utf8(`${TRI}f 1 2 3\nv 0 1 0.125`));
    expect(r.warnings).toEqual([]);
    const last = parseObjBytes(utf8(`v 0 0 0\nv 1 0 0\nv 0 1 0.125\nf 1 2 3`));
    expect([...last.positions.slice(6)]).toEqual([0, 1, 0.125]);
    expect(r.indices.length).toBe(3);
    const sc = new ByteScanner(utf8('1 22 0.5e1'));
    const values = new Float64Array(8);
    expect(sc.readPlainNumbers(values)).toBe(3);
    expect([...values.slice(0, 3)]).toEqual([1, 22, 5]);
    expect(sc.atEnd()).toBe(true);
  });

  it('reads a face of bare indices only up to its line end, the cursor unmoved when it hands the face back', () => {
    const room = new Int32Array(8);
    const sc = new ByteScanner(utf8(`f 1 2\t3  \nf 1 2 3 # c\nf 1 2 3 4 5\n`));
    sc.pos = 1;
    expect(readPositionCorners(sc, room, 2, 6, 3)).toBe(3);
    expect([...room.slice(2, 5)]).toEqual([0, 1, 2]);
    expect(sc.code(sc.pos)).toBe(10);
    for (const [from, vCount, fits] of [[12, 3, 6], [24, 4, 6], [24, 5, 4]]) {
      sc.pos = from;
      expect(readPositionCorners(sc, room, 0, fits, vCount)).toBe(-1);
      expect(sc.pos).toBe(from);
    }
    expect(readPositionCorners(sc, room, 0, 5, 5)).toBe(5);
  });

  it('reads bare indices of all ten digits up to a CR line end, and hands back digits run into a letter', () => {
    const room = new Int32Array(8);
    const sc = new ByteScanner(utf8(`f 1094 23 8765\rf 1 2 3x\r\n`));
    sc.pos = 1;
    expect(readPositionCorners(sc, room, 0, 8, 9000)).toBe(3);
    expect([...room.slice(0, 3)]).toEqual([1093, 22, 8764]);
    expect(sc.code(sc.pos)).toBe(13);
    // `3x` is no index, though 3 × 10 + (x − 0) = 102 would be one of 200 vertices.
    sc.pos = 16;
    expect(readPositionCorners(sc, room, 0, 8, 200)).toBe(-1);
    expect(sc.pos).toBe(16);
  });

  it("sums a triangle's Newell normal exactly as the loop over a polygon's edges does", () => {
    // The loop newellNormal runs for a polygon, here on 3 corners: edge last→first, then in order.
    const loop = (pos: Float64Array, corners: Int32Array): number[] => {
      let nx = 0, ny = 0, nz = 0;
      for (let k = 0, j = 3 * corners[2]; k < 3; j = 3 * corners[k++]) {
        const i = 3 * corners[k];
        nx += (pos[j + 1] - pos[i + 1]) * (pos[j + 2] + pos[i + 2]);
        ny += (pos[j + 2] - pos[i + 2]) * (pos[j] + pos[i]);
        nz += (pos[j] - pos[i]) * (pos[j + 1] + pos[i + 1]);
      }
      return [nx, ny, nz];
    };
    let seed = 7;
    const random = (): number => (seed = (seed * 16807) % 2147483647) / 2147483647 - 0.5;
    const out = new Float64Array(3);
    for (let t = 0; t < (instrumented ? 200 : 2000); t++) { // StrykerJS: fewer, for its time a mutant
      const pos = Float64Array.from({ length: 12 }, () => (t % 3 === 0 ? Math.round(4 * random()) : random() * 10 ** (t % 7)));
      const corners = Int32Array.from([3, 1, 0, 2].slice(t % 2, (t % 2) + 3));
      newellNormal(pos, corners, 0, 3, out);
      expect([...out], `triangle ${t}`).toEqual(loop(pos, corners));
    }
  });

  it('welds by position alone exactly as the general weld', { timeout: 60_000 }, () => {
    const files: [string, string][] = [
      // The scans only outside StrykerJS, where each took many seconds a mutant.
      ...(instrumented ? [] : [['bunny', bunnyObj()], ['dragon res4', dragonObj(4)]] as [string, string][]),
      ['polygons', `${QUAD}v 0.5 1.5 0.25\nf 1 2 3 5 4\nf 1 2 3 4\nf -5 -4 -3\n`],
      ['colours', `v 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0 0 0 1\nv 1 1 1\nf 1 2 3\nf 2 4 3\n`],
      ['materials that come back', `${QUAD}usemtl a\nf 1 2 3\nusemtl b\nf 1 3 4\nusemtl a\nf 2 3 4\ns 1\nusemtl b\nf 1 2 4\n`],
      ['one named smoothing group', `s 1\n${QUAD}f 1 2 3\nf 1 3 4\ns 1\nf 2 3 4\n`],
    ];
    for (const [name, text] of files) {
      const raw = readObj(text);
      const fast = buildMesh(raw), general = buildMesh(raw, false);
      expectSameOutcome({ ok: true, result: { ...fast, warnings: [] } }, { ok: true, result: { ...general, warnings: [] } }, name);
    }
  });

  it('welds each smoothing group, uv and normal apart where the file has them', () => {
    // Two smoothing groups meeting at an edge: its two positions have a vertex in each.
    const r = parseObj(`${QUAD}s 1\nf 1 2 3\ns 2\nf 1 3 4\n`);
    expect(r.positions.length / 3).toBe(6);
    const flat = parseObj(`${QUAD}s off\nf 1 2 3\nf 1 3 4\n`);
    expect(flat.positions.length / 3).toBe(6);
    const uv = parseObj(`${QUAD}vt 0 0\nvt 1 1\nf 1/1 2/1 3/1\nf 1/2 3/1 4/1\n`);
    expect(uv.positions.length / 3).toBe(5);
  });
});

/** A list's elements (up to its length); null for none. */
const elements = (list: { data: Int32Array; length: number } | null) => (list ? [...list.data.slice(0, list.length)] : null);

describe('the corner lists (corners.ts)', () => {
  it('resolves 1-based and negative indices, −2 for any outside the elements read so far', () => {
    expect([1, 3, -1, -3].map((i) => resolve(i, 3))).toEqual([0, 2, 2, 0]);
    expect([0, 4, -4, -6].map((i) => resolve(i, 3))).toEqual([-2, -2, -2, -2]);
  });

  it('starts the uv and normal lists at the first corner with one: −1 for each corner without', () => {
    const c = new CornerLists(4);
    expect(c.positionsOnly()).toBe(true);
    // add(v, t, n, and the vertices, uvs and normals read so far): 0 for no uv or normal.
    expect([c.add(1, 0, 0, 3, 2, 2), c.add(-1, 0, 0, 3, 2, 2)]).toEqual(['', '']);
    expect([elements(c.corners), c.uvs, c.normals, c.positionsOnly()]).toEqual([[0, 2], null, null, true]);
    expect(c.add(2, 2, 0, 3, 2, 2)).toBe('');
    expect([elements(c.uvs), c.normals, c.positionsOnly()]).toEqual([[-1, -1, 1], null, false]);
    expect([c.add(3, 0, -1, 3, 2, 2), c.add(1, 0, 0, 3, 2, 2)]).toEqual(['', '']);
    expect([elements(c.corners), elements(c.uvs), elements(c.normals)]).toEqual([
      [0, 2, 1, 2, 0], [-1, -1, 1, -1, -1], [-1, -1, -1, 1, -1],
    ]);
    // A normal first, no uv.
    const n = new CornerLists(4);
    expect(n.add(1, 0, 2, 3, 2, 2)).toBe('');
    expect([n.uvs, elements(n.normals), n.positionsOnly()]).toEqual([null, [1], false]);
  });

  it("forgets a dropped face's corners from every list", () => {
    const c = new CornerLists(4);
    for (const v of [1, 2, 3]) expect(c.add(v, 1, 1, 3, 1, 1)).toBe('');
    c.truncate(1);
    expect([elements(c.corners), elements(c.uvs), elements(c.normals)]).toEqual([[0], [0], [0]]);
  });

  it('writes a plain face as add would; else false, the lists as they were', () => {
    // Raw v, t, n of each corner, 0 for none.
    const face = (...corners: number[]) => new Int32Array(corners);
    const c = new CornerLists(4);
    expect(c.addPlain(face(1, 0, 0, -1, 0, 0, 2, 0, 0), 3, 3, 0, 0)).toBe(true);
    expect([elements(c.corners), c.uvs, c.normals]).toEqual([[0, 2, 1], null, null]);
    // A corner out of range, or one that would start the uv or the normal list: add's to do.
    for (const raw of [face(1, 0, 0, 4, 0, 0), face(1, 0, 0, 2, 1, 0), face(1, 0, 0, 2, 0, 1)]) {
      expect(c.addPlain(raw, 2, 3, 1, 1), `${raw}`).toBe(false);
      expect(c.corners.length).toBe(3);
    }
    // Once both lists are there, corners with and without a uv or normal.
    expect(c.add(1, 1, 1, 3, 2, 2)).toBe('');
    expect(c.addPlain(face(2, 2, 0, 3, 0, -1, 1, -2, 2), 3, 3, 2, 2)).toBe(true);
    expect([elements(c.corners), elements(c.uvs), elements(c.normals)]).toEqual([
      [0, 2, 1, 0, 1, 2, 0], [-1, -1, -1, 0, 1, -1, 0], [-1, -1, -1, 0, -1, 1, 1],
    ]);
    // A uv or a normal out of range.
    for (const raw of [face(1, 3, 1), face(1, 1, 3), face(1, -3, 1), face(1, 1, -3)]) {
      expect(c.addPlain(raw, 1, 3, 2, 2), `${raw}`).toBe(false);
      expect([c.corners.length, c.uvs?.length, c.normals?.length]).toEqual([7, 7, 7]);
    }
  });
});
