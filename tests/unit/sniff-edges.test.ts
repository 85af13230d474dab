// sniffModel at the edges of its rules (docs/scene-model.md#loading): how many control characters
// make binary, what a first line of counts and a second line make, which keywords open an OBJ,
// and that only the first 4 KB are read.
import { describe, expect, it } from 'vitest';
import { SAMPLE, sniffModel } from '../../src/loaders/sniff';

describe('sniffModel: binary', () => {
  it('needs at least 2 control characters, and more than 1 in 50 characters', () => {
    expect(sniffModel('v 0 0 0\n\u0001')).toBe('obj');
    expect(sniffModel('\u0001\u0002')).toBe('binary');
    // 2 in 100 characters is not more than 1 in 50; 2 in 99 is.
    expect(sniffModel(`\u0001\u0002${'v'.repeat(98)}`)).toBe('unknown');
    expect(sniffModel(`\u0001\u0002${'v'.repeat(97)}`)).toBe('binary');
  });

  it('counts every control character but tab, LF, form feed and CR, and DEL and U+FFFD', () => {
    expect(sniffModel('v\t0\f0\r\n0\n'.repeat(3))).toBe('obj');
    for (const c of ['\u0000', '\u0008', '\u000b', '\u000e', '\u001f', '\u007f', '\uFFFD']) expect(sniffModel(`${c}${c}v 1 2 3\n`), JSON.stringify(c)).toBe('binary');
    expect(sniffModel('\u0020\u0020v 1 2 3\n')).toBe('obj');
    expect(sniffModel('\u0080\u0080v 1 2 3\n')).toBe('unknown');
  });
});

describe('sniffModel: .byu', () => {
  it('wants exactly two whole numbers on the first line', () => {
    expect(sniffModel('3 3\n0 0 0\n')).toBe('byu-mesh');
    expect(sniffModel('3 3 3\n0 0 0\n')).toBe('unknown');
    expect(sniffModel('3 -3\n0 0 0\n')).toBe('unknown');
    expect(sniffModel('3 x\n0 0 0\n')).toBe('unknown');
    expect(sniffModel('3.5 3\n0 0 0\n')).toBe('unknown');
    expect(sniffModel('3\n0 0 0\n')).toBe('unknown');
  });

  it('is a Bézier patch only when the second line is one finite number', () => {
    expect(sniffModel('3 3\n')).toBe('byu-mesh');
    expect(sniffModel('3 3\n10\n')).toBe('byu-bezier');
    expect(sniffModel('3 3\n1e3\n')).toBe('byu-bezier');
    expect(sniffModel('3 3\nx\n')).toBe('byu-mesh');
    expect(sniffModel('3 3\n1e999\n')).toBe('byu-mesh');
    expect(sniffModel('3 3\n10 10\n')).toBe('byu-mesh');
  });
});

describe('sniffModel: OBJ', () => {
  it('opens with any of the statements OBJ files start with', () => {
    for (const k of ['v', 'vt', 'vn', 'vp', 'f', 'fo', 'l', 'p', 'o', 'g', 's', 'usemtl', 'mtllib', 'cstype', 'deg', 'curv', 'surf']) {
      expect(sniffModel(`${k} 1\n`), k).toBe('obj');
      expect(sniffModel(`# c\n${k}\tx\n`), k).toBe('obj');
    }
    for (const k of ['vx', 'V', 'newmtl', 'hello']) expect(sniffModel(`${k} 1\n`), k).toBe('unknown');
  });

  it('decides on the first line that is not a comment', () => {
    expect(sniffModel('# a\n#b\n\nhello\nv 1 2 3\n')).toBe('unknown');
    expect(sniffModel('# a\n  \t\n g x\nhello\n')).toBe('obj');
  });

  it('calls markup after a BOM and blank lines HTML, and a BOM alone unknown', () => {
    expect(sniffModel('\uFEFF\n \t<svg>')).toBe('html');
    expect(sniffModel('\uFEFF')).toBe('unknown');
    expect(sniffModel('\uFEFFv 1 2 3')).toBe('obj');
  });

  it('reads only the first 4 KB of a string', () => {
    expect(SAMPLE).toBe(4096);
    // A comment line filling the sample: what follows it is never read.
    expect(sniffModel(`#${'x'.repeat(4095)}\nhello\n`)).toBe('obj');
    expect(sniffModel(`#${'x'.repeat(4093)}\nhello\n`)).toBe('unknown');
    expect(sniffModel(`${' '.repeat(4096)}<html>`)).toBe('unknown');
  });
});
