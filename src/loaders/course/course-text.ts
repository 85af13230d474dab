// Reading the course's text files (docs/course-files.md#text-conventions): non-blank lines in order with their 1-based
// numbers, a few whitespace-separated numbers each, every fault a LoadError naming the line.
// Lazy and linear: a 10 MB line is scanned once, never split into millions of tokens.
import { LoadError } from '../load-error';
import { sniffModel, type ModelFormat } from '../sniff';
import { shown } from '../warnings';

/** A decimal number as the course's files write it: `-1`, `+3.`, `.5`, `9.5e-005`, `-1.0E-14`. */
const NUMBER = /^[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?$/;
/** No number the files need is longer; a longer token is rejected before any regex runs. */
const MAX_NUMBER_LENGTH = 64;

/** Whether `token` is a number as the course's files write one (linear time at any length). */
export function isNumber(token: string): boolean {
  return token.length <= MAX_NUMBER_LENGTH && NUMBER.test(token);
}

export interface ContentLine {
  /** 1-based physical line. */
  line: number;
  /** The first tokens (at most the number asked for, plus one to tell that more follow). */
  tokens: string[];
}

/** Throws for an HTML page or binary bytes, naming the line where they show. `format`: the text's, if already sniffed. */
export function rejectNonText(text: string, url: string, what: string, format: ModelFormat = sniffModel(text)): void {
  if (format === 'html') {
    throw new LoadError(url, `an HTML page (or other markup), not ${what}`, lineAt(text, Math.max(0, text.search(/\S/))));
  }
  if (format === 'binary') {
    const at = text.search(/[\0-\x08\x0e-\x1f\x7f\ufffd]/);
    throw new LoadError(url, `binary content, not ${what}`, lineAt(text, Math.max(0, at)));
  }
}

/** The 1-based line of character `index`. */
function lineAt(text: string, index: number): number {
  let line = 1;
  for (let i = 0; i < index; i++) {
    const c = text.charCodeAt(i);
    if (c === 10 || (c === 13 && text.charCodeAt(i + 1) !== 10)) line++;
  }
  return line;
}

/** A cursor over the non-blank lines of a text (BOM dropped; CRLF, CR or LF). */
export class CourseLines {
  readonly url: string;
  private readonly text: string;
  private pos: number;
  private line = 0;
  private readonly token = /\S+/g;
  /** The last non-blank line read, for "the file ends here" errors. */
  lastLine = 1;

  constructor(text: string, url: string) {
    this.text = text;
    this.url = url;
    this.pos = text.charCodeAt(0) === 0xfeff ? 1 : 0;
  }

  /**
   * Moves past the next physical line; returns where its first non-space character is
   * and where the line ends, or null at the end of the text. One charCodeAt pass, no slicing.
   */
  private physical(): { first: number; end: number } | null {
    const t = this.text, n = t.length;
    if (this.pos > n) return null;
    let p = this.pos, first = -1;
    for (; p < n; p++) {
      const c = t.charCodeAt(p);
      if (c === 10 || c === 13) break;
      if (first < 0 && c !== 32 && c !== 9) first = p;
    }
    this.line++;
    this.pos = p >= n ? n + 1 : p + (t.charCodeAt(p) === 13 && t.charCodeAt(p + 1) === 10 ? 2 : 1);
    return { first: first < 0 ? p : first, end: p };
  }

  /** The next non-blank line with up to `max` + 1 tokens, or null at the end of the text. */
  next(max: number): ContentLine | null {
    for (let l = this.physical(); l !== null; l = this.physical()) {
      if (l.first === l.end) continue;
      const tokens: string[] = [];
      const re = this.token;
      re.lastIndex = l.first;
      for (let m = re.exec(this.text); m !== null && m.index < l.end && tokens.length <= max; m = re.exec(this.text)) {
        tokens.push(m[0]);
      }
      if (tokens.length === 0) continue; // only other kinds of white space (\v, \f, U+00A0 …)
      this.lastLine = this.line;
      return { line: this.line, tokens };
    }
    return null;
  }

  /** Like `next`, but the end of the text is a LoadError: "the file ends here, `missing`". */
  require(max: number, missing: string): ContentLine {
    const got = this.next(max);
    if (got === null) throw new LoadError(this.url, `the file ends here, ${missing}`, this.lastLine);
    return got;
  }

  /** The first non-blank line left and how many there are, without keeping their text. */
  rest(): { first: number; count: number } | null {
    let first = 0, count = 0;
    for (let l = this.next(0); l !== null; l = this.next(0)) if (count++ === 0) first = l.line;
    return count === 0 ? null : { first, count };
  }

  /** A finite number, else a LoadError naming the line and what the token was to be. */
  number(token: string, line: number, what: string): number {
    const value = isNumber(token) ? Number(token) : NaN;
    if (Number.isFinite(value)) return value;
    const why = Number.isNaN(value) ? 'is not a number' : 'is too large';
    throw new LoadError(this.url, `${what}: ${shown(token)} ${why}`, line);
  }

  /** `count` numbers from the line (more than the line has is a LoadError). */
  numbers(l: ContentLine, count: number, what: string): number[] {
    if (l.tokens.length < count) {
      throw new LoadError(this.url, `${what} needs ${count} number${count === 1 ? '' : 's'}, the line has ${l.tokens.length}`, l.line);
    }
    const out: number[] = [];
    for (let k = 0; k < count; k++) out.push(this.number(l.tokens[k], l.line, what));
    return out;
  }

  /** A whole number ≥ `min` (a count, a degree), else a LoadError. */
  count(token: string, line: number, what: string, min: number): number {
    const value = this.number(token, line, what);
    if (!Number.isInteger(value) || value < min) {
      throw new LoadError(this.url, `${what}: ${shown(token)} is not a whole number ≥ ${min}`, line);
    }
    return value;
  }
}
