// scanner.ts over UTF-8 bytes: the same cursor, statement for statement, reading a Uint8Array
// instead of a string, so a file is parsed without decoding it. Every character the grammar
// looks at (digits, signs, blanks, line ends, `#`, `/`, `\`) is ASCII, and UTF-8 never uses
// an ASCII byte inside a longer character, so bytes and text split alike; only names and
// message text are decoded, span by span.
import { decodeSpan } from '../decode-span';

// The bytes the grammar looks at (constants here, not imported: the hot loops compare with them).
const SPACE = 32, TAB = 9, LF = 10, VT = 11, FF = 12, CR = 13, HASH = 35, BACKSLASH = 92;
const PLUS = 43, MINUS = 45, DOT = 46, SLASH = 47, ZERO = 48, NINE = 57, UPPER_E = 69, LOWER_E = 101;
const LOWER_F = 102, LOWER_V = 118;

/** What the cursor reads past the last byte. */
const EOF = -1;
/** Bytes enough to hold 40 UTF-16 units and more: `shown` cuts a token at 40. */
const SHOWN_BYTES = 256;
/** Below 2^53 a mantissa is an exact double, and so is each step of reading it. */
const EXACT_MANTISSA = 2 ** 53;
/** An exponent past this is not read further (parseFloat has the token). */
const EXPONENT_CAP = 100000;
/** Exact powers of ten: an exact mantissa times or over one of these is correctly rounded. */
const POW10 = [1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22];

export class ByteScanner {
  pos: number;
  /** 1-based physical line of `pos`. */
  line = 1;
  readonly bytes: Uint8Array;
  readonly length: number;
  /** The value of the number numberEnd read last: a field (its box written in place), as a returned double is a new heap number a call. */
  private value = 0;
  /** Where the content starts (after the byte-order mark the caller skipped). */
  private readonly start: number;

  /**
   * `start`: past the byte-order mark, if the caller found one. Content that does not end in a
   * line end is read from a copy with a LF after its `length` bytes, never read as content: so
   * a scan over digits or blanks always meets a line end within `bytes`, and those loops read
   * the next byte with no test for the end (where they meet the added LF, `p` is `length`).
   */
  constructor(bytes: Uint8Array, start = 0) {
    const last = bytes.length > 0 ? bytes[bytes.length - 1] : LF;
    const b = last === LF || last === CR ? bytes : withLineEnd(bytes);
    this.bytes = b;
    this.length = bytes.length;
    this.start = start;
    // A second mark, as scanner.ts skips a U+FEFF left in by the caller's decoder.
    this.pos = b[start] === 0xef && b[start + 1] === 0xbb && b[start + 2] === 0xbf ? start + 3 : start;
  }

  atEnd(): boolean {
    return this.pos >= this.length;
  }

  /** The byte at `p`, NaN past the end (as charCodeAt). */
  code(p: number): number {
    return p < this.length ? this.bytes[p] : NaN;
  }

  /** At a line's start: 1 for `v `, 2 for `f ` (the statements with a fast path), else 0. */
  plainKeyword(): number {
    const p = this.pos;
    if (p + 1 >= this.length || this.bytes[p + 1] !== SPACE) return 0;
    const c = this.bytes[p];
    return c === LOWER_V ? 1 : c === LOWER_F ? 2 : 0;
  }

  skipBlank(): void {
    const b = this.bytes;
    const n = this.length;
    for (;;) {
      const c = this.pos < n ? b[this.pos] : EOF;
      if (c === SPACE || c === TAB || c === VT || c === FF) this.pos++;
      else if (c === BACKSLASH && this.continuation()) continue;
      else return;
    }
  }

  atStatementEnd(): boolean {
    if (this.pos >= this.length) return true;
    const c = this.bytes[this.pos];
    return c === LF || c === CR || c === HASH;
  }

  nextLine(): void {
    const b = this.bytes;
    const n = this.length;
    let p = this.pos;
    while (p < n) {
      const c = b[p];
      if (c === LF) {
        this.line++;
        this.pos = p + 1;
        return;
      }
      if (c === CR) {
        p += p + 1 < n && b[p + 1] === LF ? 2 : 1;
        this.line++;
        this.pos = p;
        return;
      }
      if (c === BACKSLASH) {
        this.pos = p;
        if (this.continuation()) {
          p = this.pos;
          continue;
        }
      }
      p++;
    }
    this.pos = n;
  }

  tokenEnd(): number {
    return tokenEndAt(this.bytes, this.pos, this.length);
  }

  readToken(): string {
    const end = this.tokenEnd();
    const s = decodeSpan(this.bytes, this.pos, end);
    this.pos = end;
    return s;
  }

  /** As scanner.ts's readNumber: NaN (the token skipped) unless the token is a decimal number, then exactly parseFloat's value. */
  readNumber(): number {
    const end = this.numberEnd(this.pos);
    if (end < 0) return this.skipBadToken();
    this.pos = end;
    return this.value;
  }

  /**
   * A plain statement's numbers, fast: up to 8 finite numbers with spaces or tabs between, the
   * line's end right after the last (no comment, no continuation). Returns how many, leaving
   * the cursor on the line end; −1 for anything else, the cursor unmoved: the reader then reads
   * the statement the general way, which warns as it should.
   */
  readPlainNumbers(values: Float64Array): number {
    const b = this.bytes;
    const n = this.length;
    let p = this.pos;
    let count = 0;
    for (;;) {
      let c = p < n ? b[p] : EOF;
      while (c === SPACE || c === TAB) c = b[++p];
      if (c === LF || c === CR || c === EOF) break;
      if (count === values.length) return -1;
      const end = this.numberEnd(p);
      if (end < 0 || !Number.isFinite(this.value)) return -1;
      values[count++] = this.value;
      p = end;
    }
    this.pos = p;
    return count;
  }

  /**
   * A plain face's corners, fast: `v`, `v/t`, `v//n`, `v/t/n` (integers of at most 9 digits, a
   * field left empty read as 0), spaces or tabs between, the line's end after the last. Writes
   * 3 raw indices a corner into `raw` and returns how many corners; −1 for anything else or
   * more than fit, the cursor unmoved (the reader reads that face the general way).
   */
  readPlainCorners(raw: Int32Array): number {
    const b = this.bytes;
    const n = this.length;
    let p = this.pos;
    let count = 0;
    for (;;) {
      let c = p < n ? b[p] : EOF;
      while (c === SPACE || c === TAB) c = b[++p];
      if (c === LF || c === CR || c === EOF) break;
      if (3 * count === raw.length) return -1;
      for (let field = 0; field < 3; field++) {
        let negative = false;
        if (c === MINUS || c === PLUS) {
          negative = c === MINUS;
          c = b[++p];
        }
        let value = 0;
        let digits = 0;
        while (c >= ZERO && c <= NINE) {
          if (++digits > 9) return -1;
          value = value * 10 + (c - ZERO);
          c = b[++p];
        }
        if (digits === 0 && negative) return -1;
        raw[3 * count + field] = negative ? -value : value;
        if (c !== SLASH) {
          for (let rest = field + 1; rest < 3; rest++) raw[3 * count + rest] = 0;
          break;
        }
        if (field === 2) return -1; // a fourth field
        c = b[++p];
      }
      if (c !== SPACE && c !== TAB && c !== LF && c !== CR && c !== EOF) return -1;
      count++;
    }
    this.pos = p;
    return count;
  }

  /**
   * The end of the decimal number at `p` with its value in `value`, or −1 when the token is not
   * one. The value is exactly parseFloat's: below 2^53 a mantissa is an exact double and so is
   * a power of ten up to 1e22, so one multiply or divide rounds correctly (Clinger's fast
   * path); anything else (long mantissas, big exponents, subnormals) goes to parseFloat.
   */
  private numberEnd(from: number): number {
    const b = this.bytes;
    const n = this.length;
    let p = from;
    let c = p < n ? b[p] : EOF;
    let negative = false;
    if (c === MINUS || c === PLUS) {
      negative = c === MINUS;
      c = b[++p];
    }
    let mantissa = 0;
    let digits = 0;
    let scale = 0; // decimal digits after the point
    while (c >= ZERO && c <= NINE) {
      mantissa = mantissa * 10 + (c - ZERO);
      digits++;
      c = b[++p];
    }
    if (c === DOT) {
      c = b[++p];
      while (c >= ZERO && c <= NINE) {
        mantissa = mantissa * 10 + (c - ZERO);
        digits++;
        scale++;
        c = b[++p];
      }
    }
    if (digits === 0) return -1;
    let exponent = 0;
    if (c === LOWER_E || c === UPPER_E) {
      c = b[++p];
      let expNegative = false;
      if (c === MINUS || c === PLUS) {
        expNegative = c === MINUS;
        c = b[++p];
      }
      let expDigits = 0;
      while (c >= ZERO && c <= NINE) {
        if (exponent < EXPONENT_CAP) exponent = exponent * 10 + (c - ZERO);
        expDigits++;
        c = b[++p];
      }
      if (expDigits === 0) return -1;
      if (expNegative) exponent = -exponent;
    }
    // A space or LF (the usual ends) is a delimiter wherever it is; else the full test.
    if (c !== SPACE && c !== LF && !isDelimiterAt(b, p, n)) return -1;
    const power = exponent - scale;
    if (mantissa >= EXACT_MANTISSA || power < -22 || power > 22 || exponent >= EXPONENT_CAP || exponent <= -EXPONENT_CAP) {
      this.value = parseFloat(decodeSpan(b, from, p)); // the span holds the sign
    } else {
      const value = power < 0 ? mantissa / POW10[-power] : mantissa * POW10[power];
      this.value = negative ? -value : value;
    }
    return p;
  }

  readIndexField(): number {
    const b = this.bytes;
    const n = this.length;
    let p = this.pos;
    let c = p < n ? b[p] : EOF;
    let negative = false;
    if (c === MINUS || c === PLUS) {
      negative = c === MINUS;
      c = b[++p];
    }
    let value = 0;
    let digits = 0;
    while (c >= ZERO && c <= NINE) {
      value = value * 10 + (c - ZERO);
      digits++;
      c = b[++p];
    }
    if (c !== SLASH && !isDelimiterAt(b, p, n)) return this.skipBadToken();
    if (digits === 0 && negative) return this.skipBadToken();
    this.pos = p;
    return negative ? -value : value;
  }

  skipSlash(): boolean {
    if (this.pos >= this.length || this.bytes[this.pos] !== SLASH) return false;
    this.pos++;
    return true;
  }

  /** As scanner.ts: the rest of the logical line, decoded, continuations joined by a space, trimmed. */
  restOfLine(): string {
    const b = this.bytes;
    const n = this.length;
    let out = '';
    let from = this.pos;
    let p = from;
    for (;;) {
      const c = p < n ? b[p] : EOF;
      if (c === EOF || c === LF || c === CR) break;
      if (c === HASH && (p === from || isBlank(b[p - 1]))) break;
      if (c === BACKSLASH && isLineEndAt(b, p + 1, n)) {
        out += `${decodeSpan(b, from, p)} `;
        this.pos = p;
        this.continuation();
        p = from = this.pos;
        continue;
      }
      p++;
    }
    out += decodeSpan(b, from, p);
    this.pos = p;
    return out.trim();
  }

  /**
   * Bytes `from` .. `to` as `shown` would print their text, decoding no more than it shows: past
   * SHOWN_BYTES the text is longer than the 40 units shown, and its first 40 are the same.
   */
  shownSpan(from: number, to: number): string {
    return decodeSpan(this.bytes, from, Math.min(to, from + SHOWN_BYTES));
  }

  /** The character at `p` (its first UTF-16 unit, as charAt). */
  charAt(p: number): string {
    return decodeSpan(this.bytes, p, Math.min(this.length, p + 4)).charAt(0);
  }

  /** The statement before the cursor, its last 60 UTF-16 units at most, for a message. */
  lineBefore(): string {
    const b = this.bytes;
    let from = this.pos;
    // Each unit is at most 3 bytes: 4 × 60 bytes decode to more than 60 units.
    while (from > this.start && from > this.pos - 240 && b[from - 1] !== LF) from--;
    const text = decodeSpan(b, from, this.pos);
    return text.slice(Math.max(0, text.length - 60));
  }

  private skipBadToken(): number {
    this.pos = this.tokenEnd();
    return NaN;
  }

  /** At a `\`: if a line end follows, steps over both (counting the line) and returns true. */
  private continuation(): boolean {
    const b = this.bytes;
    const n = this.length;
    const q = this.pos + 1;
    if (q >= n) {
      this.pos += 1; // a `\` at the very end of the file continues into nothing
      return true;
    }
    if (b[q] === LF) this.pos += 2;
    else if (b[q] === CR) this.pos += q + 1 < n && b[q + 1] === LF ? 3 : 2;
    else return false;
    this.line++;
    return true;
  }
}

/** `bytes` and a LF. */
function withLineEnd(bytes: Uint8Array): Uint8Array {
  const b = new Uint8Array(bytes.length + 1);
  b.set(bytes);
  b[bytes.length] = LF;
  return b;
}

/** End of the token at `p`: whitespace, line end, comment, continuation or the end. */
function tokenEndAt(b: Uint8Array, p: number, n: number): number {
  for (; p < n; p++) {
    const c = b[p];
    if (c === SPACE || c === TAB || c === LF || c === CR || c === HASH || c === VT || c === FF) return p;
    if (c === BACKSLASH && isLineEndAt(b, p + 1, n)) return p;
  }
  return n;
}

function isLineEndAt(b: Uint8Array, p: number, n: number): boolean {
  return p >= n || b[p] === LF || b[p] === CR;
}

function isBlank(c: number): boolean {
  return c === SPACE || c === TAB || c === VT || c === FF;
}

/** What may follow a number or index at `p`: whitespace, a line end, a comment, a continuation, the end. */
function isDelimiterAt(b: Uint8Array, p: number, n: number): boolean {
  if (p >= n) return true;
  const c = b[p];
  return c === SPACE || c === TAB || c === LF || c === CR || c === HASH || c === VT || c === FF
    || (c === BACKSLASH && isLineEndAt(b, p + 1, n));
}
