// The byte scanner's fast paths on their own (src/loaders/obj/byte-scanner.ts): what
// readPlainCorners and readPlainNumbers return, write and leave the cursor on, and the lines they
// hand back (−1, the cursor unmoved) for the reader's general way.
import { describe, expect, it } from 'vitest';
import { ByteScanner } from '../../src/loaders/obj/byte-scanner';

const scanner = (text: string): ByteScanner => new ByteScanner(new TextEncoder().encode(text));

/** readPlainCorners on `text` into a list of `slots` raw indices filled with 99 first: [count, raw, cursor]. */
function corners(text: string, slots = 24): [number, number[], number] {
  const s = scanner(text);
  const raw = new Int32Array(slots).fill(99);
  const count = s.readPlainCorners(raw);
  return [count, [...raw.subarray(0, 3 * Math.max(count, 0))], s.pos];
}

/** readPlainNumbers on `text` into 8 values: [count, values read, cursor]. */
function numbers(text: string, slots = 8): [number, number[], number] {
  const s = scanner(text);
  const values = new Float64Array(slots);
  const count = s.readPlainNumbers(values);
  return [count, [...values.subarray(0, Math.max(count, 0))], s.pos];
}

describe('ByteScanner.readPlainCorners', () => {
  it('reads v, v/t, v//n and v/t/n with signs, an empty or missing field as 0, up to the line end', () => {
    // '1/2/3 -4//5 +6/7 8' is 18 bytes: the cursor stays on the LF at 18.
    expect(corners('1/2/3 -4//5 +6/7 8\nf 9 9 9\n')).toEqual([4, [1, 2, 3, -4, 0, 5, 6, 7, 0, 8, 0, 0], 18]);
    // Tabs and spaces around, a CR LF end (the CR at 13), and a last corner ending in a slash.
    expect(corners('\t 10\t2/  3// \r\n')).toEqual([3, [10, 0, 0, 2, 0, 0, 3, 0, 0], 13]);
    // A CR right after the last corner (at 5).
    expect(corners('4 5 6\r\n')).toEqual([3, [4, 0, 0, 5, 0, 0, 6, 0, 0], 5]);
    // The end of the file ends the line too (5 bytes).
    expect(corners('1 2 3')).toEqual([3, [1, 0, 0, 2, 0, 0, 3, 0, 0], 5]);
  });

  it('reads indices of up to 9 digits, and exactly as many corners as `raw` holds', () => {
    expect(corners('123456789 1 -987654321\n')).toEqual([3, [123456789, 0, 0, 1, 0, 0, -987654321, 0, 0], 22]);
    expect(corners('1/1 2/2 3/3\n', 9)).toEqual([3, [1, 1, 0, 2, 2, 0, 3, 3, 0], 11]);
  });

  it('hands back, the cursor unmoved, what the general way must read', () => {
    for (const text of [
      '1 2 3 4\n', // 4 corners, room for 3 (9 slots)
    ]) expect(corners(text, 9), text).toEqual([-1, [], 0]);
    for (const text of [
      '1234567890 1 2\n', // 10 digits
      '1/2/3/4 5 6\n', // a fourth field
      '- 1 2\n', '1 -/2 3\n', // a sign with no digits
      '1 2x 3\n', '1 2,3 4\n', '1 2 3 # a comment\n', '1 2 3\\\n4\n', // anything but blanks or the line end after a corner
      '1 2 3\v\n', '1.5 2 3\n',
    ]) expect(corners(text), text).toEqual([-1, [], 0]);
  });
});

describe('ByteScanner.readPlainNumbers', () => {
  it('reads finite numbers with spaces or tabs between, the cursor on the line end', () => {
    // '1 -2.5\t3e2  ' is 12 bytes.
    expect(numbers('1 -2.5\t3e2  \nv 9\n')).toEqual([3, [1, -2.5, 300], 12]);
    expect(numbers(' .5 +7\r\n')).toEqual([2, [0.5, 7], 6]);
    expect(numbers('1 2 3 4 5 6 7 8\n')).toEqual([8, [1, 2, 3, 4, 5, 6, 7, 8], 15]);
    expect(numbers('0.25')).toEqual([1, [0.25], 4]);
  });

  it('hands back, the cursor unmoved, what the general way must read', () => {
    for (const text of [
      '1 2 3 4 5 6 7 8 9\n', // 9 numbers, room for 8
      '1 1e999 2\n', '1 -1e400\n', // not finite
      '1 2 nan\n', '1 2x\n', '1 2 # a comment\n', '1 2\\\n3\n', '1 2\v3\n',
    ]) expect(numbers(text), text).toEqual([-1, [], 0]);
  });
});
