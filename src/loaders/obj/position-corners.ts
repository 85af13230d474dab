// The commonest face line of all, `f 1 2 3` (scans, and most exports without uvs or normals):
// its bare position indices read from the bytes straight into the corner list, each resolved
// as it is read (no scratch array, no uv or normal field to fill).
import type { ByteScanner } from './byte-scanner';

const SPACE = 32, TAB = 9, LF = 10, CR = 13, ZERO = 48, NINE = 57;

/**
 * At a `f ` line's corners: positive indices within the `vCount` positions read so far, spaces
 * or tabs between, the line's end right after the last. Writes each, 0-based, into `out` from
 * `at` (room for `room`), moves the cursor to the line end and returns how many; −1 for
 * anything else (a sign, a `/`, 0, an index past vCount, a comment, more than `room`), the
 * cursor unmoved: the caller reads that face another way.
 */
export function readPositionCorners(sc: ByteScanner, out: Int32Array, at: number, room: number, vCount: number): number {
  const b = sc.bytes;
  let p = sc.pos;
  let count = 0;
  // The line ends in a LF or CR within `b` (byte-scanner.ts), so no loop here tests for the end.
  for (;;) {
    let c = b[p];
    while (c === SPACE || c === TAB) c = b[++p];
    if (c === LF || c === CR) break;
    if (count === room) return -1;
    let value = 0; // a double: a long run of digits only grows past vCount, never wraps
    while (c >= ZERO && c <= NINE) {
      value = value * 10 + (c - ZERO);
      c = b[++p];
    }
    // No digits (a sign, a `/`, a `#`…), index 0, or out of range. Whatever else follows the
    // digits is no digit either: the next turn of the loop meets it and hands the face back.
    if (value === 0 || value > vCount) return -1;
    out[at + count++] = value - 1;
  }
  sc.pos = p;
  return count;
}
