// Collects a loader's warnings, capped so a file of a million bad lines stays cheap.
import type { LoadWarning } from './load-error';

const MAX_WARNINGS = 100;

export class Warnings {
  private readonly list: LoadWarning[] = [];
  private dropped = 0;
  private readonly seenKeywords = new Set<string>();

  add(line: number, message: string): void {
    if (this.list.length < MAX_WARNINGS) this.list.push({ line, message });
    else this.dropped++;
  }

  /** One warning per unknown keyword, not per line: a file full of `l` lines says so once. */
  addOncePerKeyword(keyword: string, line: number, message: string): void {
    if (this.seenKeywords.has(keyword)) return;
    this.seenKeywords.add(keyword);
    this.add(line, message);
  }

  get count(): number {
    return this.list.length + this.dropped;
  }

  /** The warnings, with one closing entry counting those past the cap. */
  result(): LoadWarning[] {
    if (this.dropped === 0) return this.list.slice();
    const last = this.list[this.list.length - 1].line;
    return [...this.list, { line: last, message: `${this.dropped} more warnings not listed` }];
  }
}

/** A token for a message: quoted, and cut short so a 10 MB token does not become a 10 MB warning. */
export function shown(token: string): string {
  return JSON.stringify(token.length > 40 ? `${token.slice(0, 40)}…` : token);
}
