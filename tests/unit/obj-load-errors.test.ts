// The OBJ loader's load errors word for word (docs/scene-model.md#loading): what was rejected and on which line,
// the worker job's error detail for any exception, and a course .byu as the model the element draws.
import { describe, expect, it } from 'vitest';
import { parseObj, parseObjBytes } from '../../src/loaders/obj';
import { runObjJob } from '../../src/loaders/obj-job';
import { bezierObj, parseByuModel } from '../../src/loaders/course/byu-model';
import { loadErrorOf } from './helpers/course';

const TRI = 'v 0 0 0\nv 1 0 0\nv 0 1 0\n';
const utf8 = (text: string): Uint8Array => new TextEncoder().encode(text);

describe('parseObj and parseObjBytes: load errors', () => {
  it('says how many faces were dropped, one or several, on the line of the first', () => {
    expect(loadErrorOf(() => parseObj(`${TRI}f 1 2 7\n`, { url: 'm.obj' })).message)
      .toBe('glass-plane-scene: m.obj line 4: no faces to draw: 1 face dropped, the first here');
    expect(loadErrorOf(() => parseObj(`${TRI}\nf 1 2\nf 1 2 9\n`, { url: 'm.obj' })).message)
      .toBe('glass-plane-scene: m.obj line 5: no faces to draw: 2 faces dropped, the first here');
    expect(loadErrorOf(() => parseObjBytes(utf8(`${TRI}f 1 2 7\n`))).detail)
      .toEqual({ type: 'load', url: '', line: 4, message: 'no faces to draw: 1 face dropped, the first here' });
    expect(loadErrorOf(() => parseObj(TRI)).detail).toEqual({ type: 'load', url: '', message: 'no faces to draw' });
  });

  it('names an HTML page, a .byu model and binary content, with the line where content starts', () => {
    expect(loadErrorOf(() => parseObj('\n\n <html>', { url: 'a.obj' })).message)
      .toBe('glass-plane-scene: a.obj line 3: an HTML page (or other markup), not an OBJ file');
    expect(loadErrorOf(() => parseObj('\n3 1\n0 0 0\n1 0 0\n0 1 0\n1 2 3\n', { url: 'a.obj' })).message)
      .toBe('glass-plane-scene: a.obj line 2: a .byu model, not an OBJ file');
    expect(loadErrorOf(() => parseObj('\n\n2 2\n4\n', { url: 'a.obj' })).message)
      .toBe('glass-plane-scene: a.obj line 3: a .byu model, not an OBJ file');
    expect(loadErrorOf(() => parseObjBytes(utf8('\n\n\n3 1\n'), { url: 'b.obj' })).detail)
      .toEqual({ type: 'load', url: 'b.obj', line: 4, message: 'a .byu model, not an OBJ file' });
    expect(loadErrorOf(() => parseObj(TRI, { url: 'c.obj', sniffed: 'binary' })).detail)
      .toEqual({ type: 'load', url: 'c.obj', message: 'binary content, not an OBJ file' });
    expect(loadErrorOf(() => parseObjBytes(utf8(TRI), { url: 'c.obj', sniffed: 'binary' })).detail)
      .toEqual({ type: 'load', url: 'c.obj', message: 'binary content, not an OBJ file' });
  });

  it('counts CR-only and CRLF line ends alike when naming the line where markup starts', () => {
    expect(loadErrorOf(() => parseObj('\r\r <html>', { url: 'a.obj' })).line).toBe(3);
    expect(loadErrorOf(() => parseObj('\r\n\r\n <html>', { url: 'a.obj' })).line).toBe(3);
    expect(loadErrorOf(() => parseObjBytes(utf8('\r\r\r<html>'), { url: 'a.obj' })).line).toBe(4);
  });

  it('finds the line of markup past the sniffed 4 KB when the caller sniffed it, and line 1 in a blank file', () => {
    const bytes = utf8(`${'\n'.repeat(5000)}<html>`);
    expect(loadErrorOf(() => parseObjBytes(bytes, { url: 'a.obj', sniffed: 'html' })).line).toBe(5001);
    expect(loadErrorOf(() => parseObjBytes(utf8('\n\n<p>'), { url: 'a.obj', sniffed: 'html' })).line).toBe(3);
    expect(loadErrorOf(() => parseObj('   ', { url: 'a.obj', sniffed: 'html' })).line).toBe(1);
    expect(loadErrorOf(() => parseObj('\n\n', { url: 'a.obj', sniffed: 'html' })).line).toBe(1);
    expect(loadErrorOf(() => parseObj('   ', { url: 'a.obj', sniffed: 'byu-mesh' })).line).toBe(1);
  });

  it('skips a second byte-order mark in bytes as the text parser skips it', () => {
    const r = parseObjBytes(utf8(`\uFEFF\uFEFF${TRI}f 1 2 3\n`));
    expect([r.warnings, Array.from(r.indices)]).toEqual([[], [0, 1, 2]]);
  });

  it('trusts what was sniffed: OBJ text sniffed as OBJ is read even if it would sniff otherwise', () => {
    const r = parseObj(`hello 1\n${TRI}f 1 2 3\n`, { sniffed: 'obj' });
    expect([...r.indices]).toEqual([0, 1, 2]);
    expect(r.warnings).toEqual([{ line: 1, message: 'unknown statement "hello"; ignored' }]);
  });
});

describe('runObjJob: errors and transfers', () => {
  it('hands back an exception that is no LoadError as a load error of its message', () => {
    const throwing = { get length(): number { throw new Error('detached buffer'); } } as unknown as ArrayBuffer;
    expect(runObjJob({ id: 3, url: 'x.obj', bytes: throwing })).toEqual({
      response: { id: 3, ok: false, error: { type: 'load', url: 'x.obj', message: 'detached buffer' } }, transfer: [],
    });
    const throwsString = { get length(): number { throw 'no bytes'; } } as unknown as ArrayBuffer; // eslint-disable-line no-throw-literal
    expect(runObjJob({ id: 4, url: 'y.obj', bytes: throwsString }).response)
      .toEqual({ id: 4, ok: false, error: { type: 'load', url: 'y.obj', message: 'no bytes' } });
  });

  it('hands back a LoadError as its detail, line included', () => {
    expect(runObjJob({ id: 5, url: 'z.obj', bytes: utf8(`${TRI}f 1 2 9\n`).buffer as ArrayBuffer }).response).toEqual({
      id: 5, ok: false, error: { type: 'load', url: 'z.obj', line: 4, message: 'no faces to draw: 1 face dropped, the first here' },
    });
  });

  it('lists the colours for transfer too, and no uvs when there are none; no Bézier for an OBJ', () => {
    const bytes = utf8('v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nf 1 2 3\n').buffer as ArrayBuffer;
    const { response, transfer } = runObjJob({ id: 6, url: 'c.obj', bytes, sniffed: 'obj' });
    if (!response.ok) throw new Error('expected a result');
    const r = response.result;
    expect(r.uvs).toBeNull();
    expect([...r.colors!]).toEqual([1, 0, 0, 0, 1, 0, 0, 0, 1]);
    expect(transfer).toEqual([r.positions.buffer, r.normals.buffer, r.colors!.buffer, r.indices.buffer]);
    expect(response.bezier).toBeNull();
  });

  it('reads the bytes as a .byu only when asked for format byu', () => {
    const bytes = utf8('3 1\n0 0 0\n1 0 0\n0 1 0\n1 2 3\n').buffer as ArrayBuffer;
    expect(runObjJob({ id: 7, url: 't.byu', bytes, format: 'obj' }).response)
      .toMatchObject({ ok: false, error: { message: 'a .byu model, not an OBJ file', line: 1 } });
    expect(runObjJob({ id: 8, url: 't.byu', bytes, format: 'byu' }).response).toMatchObject({ ok: true });
  });
});

describe('parseByuModel and bezierObj', () => {
  it('gives a mesh .byu the bounds of the vertices its faces use, with no uvs, groups or names', () => {
    const model = parseByuModel(utf8('4 1\n0 0 0\n2 0 0\n0 3 0\n-9 9 9\n1 2 3\n'), 'm.byu');
    expect(model.bezier).toBeNull();
    expect(model.obj.bounds).toEqual({ min: [0, 0, 0], max: [2, 3, 0] });
    expect(model.obj).toMatchObject({ uvs: null, colors: null, groups: [], mtllibs: [], objects: [], groupNames: [], warnings: [] });
    expect([...model.obj.indices]).toEqual([0, 1, 2]);
  });

  it('gives a Bézier .byu the bounds of its evaluated points, and its patch to evaluate again', () => {
    // A bilinear patch: the corners (0,0,0), (0,2,0), (4,0,0), (4,2,6) in the file's order.
    const model = parseByuModel(utf8('1 1\n3\n0 0 0\n0 2 0\n4 0 0\n4 2 6\n'), 'p.byu');
    expect(model.obj.positions.length).toBe(3 * 9);
    expect(model.obj.bounds).toEqual({ min: [0, 0, 0], max: [4, 2, 6] });
    expect(model.bezier).toMatchObject({ order: 'second-fastest', fileResolution: 3, patch: { degreeU: 1, degreeV: 1 } });
    expect(Array.from(model.bezier!.patch.points)).toEqual([0, 0, 0, 0, 2, 0, 4, 0, 0, 4, 2, 6]);
    const again = bezierObj(model.bezier!, 5);
    expect(again.positions.length).toBe(3 * 25);
    expect(again.bounds).toEqual({ min: [0, 0, 0], max: [4, 2, 6] });
    expect(again.warnings).toEqual([]);
    // The centre of the patch: the average of its four corners.
    const centre = [0, 1, 2].map((a) => again.positions.filter((_, i) => i % 3 === a)).map((xs) => xs[12]);
    expect(centre).toEqual([2, 1, 1.5]);
  });

  it('gives a Bézier patch the largest value of each axis, wherever its corner', () => {
    const model = parseByuModel(utf8('1 1\n2\n4 0 0\n0 2 0\n0 0 6\n0 0 0\n'), 'c.byu');
    expect(model.obj.bounds).toEqual({ min: [0, 0, 0], max: [4, 2, 6] });
  });

  it('keeps bounds of negative coordinates (min and max start from ±Infinity, not 0)', () => {
    const model = parseByuModel(utf8('1 1\n2\n-1 -2 -3\n-1 -1 -3\n-0.5 -2 -3\n-0.5 -1 -3\n'), 'n.byu');
    expect(model.obj.bounds).toEqual({ min: [-1, -2, -3], max: [-0.5, -1, -3] });
  });
});
