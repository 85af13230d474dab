// A hand-written cursor over OBJ text: charCodeAt only, no split or regex per line, so a
// million-line file costs one pass. Lines ending in `\` continue on the next physical line.

const SPACE = 32;
const TAB = 9;
const LF = 10;
const VT = 11;
const FF = 12;
const CR = 13;
const HASH = 35;
const PLUS = 43;
const MINUS = 45;
const DOT = 46;
const SLASH = 47;
const ZERO = 48;
const NINE = 57;
const BACKSLASH = 92;
const LOWER_E = 101;
const UPPER_E = 69;

/** Exact powers of ten: a mantissa below 2^53 divided by one of these is correctly rounded. */
const POW10 = [1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22];

export class Scanner {
  pos = 0;
  /** 1-based physical line of `pos`. */
  line = 1;
  readonly text: string;
  readonly length: number;

  constructor(text: string) {
    this.text = text;
    this.length = text.length;
    if (text.charCodeAt(0) === 0xfeff) this.pos = 1; // a BOM left in by the caller's decoder
  }

  atEnd(): boolean {
    return this.pos >= this.length;
  }

  /** The character code at `p`, NaN past the end. */
  code(p: number): number {
    return this.text.charCodeAt(p);
  }

  /** Skips spaces, tabs and `\`-newline continuations, stopping at a line end or a token. */
  skipBlank(): void {
    const t = this.text;
    for (;;) {
      const c = t.charCodeAt(this.pos);
      if (c === SPACE || c === TAB || c === VT || c === FF) this.pos++;
      else if (c === BACKSLASH && this.continuation()) continue;
      else return;
    }
  }

  /** At the end of the statement: a line end, the end of the text, or a `#` comment. */
  atStatementEnd(): boolean {
    const c = this.text.charCodeAt(this.pos);
    return c !== c /* NaN: end of text */ || c === LF || c === CR || c === HASH;
  }

  /** Moves past the end of the current logical line (continuations and comments included). */
  nextLine(): void {
    const t = this.text;
    const n = this.length;
    let p = this.pos;
    // Stryker disable next-line EqualityOperator: p = n reads NaN (past the end), which matches nothing: pos = n after either way
    while (p < n) {
      const c = t.charCodeAt(p);
      if (c === LF) {
        this.line++;
        this.pos = p + 1;
        return;
      }
      if (c === CR) {
        p += t.charCodeAt(p + 1) === LF ? 2 : 1;
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

  /** End of the current token: whitespace, line end, comment or end of text. */
  tokenEnd(): number {
    const t = this.text;
    let p = this.pos;
    for (;;) {
      const c = t.charCodeAt(p);
      if (c !== c || c === SPACE || c === TAB || c === LF || c === CR || c === HASH || c === VT || c === FF) return p;
      if (c === BACKSLASH && isLineEnd(t.charCodeAt(p + 1))) return p;
      p++;
    }
  }

  /** The current token as a string (for keywords and messages), advancing past it. */
  readToken(): string {
    const end = this.tokenEnd();
    const s = this.text.slice(this.pos, end);
    this.pos = end;
    return s;
  }

  /**
   * A decimal number ending at whitespace; NaN (and the token skipped) when the token is not
   * one, `nan` and `1,5` included. Fast path for the usual short mantissas; parseFloat for
   * the rare long ones so every value rounds exactly as the spec's parseFloat would.
   */
  readNumber(): number {
    const t = this.text;
    const start = this.pos;
    let p = start;
    let c = t.charCodeAt(p);
    let negative = false;
    if (c === MINUS || c === PLUS) {
      negative = c === MINUS;
      c = t.charCodeAt(++p);
    }
    let mantissa = 0;
    let digits = 0;
    let scale = 0; // decimal digits after the point
    while (c >= ZERO && c <= NINE) {
      mantissa = mantissa * 10 + (c - ZERO);
      digits++;
      c = t.charCodeAt(++p);
    }
    if (c === DOT) {
      c = t.charCodeAt(++p);
      while (c >= ZERO && c <= NINE) {
        mantissa = mantissa * 10 + (c - ZERO);
        digits++;
        scale++;
        c = t.charCodeAt(++p);
      }
    }
    if (digits === 0) return this.skipBadToken();
    let exponent = 0;
    if (c === LOWER_E || c === UPPER_E) {
      c = t.charCodeAt(++p);
      let expNegative = false;
      if (c === MINUS || c === PLUS) {
        expNegative = c === MINUS;
        c = t.charCodeAt(++p);
      }
      let expDigits = 0;
      while (c >= ZERO && c <= NINE) {
        // Past 100000 (capped or not), or with 48 added to each digit, the exponent is far over 22: parseFloat, equal to the fast path.
        // Stryker disable next-line ConditionalExpression,EqualityOperator,ArithmeticOperator: as the line above says
        if (exponent < 100000) exponent = exponent * 10 + (c - ZERO);
        // Stryker disable next-line UpdateOperator: expDigits is only compared with 0
        expDigits++;
        c = t.charCodeAt(++p);
      }
      if (expDigits === 0) return this.skipBadToken();
      if (expNegative) exponent = -exponent;
    }
    if (!isDelimiter(c, t.charCodeAt(p + 1))) return this.skipBadToken();
    this.pos = p;
    const power = exponent - scale;
    // The slice holds the sign already.
    // Stryker disable next-line ConditionalExpression,EqualityOperator,UnaryOperator: parseFloat equals the exact fast path anywhere
    if (digits > 15 || power < -22 || power > 22) return parseFloat(t.slice(start, p));
    // Stryker disable next-line EqualityOperator: at power = 0, mantissa / 10⁰ = mantissa × 10⁰
    const value = power < 0 ? mantissa / POW10[-power] : mantissa * POW10[power];
    return negative ? -value : value;
  }

  /**
   * One field of a face corner: a signed integer, 0 for an empty field (`1//3`), NaN for
   * anything else. Stops at `/`, whitespace or a line end.
   */
  readIndexField(): number {
    const t = this.text;
    let p = this.pos;
    let c = t.charCodeAt(p);
    let negative = false;
    if (c === MINUS || c === PLUS) {
      negative = c === MINUS;
      c = t.charCodeAt(++p);
    }
    let value = 0;
    let digits = 0;
    while (c >= ZERO && c <= NINE) {
      value = value * 10 + (c - ZERO);
      // Stryker disable next-line UpdateOperator: digits is only compared with 0
      digits++;
      c = t.charCodeAt(++p);
    }
    if (c !== SLASH && !isDelimiter(c, t.charCodeAt(p + 1))) return this.skipBadToken();
    if (digits === 0 && negative) return this.skipBadToken();
    this.pos = p;
    return negative ? -value : value;
  }

  /** byte-scanner.ts reads plain statements on a fast path first; text always goes the general way. */
  plainKeyword(): number {
    return 0;
  }

  // Stryker disable next-line BlockStatement: undefined fails the reader's plain >= 0 as −1 does
  readPlainNumbers(_values: Float64Array): number {
    return -1;
  }

  readPlainCorners(_raw: Int32Array): number {
    return -1;
  }

  /** If the cursor is on a `/`, steps over it. */
  skipSlash(): boolean {
    // Stryker disable next-line BooleanLiteral: with no / the next field read is empty: 0, the cursor unmoved, as no field
    if (this.text.charCodeAt(this.pos) !== SLASH) return false;
    this.pos++;
    return true;
  }

  /**
   * The rest of the logical line, continuations joined by a space, a trailing ` #comment`
   * cut (a `#` inside a name is kept), trimmed. Leaves the cursor on the line end.
   */
  restOfLine(): string {
    const t = this.text;
    let out = '';
    let from = this.pos;
    let p = from;
    for (;;) {
      const c = t.charCodeAt(p);
      if (c !== c || c === LF || c === CR) break;
      if (c === HASH && (p === from || isBlank(t.charCodeAt(p - 1)))) break;
      if (c === BACKSLASH && isLineEnd(t.charCodeAt(p + 1))) {
        out += `${t.slice(from, p)} `;
        this.pos = p;
        this.continuation();
        p = from = this.pos;
        continue;
      }
      p++;
    }
    out += t.slice(from, p);
    this.pos = p;
    return out.trim();
  }

  /** The text from `from` to `to`, for `shown` (byte-scanner.ts decodes only what it shows). */
  shownSpan(from: number, to: number): string {
    return this.text.slice(from, to);
  }

  // Stryker disable next-line BlockStatement: only for a character no field read moves past, which text never holds (bytes may)
  charAt(p: number): string {
    // Stryker disable next-line MethodExpression: the same: never called for text
    return this.text.charAt(p);
  }

  /** The statement before the cursor, its last 60 characters at most, for a message. */
  lineBefore(): string {
    const t = this.text;
    let start = this.pos;
    while (start > 0 && start > this.pos - 60 && t.charCodeAt(start - 1) !== LF) start--;
    return t.slice(start, this.pos);
  }

  private skipBadToken(): number {
    this.pos = this.tokenEnd();
    return NaN;
  }

  /** At a `\`: if a line end follows, steps over both (counting the line) and returns true. */
  private continuation(): boolean {
    const t = this.text;
    const next = t.charCodeAt(this.pos + 1);
    if (next === LF) {
      this.pos += 2;
    } else if (next === CR) {
      this.pos += t.charCodeAt(this.pos + 2) === LF ? 3 : 2;
    } else if (next !== next) {
      this.pos += 1; // a `\` at the very end of the file continues into nothing
      // Stryker disable next-line BooleanLiteral: the cursor is past the `\` either way, and every caller then meets the end
      return true;
    } else {
      return false;
    }
    this.line++;
    return true;
  }
}

function isLineEnd(c: number): boolean {
  return c === LF || c === CR || c !== c;
}

function isBlank(c: number): boolean {
  return c === SPACE || c === TAB || c === VT || c === FF;
}

/** What may follow a number or index: whitespace, a line end, a comment, a continuation. */
function isDelimiter(c: number, next: number): boolean {
  return c !== c || c === SPACE || c === TAB || c === LF || c === CR || c === HASH || c === VT || c === FF
    || (c === BACKSLASH && isLineEnd(next));
}
