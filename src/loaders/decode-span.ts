// Text of a span of UTF-8 bytes, for the byte scanner's names and messages (obj/byte-scanner.ts).

/** ignoreBOM: a U+FEFF opening a span is text there, as it is inside the whole file's text. */
const utf8 = new TextDecoder('utf-8', { ignoreBOM: true });

/**
 * The text of UTF-8 bytes `from` .. `to`, as decoding the whole file would give it there (a
 * mark U+FEFF inside is text, invalid bytes are U+FFFD). Short ASCII spans (keywords, most
 * names) skip the decoder.
 */
export function decodeSpan(b: Uint8Array, from: number, to: number): string {
  // Stryker disable next-line ConditionalExpression,EqualityOperator,ArithmeticOperator,BlockStatement: which way a span goes is speed only: the decoder gives ASCII the same text
  if (to - from <= 16) {
    let s = '';
    for (let p = from; p < to; p++) {
      const c = b[p];
      if (c >= 0x80) return utf8.decode(b.subarray(from, to));
      s += String.fromCharCode(c);
    }
    return s;
  }
  return utf8.decode(b.subarray(from, to));
}
