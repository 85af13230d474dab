// Logical lines of the small text formats (MTL, and later .byu/.cfg): CRLF, CR or LF, a
// trailing `\` joining the next line, a leading BOM dropped. Linear in the text's length.

export interface TextLine {
  /** 1-based physical line where the logical line starts. */
  line: number;
  text: string;
}

export function logicalLines(text: string): TextLine[] {
  const physical = (text.charCodeAt(0) === 0xfeff ? text.slice(1) : text).split(/\r\n|\r|\n/);
  const out: TextLine[] = [];
  let parts: string[] = [];
  let start = 0;
  for (let i = 0; i < physical.length; i++) {
    const p = physical[i];
    if (parts.length === 0) start = i + 1;
    if (p.endsWith('\\')) {
      parts.push(p.slice(0, -1));
      continue;
    }
    parts.push(p);
    out.push({ line: start, text: parts.length === 1 ? parts[0] : parts.join(' ') });
    parts = [];
  }
  if (parts.length > 0) out.push({ line: start, text: parts.join(' ') });
  return out;
}

/** Cuts a comment: `#` at the start or after whitespace (a `#` inside a name stays). */
export function stripComment(text: string): string {
  const at = text.search(/(^|\s)#/);
  return at < 0 ? text : text.slice(0, at);
}
