// What every loader says when it fails or warns (docs/scene-model.md#loading): a LoadError's
// console text and event detail, a warning's console text, the warning cap, and how a token
// is quoted in a message.
import { describe, expect, it } from 'vitest';
import { LoadError, warningText } from '../../src/loaders/load-error';
import { shown, Warnings } from '../../src/loaders/warnings';

describe('LoadError', () => {
  it('names the file and the line in its message, and holds the bare parts in its detail', () => {
    const e = new LoadError('models/a.obj', 'no faces to draw', 12);
    expect(e).toBeInstanceOf(Error);
    expect(e.name).toBe('LoadError');
    expect(e.message).toBe('glass-plane-scene: models/a.obj line 12: no faces to draw');
    expect(e.url).toBe('models/a.obj');
    expect(e.line).toBe(12);
    expect(e.detail).toEqual({ type: 'load', url: 'models/a.obj', line: 12, message: 'no faces to draw' });
  });

  it('leaves the line out of message and detail when it has none, and calls a file without URL (inline)', () => {
    const e = new LoadError('', 'binary content, not an OBJ file');
    expect(e.message).toBe('glass-plane-scene: (inline): binary content, not an OBJ file');
    expect(e.line).toBeUndefined();
    expect(e.detail).toStrictEqual({ type: 'load', url: '', message: 'binary content, not an OBJ file' });
    expect('line' in e.detail).toBe(false);
  });
});

describe('warningText', () => {
  it('has the shape of a LoadError message', () => {
    expect(warningText('cam.cfg', { line: 5, message: '1 line after "d hx hy"; ignored' }))
      .toBe('glass-plane-scene: cam.cfg line 5: 1 line after "d hx hy"; ignored');
    expect(warningText('', { line: 2, message: 'x' })).toBe('glass-plane-scene: (inline) line 2: x');
  });
});

describe('Warnings', () => {
  it('keeps the first 100 and closes with one entry counting the rest, on the line of the 100th', () => {
    const w = new Warnings();
    for (let k = 1; k <= 100; k++) w.add(k, `w${k}`);
    expect(w.count).toBe(100);
    expect(w.result().length).toBe(100);
    expect(w.result()[99]).toEqual({ line: 100, message: 'w100' });
    w.add(500, 'w101');
    w.add(600, 'w102');
    expect(w.count).toBe(102);
    const r = w.result();
    expect(r.length).toBe(101);
    expect(r[99]).toEqual({ line: 100, message: 'w100' });
    expect(r[100]).toEqual({ line: 100, message: '2 more warnings not listed' });
  });

  it('gives a copy: a result taken earlier does not grow with later warnings', () => {
    const w = new Warnings();
    w.add(1, 'a');
    const first = w.result();
    w.add(2, 'b');
    expect(first).toEqual([{ line: 1, message: 'a' }]);
    expect(w.result()).toEqual([{ line: 1, message: 'a' }, { line: 2, message: 'b' }]);
  });

  it('says a keyword once, at its first line, whatever other keywords come between', () => {
    const w = new Warnings();
    w.addOncePerKeyword('l', 3, 'l first');
    w.addOncePerKeyword('p', 4, 'p first');
    w.addOncePerKeyword('l', 5, 'l again');
    w.add(6, 'plain');
    w.addOncePerKeyword('p', 7, 'p again');
    expect(w.result()).toEqual([{ line: 3, message: 'l first' }, { line: 4, message: 'p first' }, { line: 6, message: 'plain' }]);
    expect(w.count).toBe(3);
  });
});

describe('shown', () => {
  it('quotes a token as JSON, cut to 40 characters and an ellipsis past that', () => {
    expect(shown('usemtl')).toBe('"usemtl"');
    expect(shown('a"b\\')).toBe('"a\\"b\\\\"');
    const forty = 'x'.repeat(40);
    expect(shown(forty)).toBe(`"${forty}"`);
    expect(shown(`${forty}y`)).toBe(`"${forty}…"`);
    expect(shown('z'.repeat(10_000_000)).length).toBe(43);
  });
});
