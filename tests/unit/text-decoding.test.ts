// The text loaders' bytes and lines (src/loaders/decode-text.ts, decode-span.ts, text-lines.ts,
// number-token.ts): byte-order marks, spans of UTF-8, logical lines with continuations and
// comments, and which tokens are numbers.
import { describe, expect, it } from 'vitest';
import { bomOf, decodeText } from '../../src/loaders/decode-text';
import { decodeSpan } from '../../src/loaders/decode-span';
import { logicalLines, stripComment } from '../../src/loaders/text-lines';
import { isNumberToken } from '../../src/loaders/number-token';

const bytes = (...b: number[]): Uint8Array => new Uint8Array(b);
const utf8 = (text: string): Uint8Array => new TextEncoder().encode(text);

describe('bomOf and decodeText', () => {
  it('names each mark and its length, and UTF-8 with none', () => {
    expect(bomOf(bytes(0xef, 0xbb, 0xbf))).toEqual({ encoding: 'utf-8', skip: 3 });
    expect(bomOf(bytes(0xff, 0xfe))).toEqual({ encoding: 'utf-16le', skip: 2 });
    expect(bomOf(bytes(0xfe, 0xff))).toEqual({ encoding: 'utf-16be', skip: 2 });
    expect(bomOf(bytes(0xef, 0xbb))).toEqual({ encoding: 'utf-8', skip: 0 });
    expect(bomOf(bytes(0xff))).toEqual({ encoding: 'utf-8', skip: 0 });
    expect(bomOf(bytes(0xfe))).toEqual({ encoding: 'utf-8', skip: 0 });
    expect(bomOf(bytes(0x76, 0xbb, 0xbf))).toEqual({ encoding: 'utf-8', skip: 0 });
    expect(bomOf(bytes(0xef, 0x76, 0xbf))).toEqual({ encoding: 'utf-8', skip: 0 });
    expect(bomOf(bytes(0xef, 0xbb, 0x76))).toEqual({ encoding: 'utf-8', skip: 0 });
    expect(bomOf(bytes(0xff, 0xff))).toEqual({ encoding: 'utf-8', skip: 0 });
    expect(bomOf(bytes(0xfe, 0xfe))).toEqual({ encoding: 'utf-8', skip: 0 });
  });

  it('decodes a file that is only its mark to nothing, and keeps a second mark as text', () => {
    expect(decodeText(bytes(0xef, 0xbb, 0xbf))).toBe('');
    expect(decodeText(bytes(0xff, 0xfe))).toBe('');
    expect(decodeText(bytes(0xfe, 0xff))).toBe('');
    expect(decodeText(bytes(0xef, 0xbb, 0xbf, 0xef, 0xbb, 0xbf, 0x61))).toBe('\uFEFFa');
    expect(decodeText(bytes(0xfe, 0xff, 0, 0x76, 0, 0x31))).toBe('v1');
    expect(decodeText(bytes(0xff, 0xfe, 0x76, 0, 0x31, 0).buffer as ArrayBuffer)).toBe('v1');
  });

  it('decodes only the first `limit` bytes after the mark, invalid UTF-8 as U+FFFD', () => {
    expect(decodeText(utf8('\uFEFFabcdef'), 3)).toBe('abc');
    expect(decodeText(utf8('abcdef'), 3)).toBe('abc');
    expect(decodeText(bytes(0x61, 0xff, 0x62))).toBe('a\uFFFDb');
  });
});

describe('decodeSpan', () => {
  it('gives the text of bytes from .. to, as decoding the whole file gives it there', () => {
    const b = utf8('usemtl red glass');
    expect(decodeSpan(b, 7, 10)).toBe('red');
    expect(decodeSpan(b, 7, 7)).toBe('');
    expect(decodeSpan(b, 0, b.length)).toBe('usemtl red glass');
    const long = utf8('o a-name-of-more-than-sixteen-bytes');
    expect(decodeSpan(long, 2, long.length)).toBe('a-name-of-more-than-sixteen-bytes');
  });

  it('decodes non-ASCII, keeps a mark U+FEFF as text and reads a stray byte as U+FFFD, in short spans and long', () => {
    expect(decodeSpan(utf8('ñé'), 0, 4)).toBe('ñé');
    const b = utf8('o Zoë');
    expect(decodeSpan(b, 2, b.length)).toBe('Zoë');
    expect(decodeSpan(bytes(0xef, 0xbb, 0xbf, 0x61), 0, 4)).toBe('\uFEFFa');
    expect(decodeSpan(bytes(0x61, 0x80), 0, 2)).toBe('a\uFFFD');
    expect(decodeSpan(bytes(0x61, 0x7f), 0, 2)).toBe('a\u007f');
    const longMark = new Uint8Array([0xef, 0xbb, 0xbf, ...utf8('x'.repeat(20))]);
    expect(decodeSpan(longMark, 0, longMark.length)).toBe(`\uFEFF${'x'.repeat(20)}`);
  });
});

describe('logicalLines', () => {
  it('splits CRLF, CR and LF, numbering physical lines from 1, a leading BOM dropped', () => {
    expect(logicalLines('\uFEFFa\r\nb\rc\nd')).toEqual([
      { line: 1, text: 'a' }, { line: 2, text: 'b' }, { line: 3, text: 'c' }, { line: 4, text: 'd' },
    ]);
    expect(logicalLines('a\n\uFEFFb')).toEqual([{ line: 1, text: 'a' }, { line: 2, text: '\uFEFFb' }]);
  });

  it('joins a line ending in \\ to the next with a space, numbered where it starts', () => {
    expect(logicalLines('Kd 1 \\\n0 \\\r\n0\nNs 5\n')).toEqual([
      { line: 1, text: 'Kd 1  0  0' }, { line: 4, text: 'Ns 5' }, { line: 5, text: '' },
    ]);
    expect(logicalLines('a\\\nb\nc')).toEqual([{ line: 1, text: 'a b' }, { line: 3, text: 'c' }]);
  });

  it('keeps a continuation that runs into the end of the text', () => {
    expect(logicalLines('x\ny\\')).toEqual([{ line: 1, text: 'x' }, { line: 2, text: 'y' }]);
    expect(logicalLines('x\ny\\\nz\\')).toEqual([{ line: 1, text: 'x' }, { line: 2, text: 'y z' }]);
  });
});

describe('stripComment', () => {
  it('cuts a # at the start or after white space, and keeps one inside a name', () => {
    expect(stripComment('# all')).toBe('');
    expect(stripComment('Kd 1 1 1 # red')).toBe('Kd 1 1 1');
    expect(stripComment('Kd 1\t# tab')).toBe('Kd 1');
    expect(stripComment('newmtl a#1')).toBe('newmtl a#1');
    expect(stripComment('newmtl a#1 #x')).toBe('newmtl a#1');
  });
});

describe('isNumberToken', () => {
  it('takes the decimal forms MTL and OBJ files write, and nothing else', () => {
    for (const t of ['1', '-0.5', '+2', '.5', '3.', '1e-5', '1E+2', '-.5e3']) expect(isNumberToken(t), t).toBe(true);
    for (const t of ['', '.', '-', 'e5', '1e', '1.2.3', 'nan', 'inf', '1,5', ' 1', '1 ', '0x10', '1e5x', 'x1']) expect(isNumberToken(t), t).toBe(false);
  });

  it('refuses a token longer than 64 characters, number or not', () => {
    expect(isNumberToken('1'.repeat(64))).toBe(true);
    expect(isNumberToken('1'.repeat(65))).toBe(false);
  });
});
