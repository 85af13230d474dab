// The course files' line cursor and their sniffer at the edges (src/loaders/course/course-text.ts,
// sniff-course.ts; docs/course-files.md#text-conventions): which lines count, how many tokens a
// line gives, what the file ends on, and which names decide a file too broken to tell.
import { describe, expect, it } from 'vitest';
import { CourseLines, rejectNonText } from '../../src/loaders/course/course-text';
import { sniffCourse } from '../../src/loaders/course/sniff-course';
import { loadErrorOf } from './helpers/course';

function lines(text: string, max = 3): { line: number; tokens: string[] }[] {
  const c = new CourseLines(text, 'f');
  const out = [];
  for (let l = c.next(max); l !== null; l = c.next(max)) out.push(l);
  return out;
}

describe('CourseLines', () => {
  it('gives the non-blank lines with their numbers, whatever the line ends', () => {
    expect(lines('\uFEFF1 2\r\n\r\n3\r4\n\n  \t\n5')).toEqual([
      { line: 1, tokens: ['1', '2'] }, { line: 3, tokens: ['3'] }, { line: 4, tokens: ['4'] }, { line: 7, tokens: ['5'] },
    ]);
    expect(lines('a\n')).toEqual([{ line: 1, tokens: ['a'] }]);
    expect(lines('')).toEqual([]);
  });

  it('skips a line of other white space (vertical tab, form feed, no-break space) as blank', () => {
    expect(lines('\u000b\n\f\n\u00a0\nx')).toEqual([{ line: 4, tokens: ['x'] }]);
  });

  it('gives at most `max` + 1 tokens of a line, and none of the next line', () => {
    expect(lines('1 2 3 4 5 6\n7', 3)).toEqual([{ line: 1, tokens: ['1', '2', '3', '4'] }, { line: 2, tokens: ['7'] }]);
    expect(lines('1 2 3 4\n7', 0)).toEqual([{ line: 1, tokens: ['1'] }, { line: 2, tokens: ['7'] }]);
    expect(lines('1\n2 3', 3)).toEqual([{ line: 1, tokens: ['1'] }, { line: 2, tokens: ['2', '3'] }]);
    expect(lines('  1\t2', 3)).toEqual([{ line: 1, tokens: ['1', '2'] }]);
  });

  it('names the last non-blank line when the file ends too soon', () => {
    const c = new CourseLines('1\n\n2\n\n\n', 'f.txt');
    c.next(1);
    c.next(1);
    const e = loadErrorOf(() => c.require(1, 'no line for n'));
    expect(e.detail).toEqual({ type: 'load', url: 'f.txt', line: 3, message: 'the file ends here, no line for n' });
  });

  it('counts the lines left and names the first', () => {
    const c = new CourseLines('1\n\n2 2\n\n3\n4', 'f');
    c.next(3);
    expect(c.rest()).toEqual({ first: 3, count: 3 });
    expect(c.rest()).toBeNull();
    expect(new CourseLines('\n \n', 'f').rest()).toBeNull();
  });

  it('reads numbers and whole-number counts, naming what each was to be', () => {
    const c = new CourseLines('', 'f');
    expect(c.number('-2.5e1', 4, 'x')).toBe(-25);
    expect(loadErrorOf(() => c.number('1e400', 4, 'Pl')).detail).toEqual({ type: 'load', url: 'f', line: 4, message: 'Pl: "1e400" is too large' });
    expect(loadErrorOf(() => c.number('1.1.1', 5, 'Pl')).detail.message).toBe('Pl: "1.1.1" is not a number');
    expect(c.count('3', 1, 'NV', 3)).toBe(3);
    expect(c.count('0', 1, 'NV', 0)).toBe(0);
    expect(loadErrorOf(() => c.count('2', 1, 'NV', 3)).detail.message).toBe('NV: "2" is not a whole number ≥ 3');
    expect(loadErrorOf(() => c.count('2.5', 2, 'NT', 1)).detail).toEqual({ type: 'load', url: 'f', line: 2, message: 'NT: "2.5" is not a whole number ≥ 1' });
    expect(c.numbers({ line: 1, tokens: ['1', '2', '3', '4'] }, 3, 'C')).toEqual([1, 2, 3]);
    expect(loadErrorOf(() => c.numbers({ line: 6, tokens: [] }, 1, 'ka')).detail.message).toBe('ka needs 1 number, the line has 0');
  });
});

describe('rejectNonText', () => {
  it('names the line of the markup or of the first control character, CR and CRLF counted once each', () => {
    expect(loadErrorOf(() => rejectNonText('\r\n\r \n<x>', 'a', 'a camera .cfg file')).detail)
      .toEqual({ type: 'load', url: 'a', line: 4, message: 'an HTML page (or other markup), not a camera .cfg file' });
    expect(loadErrorOf(() => rejectNonText('1 2\r3 4\r\n\u0000\u0001\u0002', 'b', 'a .byu file')).detail)
      .toEqual({ type: 'load', url: 'b', line: 3, message: 'binary content, not a .byu file' });
    expect(loadErrorOf(() => rejectNonText('1 2\n3', 'c', 'x', 'binary')).line).toBe(1);
    expect(loadErrorOf(() => rejectNonText('   ', 'c', 'x', 'html')).line).toBe(1);
    expect(loadErrorOf(() => rejectNonText('\n1', 'c', 'x', 'binary')).line).toBe(1);
    expect(loadErrorOf(() => rejectNonText('\n\n', 'c', 'x', 'html')).line).toBe(1);
    expect(() => rejectNonText('1 2\n', 'd', 'x')).not.toThrow();
    expect(() => rejectNonText('<html>', 'd', 'x', 'obj')).not.toThrow();
  });
});

describe('sniffCourse', () => {
  const CAMERA = '0 0 10\n0 0 -1\n0 1 0\n1 1 1\n';
  const LIGHTING = '0 0 0\n0.2\n1 1 1\n0.5\n1 1 1\n0.5\n1 1 1\n2\n';

  it('tells a camera from lighting by the numbers per line, extra lines after them allowed', () => {
    expect(sniffCourse('', CAMERA)).toBe('camera');
    expect(sniffCourse('', `${CAMERA}x\n`)).toBe('camera');
    expect(sniffCourse('', LIGHTING)).toBe('lighting');
    expect(sniffCourse('', `${LIGHTING}9\n9 9\n`)).toBe('lighting');
    expect(sniffCourse('', CAMERA.replace('0 1 0', '0 1 0 0'))).toBe('unknown');
    expect(sniffCourse('', CAMERA.replace('0 1 0', '0 1 x'))).toBe('unknown');
    expect(sniffCourse('', LIGHTING.replace('0.5', '0.5 0.5'))).toBe('unknown');
    expect(sniffCourse('', '0 0 0\n0.2\n1 1 1\n')).toBe('unknown');
    // A word counts as no number: lines of three words are no camera, a word is no lighting value.
    expect(sniffCourse('', 'a b c\nd e f\ng h i\nj k l\n')).toBe('unknown');
    expect(sniffCourse('', LIGHTING.replace('0.2', 'x'))).toBe('unknown');
  });

  it('returns what sniffModel said for HTML and binary, whatever the name', () => {
    expect(sniffCourse('a.cfg', CAMERA, 'html')).toBe('html');
    expect(sniffCourse('a.cfg', CAMERA, 'binary')).toBe('binary');
    expect(sniffCourse('a.byu', '\u0000\u0001\u0002')).toBe('binary');
  });

  it('goes by the file name only for content that fits nothing, query and fragment cut, in any case', () => {
    expect(sniffCourse('https://h/x/CAM.CFG?v=1#top', 'oops')).toBe('camera');
    expect(sniffCourse('x/iluminacao-2.txt#a', 'oops')).toBe('lighting');
    expect(sniffCourse('ILUMINAÇÃO.TXT', 'oops')).toBe('lighting');
    expect(sniffCourse('x/modelo.BYU', 'oops')).toBe('byu-mesh');
    for (const url of ['x.cfg/readme', 'my-iluminacao.txt', 'iluminacao.txt.bak', 'luz.txt', 'x.byu.txt', '', 'a?b.cfg']) {
      expect(sniffCourse(url, 'oops'), url).toBe('unknown');
    }
  });

  it('reads a .byu by its first line of two whole numbers, even before a camera-like rest', () => {
    expect(sniffCourse('x.cfg', '4 2\n0 0 0\n0 0 0\n0 0 0\n')).toBe('byu-mesh');
    expect(sniffCourse('', '4 2 1\n0 0 0\n0 0 0\n0 0 0\n')).toBe('camera'); // three numbers first: a camera's shape
    expect(sniffCourse('', '4 2.0\n0 0 0\n')).toBe('unknown');
    expect(sniffCourse('', '3 3\n5\n')).toBe('byu-bezier');
    expect(sniffCourse('', '3 3')).toBe('byu-mesh');
    expect(sniffCourse('', '3 3\n5 5\n')).toBe('byu-mesh');
  });
});
