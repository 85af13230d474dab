// The Radiance .hdr reader (src/loaders/hdr.ts, docs/pbr.md#an-image): values worked by hand from the format's definition
// (a pixel (r, g, b, e) is (m + ½)·2^(e − 136) per channel, 0 when e is 0), both encodings of a scanline, the four
// orientations, and the messy files of the wild — each a picture or an error naming the file and the place.
import { describe, expect, it } from 'vitest';
import { parseHdr } from '../../src/loaders/hdr';
import { LoadError } from '../../src/loaders/load-error';

const enc = new TextEncoder();
const URL_ = 'studio light.hdr';

/** A file: header lines, a blank line, the resolution line, then `pixels` bytes. */
function file(header: string[], resolution: string, pixels: number[], eol = '\n'): Uint8Array {
  const head = enc.encode([...header, '', resolution].join(eol) + eol);
  const out = new Uint8Array(head.length + pixels.length);
  out.set(head);
  out.set(pixels, head.length);
  return out;
}

const HEADER = ['#?RADIANCE', 'FORMAT=32-bit_rle_rgbe'];
/** Flat pixels (too narrow for run-length scanlines): each [r, g, b, e]. */
const flat = (...px: number[][]) => px.flat();

function fails(bytes: Uint8Array): LoadError {
  try {
    parseHdr(bytes, { url: URL_ });
  } catch (e) {
    expect(e).toBeInstanceOf(LoadError);
    expect((e as LoadError).message).toContain(URL_);
    return e as LoadError;
  }
  throw new Error('parsed');
}

/** One run-length scanline of width w from four channel arrays. */
function rleLine(w: number, channels: number[][]): number[] {
  const out = [2, 2, w >> 8, w & 255];
  for (const c of channels) out.push(...c);
  return out;
}

describe('the Radiance reader', () => {
  it('decodes flat pixels as (m + ½)·2^(e − 136), zero at e = 0, rows top first', () => {
    const img = parseHdr(file(HEADER, '-Y 2 +X 2', flat([128, 64, 0, 129], [255, 0, 1, 136], [7, 7, 7, 0], [1, 2, 3, 128])), { url: URL_ });
    expect([img.width, img.height]).toEqual([2, 2]);
    // 128.5·2⁻⁷, 64.5·2⁻⁷, 0.5·2⁻⁷ | 255.5, 0.5, 1.5 | 0 | 1.5·2⁻⁸, 2.5·2⁻⁸, 3.5·2⁻⁸
    expect(Array.from(img.rgb)).toEqual([128.5 / 128, 64.5 / 128, 0.5 / 128, 255.5, 0.5, 1.5, 0, 0, 0, 1.5 / 256, 2.5 / 256, 3.5 / 256]);
  });

  it('reads run-length scanlines: runs (count > 128) and literals, channel by channel', () => {
    // 8 wide: red a run of 8 × 100; green 3 literals then a run of 5 × 9; blue a literal of 8; exponent a run of 8 × 130.
    const line = rleLine(8, [[128 + 8, 100], [3, 1, 2, 3, 128 + 5, 9], [8, 0, 1, 2, 3, 4, 5, 6, 7], [128 + 8, 130]]);
    const img = parseHdr(file(HEADER, '-Y 1 +X 8', line), { url: URL_ });
    const f = 2 ** (130 - 136);
    const green = [1, 2, 3, 9, 9, 9, 9, 9];
    for (let x = 0; x < 8; x++) {
      expect(img.rgb[3 * x]).toBe(100.5 * f);
      expect(img.rgb[3 * x + 1]).toBe((green[x] + 0.5) * f);
      expect(img.rgb[3 * x + 2]).toBe((x + 0.5) * f);
    }
  });

  it('turns the four orientations so that row 0 is the top and column 0 the left', () => {
    // Stored order a, b / c, d (the file's first scanline first).
    const px = flat([10, 0, 0, 137], [20, 0, 0, 137], [30, 0, 0, 137], [40, 0, 0, 137]);
    const reds = (res: string) => Array.from(parseHdr(file(HEADER, res, px), { url: URL_ }).rgb.filter((_, i) => i % 3 === 0)).map((r) => r * 2 ** -1 - 0.5);
    expect(reds('-Y 2 +X 2')).toEqual([10, 20, 30, 40]);
    expect(reds('+Y 2 +X 2')).toEqual([30, 40, 10, 20]);
    expect(reds('-Y 2 -X 2')).toEqual([20, 10, 40, 30]);
    expect(reds('+Y 2 -X 2')).toEqual([40, 30, 20, 10]);
  });

  it('takes what files in the wild carry: CRLF, a BOM, #?RGBE, comments, EXPOSURE and other lines, no FORMAT', () => {
    const px = flat([128, 128, 128, 129]);
    const plain = parseHdr(file(HEADER, '-Y 1 +X 1', px), { url: URL_ }).rgb;
    const crlf = file(['#?RGBE', '# made by hand', 'EXPOSURE=2.0', 'GAMMA=1', 'PRIMARIES=0.64 0.33 0.3 0.6 0.15 0.06 0.3127 0.329'], '-Y 1 +X 1', px, '\r\n');
    const bom = new Uint8Array([0xef, 0xbb, 0xbf, ...file(['#?RADIANCE'], '-Y  1  +X  1', px)]);
    expect(parseHdr(crlf, { url: URL_ }).rgb).toEqual(plain);
    expect(parseHdr(bom, { url: URL_ }).rgb).toEqual(plain);
  });

  it('reads the old run-length form: (1, 1, 1, n) repeats the pixel before n times, shifted by 8 when repeated', () => {
    const px = flat([50, 0, 0, 137], [1, 1, 1, 2], [60, 0, 0, 137], [1, 1, 1, 1], [1, 1, 1, 1]);
    // 50, then 2 repeats; 60, then 1 + (1 << 8) = 257 repeats would overrun a width of 6: so a width that fits 1 + 2 + 1 + 257.
    const img = parseHdr(file(HEADER, '-Y 1 +X 261', px), { url: URL_ });
    const red = (x: number) => img.rgb[3 * x] * 0.5 - 0.5;
    expect([red(0), red(1), red(2), red(3), red(4), red(260)]).toEqual([50, 50, 50, 60, 60, 60]);
  });

  describe('errors that name the file and the place', () => {
    it('an HTML page where the image should be', () => {
      expect(fails(enc.encode('<!doctype html><html><body>Not found</body></html>')).message).toMatch(/HTML/);
    });

    it('a file that is not Radiance at all (a PNG)', () => {
      expect(fails(new Uint8Array([0x89, 0x50, 0x4e, 0x47, 13, 10, 26, 10, 0, 0])).message).toMatch(/#\?/);
    });

    it('a header without its end, or without the resolution line', () => {
      expect(fails(enc.encode('#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n')).message).toMatch(/resolution/);
      expect(fails(enc.encode('#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n')).message).toMatch(/resolution/);
    });

    it('a resolution line it cannot read, by its line', () => {
      const e = fails(file(HEADER, 'Y 2 X 2', flat([1, 1, 1, 128])));
      expect(e.line).toBe(4);
      expect(e.message).toMatch(/Y 2 X 2/);
      expect(fails(file(HEADER, '+X 2 -Y 2', flat([1, 1, 1, 128]))).message).toMatch(/column/);
      expect(fails(file(HEADER, '-Y 0 +X 2', [])).message).toMatch(/0 × 2|2 × 0/);
    });

    it('a format other than RGBE, by its line', () => {
      const e = fails(file(['#?RADIANCE', '# xyz', 'FORMAT=32-bit_rle_xyze'], '-Y 1 +X 1', flat([1, 1, 1, 128])));
      expect(e.line).toBe(3);
      expect(e.message).toMatch(/xyze/);
    });

    it('sizes far past what is there, before anything is allocated', () => {
      // 30000 × 30000 would be 10.8 GB of floats: refused by count; 4000 × 3000 by the bytes that follow.
      expect(fails(file(HEADER, '-Y 30000 +X 30000', [1, 1, 1, 128])).message).toMatch(/more than/);
      expect(fails(file(HEADER, '-Y 3000 +X 4000', rleLine(4000, [[128 + 127, 1]]))).message).toMatch(/3000 scanlines/);
    });

    it('pixels that end early: the scanline where they stop', () => {
      const good = rleLine(8, [[128 + 8, 1], [128 + 8, 1], [128 + 8, 1], [128 + 8, 1]]);
      const e = fails(file(HEADER, '-Y 3 +X 8', [...good, ...good, ...good.slice(0, 7)]));
      expect(e.message).toMatch(/scanline 3 of 3/);
      expect(fails(file(HEADER, '-Y 2 +X 2', flat([5, 5, 5, 128], [5, 5, 5, 128], [5, 5]))).message).toMatch(/scanline 2 of 2/);
    });

    it('runs that overrun the scanline, runs of length 0, and a scanline that says another width', () => {
      expect(fails(file(HEADER, '-Y 1 +X 8', rleLine(8, [[128 + 9, 1]]))).message).toMatch(/past the end of scanline 1/);
      expect(fails(file(HEADER, '-Y 1 +X 8', rleLine(8, [[9, 0, 0, 0, 0, 0, 0, 0, 0, 0]]))).message).toMatch(/past the end of scanline 1/);
      expect(fails(file(HEADER, '-Y 1 +X 8', rleLine(8, [[0]]))).message).toMatch(/length 0/);
      expect(fails(file(HEADER, '-Y 1 +X 8', [2, 2, 0, 9, ...new Array(40).fill(129)])).message).toMatch(/9 wide.*8/);
      expect(fails(file(HEADER, '-Y 1 +X 2', flat([1, 1, 1, 3]))).message).toMatch(/repeat/);
    });
  });
});

describe('the files the tests write (helpers/hdr-file.ts)', () => {
  it('read back within the format\'s precision: half a step of the largest channel\'s mantissa', async () => {
    const { hdrFile } = await import('./helpers/hdr-file');
    const { skyImage } = await import('./helpers/pbr-scenes');
    const sky = skyImage(64), back = parseHdr(hdrFile(sky), { url: 'sky.hdr' });
    expect([back.width, back.height]).toEqual([64, 32]);
    for (let k = 0; k < sky.rgb.length; k += 3) {
      const v = Math.max(sky.rgb[k], sky.rgb[k + 1], sky.rgb[k + 2]);
      for (let c = 0; c < 3; c++) expect(Math.abs(back.rgb[k + c] - sky.rgb[k + c])).toBeLessThanOrEqual(v / 128);
    }
  });
});

describe('the edges of the format (each a mutant of the reader once)', () => {
  const ok = (bytes: Uint8Array) => parseHdr(bytes, { url: URL_ });
  const px1 = flat([128, 128, 128, 129]);

  it('a header past 64 kB without its blank line is refused, however it goes on', () => {
    const comments = Array.from({ length: 1200 }, (_, i) => `# comment line ${i} ${'x'.repeat(50)}`);
    expect(fails(file(['#?RADIANCE', ...comments], '-Y 1 +X 1', px1)).message).toMatch(/no resolution line/);
  });

  it('the line a missing resolution line is reported at: after the last whole line', () => {
    expect(fails(enc.encode('#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n')).line).toBe(3);
    expect(fails(enc.encode('#?RADIANCE\nFORMAT=32-bit_rle_rgbe')).line).toBe(2);
  });

  it('white space before an HTML page, and bytes that are almost a BOM, almost "#?"', () => {
    for (const ws of ['\r\n', '\t', ' ', '\n']) expect(fails(enc.encode(`${ws}<html>`)).message).toMatch(/HTML/);
    const header = file(HEADER, '-Y 1 +X 1', px1);
    for (const three of [[0xef, 0xbb, 0x41], [0xef, 0x41, 0xbf], [0x41, 0xbb, 0xbf]]) {
      expect(fails(new Uint8Array([...three, ...header])).message, three.join()).toMatch(/#\?/);
    }
    // Whole files but for their first two bytes: refused by those alone.
    expect(fails(file(['#!RADIANCE'], '-Y 1 +X 1', px1)).message).toMatch(/#\?/);
    expect(fails(file(['X?RADIANCE'], '-Y 1 +X 1', px1)).message).toMatch(/#\?/);
  });

  it('FORMAT: indented or spaced still read; in a comment not', () => {
    expect(fails(file(['#?RADIANCE', '  FORMAT=32-bit_rle_xyze'], '-Y 1 +X 1', px1)).line).toBe(2);
    expect(fails(file(['#?RADIANCE', 'FORMAT = 32-bit_rle_xyze'], '-Y 1 +X 1', px1)).line).toBe(2);
    expect(ok(file(['#?RADIANCE', '# FORMAT=32-bit_rle_xyze (not this file)'], '-Y 1 +X 1', px1)).width).toBe(1);
  });

  it('the resolution line: spaces around it taken, more on it refused; column order told by its shape', () => {
    expect(ok(file(HEADER, '  -Y 1 +X 1  ', px1)).width).toBe(1);
    expect(fails(file(HEADER, '-Y 1 +X 1 junk', px1)).message).toMatch(/not a resolution line/);
    expect(fails(file(HEADER, 'junk -Y 1 +X 1', px1)).message).toMatch(/not a resolution line/);
    expect(fails(file(HEADER, '+X  12  -Y  12', px1)).message).toMatch(/column by column/);
    expect(fails(file(HEADER, 'x +X 2 -Y 2', px1)).message).toMatch(/not a resolution line/);
    expect(fails(file(HEADER, '+X 2 -Y 2 x', px1)).message).toMatch(/not a resolution line/);
    expect(fails(file(HEADER, '-Y 2 +X 0', px1)).message).toMatch(/0 × 2/);
  });

  it('sizes: 4096 × 4096 is allowed (then short of bytes); the room reported', () => {
    expect(fails(file(HEADER, '-Y 4096 +X 4096', px1)).message).toMatch(/4096 scanlines, but the 4 bytes after it hold at most 1$/);
    expect(fails(file(HEADER, '-Y 3000 +X 4000', rleLine(4000, [[128 + 127, 1]]))).message).toMatch(/the 6 bytes after it hold at most 1$/);
  });

  it('run-length scanlines cut anywhere: in the marker, before a count, before a run\'s value, inside a literal', () => {
    const cut = (tail: number[]) => fails(file(HEADER, '-Y 2 +X 8', [...rleLine(8, [[136, 1], [136, 1], [136, 1], [136, 1]]), ...tail])).message;
    for (const tail of [[2, 2, 0, 8, 136], [2, 2, 0, 8], [2, 2, 0, 8, 136, 1, 136], [2, 2, 0, 8, 8, 1, 2, 3]]) {
      expect(cut(tail), tail.join()).toMatch(/the pixels end in scanline 2 of 2/);
    }
    // In the last channel, where no later check would catch it: its count, its run's value, its literal.
    const last = [2, 2, 0, 8, 136, 1, 136, 1, 136, 1];
    for (const tail of [last, [...last, 136], [...last, 8, 1, 2, 3]]) expect(cut(tail), tail.join()).toMatch(/the pixels end in scanline 2 of 2/);
    // The marker itself cut: three bytes of four.
    expect(cut([2, 2, 0])).toMatch(/the pixels end in scanline 2 of 2/);
  });

  it('a literal of 128 bytes (the count 128 is a literal, not a run)', () => {
    const w = 128, lit = [128, ...Array.from({ length: 128 }, (_, i) => i)];
    const img = ok(file(HEADER, `-Y 1 +X ${w}`, rleLine(w, [lit, [128 + 127, 0, 129, 0], [128 + 127, 0, 129, 0], [128 + 127, 137, 129, 137]])));
    expect(img.rgb[3 * 100] * 0.5 - 0.5).toBe(100);
  });

  it('which scanlines are run-length: only (2, 2, width < 32768) at a width of 8 or more; the rest flat', () => {
    // 8 wide, flat, its first pixel (2, 2, 200, 137): the third byte's top bit says it is a pixel.
    const first = [2, 2, 200, 137], rest = Array.from({ length: 7 }, () => [10, 20, 30, 137]).flat();
    expect(ok(file(HEADER, '-Y 1 +X 8', [...first, ...rest])).rgb[2] * 0.5 - 0.5).toBe(200);
    // 8 wide, flat, first pixel (2, 5, 0, 137): not the marker.
    expect(ok(file(HEADER, '-Y 1 +X 8', [2, 5, 0, 137, ...rest])).rgb[1] * 0.5 - 0.5).toBe(5);
    // 4 wide, flat, first pixel (2, 2, 0, 137): too narrow for run-length scanlines.
    expect(ok(file(HEADER, '-Y 1 +X 4', [2, 2, 0, 137, 10, 20, 30, 137, 10, 20, 30, 137, 10, 20, 30, 137])).rgb[0] * 0.5 - 0.5).toBe(2);
    // 32768 wide, flat: too wide for them (its width does not fit the marker's 15 bits).
    const wide = new Uint8Array(32768 * 4);
    for (let i = 0; i < 32768; i++) wide.set([2, 2, 0, 137], 4 * i);
    const img = ok(file(HEADER, '-Y 1 +X 32768', [...wide]));
    expect(img.rgb[3 * 32767] * 0.5 - 0.5).toBe(2);
  });

  it('flat pixels: a pixel with some channels 1 is a pixel; a third pixel lands third; repeats\' errors name their scanline', () => {
    const img = ok(file(HEADER, '-Y 1 +X 5', flat([1, 2, 3, 137], [1, 1, 5, 137], [7, 8, 9, 137], [1, 5, 1, 137], [5, 1, 1, 137])));
    expect(Array.from(img.rgb).map((v) => v * 0.5 - 0.5)).toEqual([1, 2, 3, 1, 1, 5, 7, 8, 9, 1, 5, 1, 5, 1, 1]);
    const two = (second: number[]) => fails(file(HEADER, '-Y 2 +X 3', [...flat([5, 5, 5, 130], [5, 5, 5, 130], [5, 5, 5, 130]), ...second])).message;
    expect(two(flat([1, 1, 1, 1]))).toMatch(/scanline 2 begins with a repeat/);
    expect(two(flat([5, 5, 5, 130], [1, 1, 1, 5]))).toMatch(/a repeat goes past the end of scanline 2 \(3 wide\)/);
  });
});
