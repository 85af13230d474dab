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
