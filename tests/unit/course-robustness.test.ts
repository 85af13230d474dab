// The course's files as found in the wild (docs/course-files.md#text-conventions): sniffing, HTML pages and binary bytes,
// number forms, 10 MB lines, and random input that must end in a result or a LoadError.
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { LoadError } from '../../src/loaders/load-error';
import { parseByu } from '../../src/loaders/course/byu';
import { parseByuBezier } from '../../src/loaders/course/byu-bezier';
import { parseByuMesh } from '../../src/loaders/course/byu-mesh';
import { parseCameraCfg } from '../../src/loaders/course/camera-cfg';
import { parseLightingTxt } from '../../src/loaders/course/lighting-txt';
import { sniffCourse } from '../../src/loaders/course/sniff-course';
import { CourseLines, isNumber } from '../../src/loaders/course/course-text';
import { expectLoadError, sample } from './helpers/course';
import { instrumented } from './helpers/collections';

const PARSERS: [string, (text: string, o: { url: string }) => unknown][] = [
  ['parseByuMesh', parseByuMesh], ['parseByuBezier', parseByuBezier], ['parseByu', parseByu],
  ['parseCameraCfg', parseCameraCfg], ['parseLightingTxt', parseLightingTxt],
];

describe('sniffCourse', () => {
  it('names every sample by its content', () => {
    const dir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../data/course');
    const want: Record<string, string> = {
      'tetra.byu': 'byu-mesh', 'tetra-crlf-bom.byu': 'byu-mesh', 'tetra-trailing.byu': 'byu-mesh',
      'mesh-truncated.byu': 'byu-mesh', 'mesh-bad-token.byu': 'byu-mesh',
      'patch-3x3-first-fastest.byu': 'byu-bezier', 'patch-2x5-second-fastest.byu': 'byu-bezier', 'patch-degenerate-edge.byu': 'byu-bezier',
      'camera.cfg': 'camera', 'camera-negative-hx.cfg': 'camera', 'iluminacao.txt': 'lighting',
      'page.byu': 'html', 'garbage.byu': 'binary',
    };
    for (const [name, format] of Object.entries(want)) expect(sniffCourse('', sample(name)), name).toBe(format);
    expect(fs.readdirSync(dir).filter((f) => /\.(byu|cfg|txt)$/.test(f)).length).toBeGreaterThan(Object.keys(want).length);
  });

  it('falls back on the name only when the content fits no format', () => {
    expect(sniffCourse('models/x.cfg', sample('camera-truncated.cfg'))).toBe('camera');
    expect(sniffCourse('https://h/entradas/Iluminacao.txt?v=2', sample('iluminacao-truncated.txt'))).toBe('lighting');
    expect(sniffCourse('a/iluminação.txt', 'oops\n')).toBe('lighting');
    expect(sniffCourse('m.byu', sample('mesh-missing-count.byu'))).toBe('byu-mesh');
    expect(sniffCourse('notes.txt', sample('camera-truncated.cfg'))).toBe('unknown');
    // Content beats the name.
    expect(sniffCourse('camera.cfg', sample('iluminacao.txt'))).toBe('lighting');
    expect(sniffCourse('x.cfg', sample('tetra.byu'))).toBe('byu-mesh');
    expect(sniffCourse('x.byu', '<html></html>')).toBe('html');
  });

  it('calls a .byu Bézier exactly when its second non-blank line is one number', () => {
    expect(sniffCourse('', '3 3\n\n\n  10  \n0 0 0\n')).toBe('byu-bezier');
    expect(sniffCourse('', '3 3\r\n10 1\r\n')).toBe('byu-mesh');
    expect(sniffCourse('', '3 1\n0 0 0\n')).toBe('byu-mesh');
  });
});

describe('HTML pages and binary bytes', () => {
  it('is a load error naming the file and the line where the markup starts, for every parser', () => {
    for (const [name, parse] of PARSERS) {
      const e = expectLoadError(() => parse(sample('page.byu'), { url: 'models/calice.byu' }), 'models/calice.byu', 2, /an HTML page/);
      expect(e.message, name).toMatch(/^glass-plane-scene: models\/calice\.byu line 2: an HTML page/);
    }
  });

  it('is a load error naming the file and a line for binary garbage, for every parser', () => {
    for (const [, parse] of PARSERS) {
      expectLoadError(() => parse(sample('garbage.byu'), { url: 'g.byu' }), 'g.byu', 1, /binary content/);
    }
    const late = `4 1\n0 0 0\n${'\u0000\u0001\u0002'.repeat(40)}\n`;
    expectLoadError(() => parseByuMesh(late, { url: 'g.byu' }), 'g.byu', 3, /binary content/);
  });
});

// Each case as LF text: its LoadError's line (null for none) and its warnings' lines. Blank lines
// sit before the faults, so that a line end counted twice (CR then LF) or not at all moves them.
describe('line numbers with CRLF, CR or LF line ends (docs/course-files.md#text-conventions)', () => {
  const cases: [string, (text: string, o: { url: string }) => { warnings: { line: number }[] }, string, number | null, number[]][] = [
    ['a mesh .byu: a bad token', parseByuMesh, '4 1\n\n0 0 0\n1 0 0\n\n\n0 1 0\n0 x 1\n1 2 3\n', 8, []],
    ['a mesh .byu: extra values, a face out of range, lines after the counts', parseByuMesh,
      '4 2 9\n\n0 0 0\n1 0 0\n\n0 1 0 7\n0 0 1\n\n1 2 9\n1 2 3\n\n\nextra\n', null, [1, 6, 9, 13]],
    ['a mesh .byu: too few lines', parseByuMesh, '4 1\n\n0 0 0\n\n1 0 0\n\n', 5, []],
    ['a Bézier .byu: a bad token', parseByuBezier, '1 1\n\n3\n\n0 0 0\n1 0 0\n\n0 1 ,\n1 1 0\n', 8, []],
    ['a Bézier .byu: values after E, lines after the points, a resolution clamped (named at E\'s line)',
      (t, o) => parseByuBezier(t, { ...o, resolution: 1 }), '1 1\n\n\n3 9\n0 0 0\n1 0 0\n\n0 1 0\n1 1 0\n\nmore\n', null, [4, 11, 4]],
    ['a camera .cfg: d of 0', parseCameraCfg, '0 0 10\n\n0 0 -1\n0 1 0\n\n\n0 1 1\n', 7, []],
    ['a camera .cfg: V parallel to N', parseCameraCfg, '0 0 10\n\n0 0 -1\n\n0 0 2\n1 1 1\n', 5, []],
    ['a camera .cfg: extra values and lines', parseCameraCfg, '0 0 10\n\n0 0 -1 5\n0 1 0\n1 1 1\n\n\nx\n', null, [3, 8]],
    ['an iluminacao.txt: a bad token', parseLightingTxt, '0 0 0\n\n0.5\n255 255 255\n\n0.5\nx 1 1\n', 7, []],
    ['an iluminacao.txt: values clamped', parseLightingTxt,
      '0 0 0\n\n1.5\n255 255 255\n0.5\n\n1 1 1\n0.5\n300 255 255\n\n4\n', null, [3, 9]],
    ['an HTML page after blank lines', parseLightingTxt, '\n\n  \n<html>\n</html>\n', 4, []],
  ];
  const endings: [string, (text: string) => string][] = [
    ['LF', (t) => t], ['CRLF', (t) => t.replace(/\n/g, '\r\n')], ['CR', (t) => t.replace(/\n/g, '\r')],
    ['CRLF with a BOM', (t) => `\uFEFF${t.replace(/\n/g, '\r\n')}`],
  ];

  for (const [what, parse, text, errorLine, warningLines] of cases) {
    it(`names the same lines whatever the line ends: ${what}`, () => {
      for (const [how, convert] of endings) {
        const label = `${what} (${how})`;
        if (errorLine !== null) {
          expectLoadError(() => parse(convert(text), { url: 'f' }), 'f', errorLine, /./);
          continue;
        }
        expect(parse(convert(text), { url: 'f' }).warnings.map((w) => w.line), label).toEqual(warningLines);
      }
    });
  }
});

describe('numbers', () => {
  const camera = (d: string): string => `0 0 10\n0 0 -1\n0 1 0\n${d} 1 1\n`;

  it('reads 9.5e-005, -1.0E-14, +3., .5, 1E+2, 007 as the course\'s C and Java programs do', () => {
    for (const [token, value] of [['9.5e-005', 9.5e-5], ['-1.0E-14', -1e-14], ['+3.', 3], ['.5', 0.5], ['1E+2', 100], ['007', 7], ['-.25e1', -2.5]] as const) {
      expect(parseCameraCfg(camera(token)).d, token).toBe(value);
    }
  });

  it('refuses what is not a decimal number: 1,5 0x10 Infinity NaN 1e . +- 1.2.3 1_0 e5', () => {
    for (const token of ['1,5', '0x10', 'Infinity', 'NaN', '1e', '.', '+-1', '1.2.3', '1_0', 'e5', '½']) {
      expectLoadError(() => parseCameraCfg(camera(token), { url: 'c.cfg' }), 'c.cfg', 4, /is not a number/);
    }
  });
});

/** Calls of any RegExp's exec (test, search, split and matchAll go through it) during `run`. */
function regexCalls(run: () => void): number {
  const exec = RegExp.prototype.exec;
  let calls = 0;
  RegExp.prototype.exec = function (this: RegExp, s: string) {
    calls++;
    return exec.call(this, s);
  };
  try {
    run();
  } finally {
    RegExp.prototype.exec = exec;
  }
  return calls;
}

// Clock-free (the times are in `npm run bench`, bench/parse-course.md). Each input ends in a
// LoadError naming a line, with a short message; and the regular-expression work does not grow
// with the text: a line is read only up to the tokens a reader needs, a token longer than any
// number is refused before a pattern runs, and the sniffers look at the first 4 KB. Reading a
// 10 MB line as tokens would be millions of calls; here 1 MB and 10 MB of each take the same
// number (at most ~25,000, mostly from splitting the 4 KB sample).
describe('never a hang', { timeout: 30_000 }, () => {
  // Under StrykerJS every call is instrumented: 10 MB through five parsers took over 30 s there.
  // Its sizes are 8 KB and 80 KB, still past the 4 KB the sniffers read, and as telling of growth.
  const MB = instrumented ? 8 * 1024 : 1024 * 1024;
  const cases: [string, (size: number) => string][] = [
    ['one big number', (n) => '1'.repeat(n)],
    ['one big word', (n) => 'a'.repeat(n)],
    ['one big run of digits ending in a letter', (n) => `${'1'.repeat(n)}x 1`],
    ['a big line of numbers', (n) => '0 '.repeat(n / 2)],
    ['a header, then a big line of numbers', (n) => `4 2\n${'1 '.repeat(n / 2)}`],
    ['a header, then a big run of digits and dots', (n) => `1 1\n3\n${'1.'.repeat(n / 2)}x`],
    ['big blank lines and spaces', (n) => ' \r\n\t'.repeat(n / 4)],
    ['big exponent-like junk', (n) => '1e1e'.repeat(n / 4)],
  ];
  for (const [what, make] of cases) {
    it(`ends in a LoadError naming a line, with work that does not grow from 1 MB to 10 MB, for ${what}`, () => {
      const small = make(MB), big = make(10 * MB);
      for (const [name, parse] of PARSERS) {
        const calls = [small, big].map((text) => regexCalls(() => {
          let caught: unknown;
          try {
            parse(text, { url: 'big' });
          } catch (e) {
            caught = e;
          }
          expect(caught, name).toBeInstanceOf(LoadError);
          const e = caught as LoadError;
          expect(e.line, name).toBeGreaterThanOrEqual(1);
          expect(e.message.length, name).toBeLessThan(200);
        }));
        expect(calls[1], `${name}: regular-expression calls at 10 MB against 1 MB`).toBe(calls[0]);
      }
      const sniffs = [small, big].map((text) => regexCalls(() => sniffCourse('big.byu', text)));
      expect(sniffs[1]).toBe(sniffs[0]);
    });
  }

  it('refuses a token longer than any number before its pattern runs, and reads a line only as far as asked', () => {
    expect(isNumber(`0.${'1'.repeat(62)}`)).toBe(true);
    expect(isNumber(`0.${'1'.repeat(63)}`)).toBe(false);
    expect(regexCalls(() => isNumber('1'.repeat(65)))).toBe(0);
    const line = new CourseLines(`\n\n${'7 '.repeat(1_000_000)}\n8\n`, 'x').next(3);
    expect(line).toEqual({ line: 3, tokens: ['7', '7', '7', '7'] });
  });

  it('ends every random text in a result or a LoadError, never another exception', () => {
    let seed = 7;
    const r = (n: number): number => ((seed = (Math.imul(seed, 1664525) + 1013904223) >>> 0) % n);
    const pieces = ['0', '1', '2', '3', '4', '-1', '1e9', '99999999999', '.5', '+3.', 'x', '<', '\u0000', ' ', '\t', '\n', '\r\n', '\n\n', '\uFEFF', '1e999'];
    for (let k = 0; k < 400; k++) {
      const text = Array.from({ length: 5 + r(60) }, () => pieces[r(pieces.length)]).join(r(2) ? ' ' : '');
      for (const [name, parse] of PARSERS) {
        try {
          parse(text, { url: 'fuzz' });
        } catch (e) {
          expect(e, `${name} on ${JSON.stringify(text)}`).toBeInstanceOf(LoadError);
        }
      }
    }
  });
});
