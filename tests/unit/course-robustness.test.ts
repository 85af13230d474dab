// The course's files as found in the wild (SPEC §11): sniffing, HTML pages and binary bytes,
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
import { expectLoadError, sample } from './course-helpers';

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

describe('never a hang', () => {
  const MB10 = 10 * 1024 * 1024;
  const cases: [string, string][] = [
    ['one 10 MB number', '1'.repeat(MB10)],
    ['one 10 MB word', 'a'.repeat(MB10)],
    ['one 10 MB run of digits ending in a letter', `${'1'.repeat(MB10)}x 1`],
    ['a 10 MB line of numbers', '0 '.repeat(MB10 / 2)],
    ['a header, then a 10 MB line of numbers', `4 2\n${'1 '.repeat(MB10 / 2)}`],
    ['a header, then a 10 MB run of digits and dots', `1 1\n3\n${'1.'.repeat(MB10 / 2)}x`],
    ['10 MB of blank lines and spaces', ' \r\n\t'.repeat(MB10 / 4)],
    ['10 MB of exponent-like junk', '1e1e'.repeat(MB10 / 4)],
  ];
  for (const [what, text] of cases) {
    it(`returns or throws a LoadError promptly for ${what}`, () => {
      for (const [name, parse] of PARSERS) {
        const started = performance.now();
        try {
          parse(text, { url: 'big' });
        } catch (e) {
          expect(e, name).toBeInstanceOf(LoadError);
        }
        expect(performance.now() - started, name).toBeLessThan(1500);
      }
      const started = performance.now();
      sniffCourse('big.byu', text);
      expect(performance.now() - started).toBeLessThan(500);
    });
  }

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
