// Radiance .hdr (RGBE) files, the environment images people bring (docs/pbr.md#an-image): the header's lines to a blank line,
// the resolution line, then one scanline after another — flat pixels (r, g, b, e), with the old form's repeats (1, 1, 1, n), or
// run-length scanlines (2, 2, width) whose four channels are each runs (count > 128: count − 128 copies of one byte) and literals.
// A pixel is (m + ½)·2^(e − 136) per channel, 0 when e is 0 (Radiance's own colr_color); EXPOSURE and the other header lines are
// read past, as the web's viewers do. Sizes are checked against the bytes before anything is allocated; what cannot be read
// throws a LoadError naming the file and the line of the header or the scanline of the pixels.
import { LoadError } from './load-error';

/** An image of linear RGB, row 0 at the top, column 0 at the left. */
export interface HdrImage {
  width: number;
  height: number;
  rgb: Float32Array;
}

/** The most pixels an environment image may have: 4096 × 4096 (about 200 MB as floats; it is reduced to 512 wide anyway). */
export const MAX_PIXELS = 1 << 24;
/** The longest header read before giving up on finding its end. */
const MAX_HEADER = 1 << 16;

/** The file's lines from `start` up to the resolution line, with where the pixels begin (a CR LF line keeps its CR: every reader trims or stops at white space). */
function headerLines(b: Uint8Array, start: number, url: string): { lines: string[]; pixels: number } {
  const lines: string[] = [];
  const end = Math.min(b.length, start + MAX_HEADER);
  let p = start, blank = false;
  // Stryker disable next-line EqualityOperator: at p = end the inner loop stops at once and q === end breaks out
  while (p < end) {
    let q = p;
    // Stryker disable next-line EqualityOperator: b[end] is past the window (or undefined past the file): not LF, and q === end breaks out next
    while (q < end && b[q] !== 0x0a) q++;
    if (q === end) break;
    let text = '';
    // Stryker disable next-line EqualityOperator: i = q adds the line's LF, which the readers of a line trim as they trim a CR
    for (let i = p; i < q; i++) text += String.fromCharCode(b[i]);
    lines.push(text);
    p = q + 1;
    // The line after the blank one is the resolution line: the pixels follow it.
    if (blank) return { lines, pixels: p };
    if (text.trim() === '') blank = true;
  }
  throw new LoadError(url, `the header has no resolution line (such as "-Y 512 +X 1024") after its blank line`, lines.length + 1);
}

/** Pixel (r, g, b, e) as linear RGB into out[o..o+2]. */
function putPixel(out: Float32Array, o: number, r: number, g: number, b: number, e: number): void {
  if (e === 0) {
    out[o] = out[o + 1] = out[o + 2] = 0;
    return;
  }
  const f = 2 ** (e - 136);
  out[o] = (r + 0.5) * f;
  out[o + 1] = (g + 0.5) * f;
  out[o + 2] = (b + 0.5) * f;
}

/** Where a read is: the file, its bytes, the next byte `p`, the image's size and the scanline `s` (0-based). */
interface At { url: string; b: Uint8Array; p: number; width: number; height: number; s: number }

const short = (at: At) => new LoadError(at.url, `the pixels end in scanline ${at.s + 1} of ${at.height} (the file is ${at.b.length} bytes)`);

/** A run-length scanline (2, 2, width, then each channel's runs and literals) into line[4x + c]. */
function readRunLengthLine(at: At, line: Uint8Array): void {
  const { b, width } = at, n1 = at.s + 1;
  let p = at.p;
  // Stryker disable next-line EqualityOperator: a marker with nothing after it stops at the first count instead, with the same error
  if (p + 4 > b.length) throw short(at);
  const said = (b[p + 2] << 8) | b[p + 3];
  if (said !== width) throw new LoadError(at.url, `scanline ${n1} says it is ${said} wide; the header says ${width}`);
  p += 4;
  for (let c = 0; c < 4; c++) {
    let x = 0;
    while (x < width) {
      if (p >= b.length) throw short(at);
      const count = b[p++];
      if (count === 0) throw new LoadError(at.url, `scanline ${n1} has a run of length 0`);
      const n = count > 128 ? count - 128 : count;
      if (x + n > width) throw new LoadError(at.url, `a run goes past the end of scanline ${n1} (${width} wide)`);
      if (count > 128) {
        if (p >= b.length) throw short(at);
        const v = b[p++];
        // Stryker disable next-line EqualityOperator: k = n writes the next pixel's byte of this channel, written again by the next run (or past the line: dropped)
        for (let k = 0; k < n; k++) line[4 * (x + k) + c] = v;
      } else {
        if (p + n > b.length) throw short(at);
        for (let k = 0; k < n; k++) line[4 * (x + k) + c] = b[p++];
      }
      x += n;
    }
  }
  at.p = p;
}

/** Flat pixels into line; (1, 1, 1, n) repeats the pixel before n times, n shifted up by 8 for each repeat in a row. */
function readFlatLine(at: At, line: Uint8Array): void {
  const { b, width } = at, n1 = at.s + 1;
  let p = at.p, x = 0, shift = 0;
  while (x < width) {
    if (p + 4 > b.length) throw short(at);
    const r = b[p], g = b[p + 1], bb = b[p + 2], e = b[p + 3];
    p += 4;
    if (r === 1 && g === 1 && bb === 1) {
      if (x === 0) throw new LoadError(at.url, `scanline ${n1} begins with a repeat (1, 1, 1, n) of no pixel`);
      const n = e * 2 ** shift;
      if (x + n > width) throw new LoadError(at.url, `a repeat goes past the end of scanline ${n1} (${width} wide)`);
      // Stryker disable next-line EqualityOperator: k = n copies into the next pixel, written again when it is read (or past the line: dropped)
      for (let k = 0; k < n; k++) line.copyWithin(4 * (x + k), 4 * (x - 1), 4 * x);
      x += n;
      shift += 8;
    } else {
      line[4 * x] = r; line[4 * x + 1] = g; line[4 * x + 2] = bb; line[4 * x + 3] = e;
      x++;
      shift = 0;
    }
  }
  at.p = p;
}

export function parseHdr(bytes: ArrayBuffer | Uint8Array, options: { url: string }): HdrImage {
  const url = options.url, b = bytes instanceof Uint8Array ? bytes : new Uint8Array(bytes);
  // A UTF-8 byte-order mark some editors put before the header.
  const start = b[0] === 0xef && b[1] === 0xbb && b[2] === 0xbf ? 3 : 0;
  let first = start;
  // Stryker disable next-line EqualityOperator,ConditionalExpression: b[b.length] is undefined: not white space, so the loop stops there anyway
  while (first < b.length && (b[first] === 0x20 || b[first] === 0x09 || b[first] === 0x0d || b[first] === 0x0a)) first++;
  if (b[first] === 0x3c) throw new LoadError(url, 'this is an HTML page, not a Radiance .hdr image (a server\'s error page?)');
  if (b[start] !== 0x23 || b[start + 1] !== 0x3f) throw new LoadError(url, 'not a Radiance .hdr image: it does not begin with "#?"');

  const { lines, pixels } = headerLines(b, start, url);
  // Stryker disable next-line EqualityOperator,ArithmeticOperator: the resolution line (and lines past the last, undefined) never match FORMAT=
  for (let i = 0; i < lines.length - 1; i++) {
    const m = /^\s*FORMAT\s*=\s*(\S+)/.exec(lines[i]);
    if (m && m[1] !== '32-bit_rle_rgbe') throw new LoadError(url, `FORMAT=${m[1]}: only 32-bit_rle_rgbe (RGB) pixels are read`, i + 1);
  }
  const resolutionLine = lines.length, resolution = lines[lines.length - 1].trim();
  const m = /^([-+])Y\s+(\d+)\s+([-+])X\s+(\d+)$/.exec(resolution);
  if (!m) {
    const columns = /^[-+]X\s+\d+\s+[-+]Y\s+\d+$/.test(resolution);
    throw new LoadError(url, columns
      ? `"${resolution}": this file stores its pixels column by column, which is not read (only row by row: "-Y height +X width")`
      : `"${resolution}" is not a resolution line (such as "-Y 512 +X 1024")`, resolutionLine);
  }
  const height = Number(m[2]), width = Number(m[4]);
  const bottomUp = m[1] === '+', rightToLeft = m[3] === '-';
  if (width < 1 || height < 1) throw new LoadError(url, `an image of ${width} × ${height} pixels has none`, resolutionLine);
  if (width * height > MAX_PIXELS) {
    throw new LoadError(url, `${width} × ${height} pixels: more than the ${MAX_PIXELS} an environment may have (it is reduced to 512 wide: a 2048 × 1024 version lights the same)`, resolutionLine);
  }
  // Every scanline takes at least 4 bytes (one pixel, or a run-length scanline's marker): checked before the floats are made.
  const room = b.length - pixels;
  if (room < 4 * height) {
    throw new LoadError(url, `the header says ${height} scanlines, but the ${room} bytes after it hold at most ${Math.floor(room / 4)}`);
  }

  const rgb = new Float32Array(width * height * 3);
  const line = new Uint8Array(4 * width);
  const at = { url, b, p: pixels, width, height, s: 0 };
  for (let s = 0; s < height; s++) {
    at.s = s;
    const p = at.p;
    if (width >= 8 && width < 0x8000 && b[p] === 2 && b[p + 1] === 2 && (b[p + 2] & 0x80) === 0) readRunLengthLine(at, line);
    else readFlatLine(at, line);
    const row = bottomUp ? height - 1 - s : s;
    for (let x = 0; x < width; x++) {
      const col = rightToLeft ? width - 1 - x : x;
      putPixel(rgb, 3 * (row * width + col), line[4 * x], line[4 * x + 1], line[4 * x + 2], line[4 * x + 3]);
    }
  }
  return { width, height, rgb };
}
