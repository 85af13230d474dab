// The OBJ parser over bytes (issue 22): byte-scanner.ts's numbers, line ends, continuations and
// decoded names, and parseObjBytes's BOM. Each is caught by the comparison with the text parser
// (obj-bytes.test.ts) or by the million tokens against parseFloat (obj-bytes-numbers.test.ts).
const BYTES = 'src/loaders/obj/byte-scanner.ts';
const EQUAL = 'tests/unit/obj-bytes.test.ts';
const NUMBERS = 'tests/unit/obj-bytes-numbers.test.ts';

export default [
  {
    name: 'B1 the exponent\'s minus sign dropped',
    edits: [{ file: BYTES, find: 'if (expNegative) exponent = -exponent;', replace: '' }],
    tests: [NUMBERS],
  },
  {
    name: 'B2 the fast path taken past 2^53 (a long mantissa rounded twice)',
    edits: [{ file: BYTES, find: 'if (mantissa >= EXACT_MANTISSA || power < -22', replace: 'if (power < -22' }],
    tests: [NUMBERS],
  },
  {
    name: 'B3 the fast path taken for 1e23 (a power of ten that is no exact double)',
    edits: [{ file: BYTES, find: 'power < -22 || power > 22 ||', replace: 'power < -22 || power > 23 ||' }],
    tests: [NUMBERS],
  },
  {
    name: 'B4 a lone CR not a line end',
    edits: [{ file: BYTES, find: '      if (c === CR) {\n        p += p + 1 < n && b[p + 1] === LF ? 2 : 1;', replace: '      if (c === CR && p + 1 < n && b[p + 1] === LF) {\n        p += 2;' }],
    tests: [EQUAL],
  },
  {
    name: 'B5 the UTF-8 BOM read as content',
    edits: [{ file: 'src/loaders/obj.ts', find: "encoding === 'utf-8' ? skip : 0", replace: '0' }],
    tests: [EQUAL],
  },
  {
    name: 'B6 a continuation between two numbers not followed',
    edits: [{ file: BYTES, find: 'else if (c === BACKSLASH && this.continuation()) continue;', replace: 'else if (c === -2 && this.continuation()) continue;' }],
    tests: [EQUAL],
  },
  {
    name: 'B7 a name decoded one byte short',
    edits: [{ file: BYTES, find: 'out += decodeSpan(b, from, p);', replace: 'out += decodeSpan(b, from, p - 1);' }],
    tests: [EQUAL],
  },
  {
    name: 'B8 a U+FEFF that opens a name dropped by the decoder',
    edits: [{ file: 'src/loaders/decode-span.ts', find: "const utf8 = new TextDecoder('utf-8', { ignoreBOM: true });", replace: "const utf8 = new TextDecoder('utf-8');" }],
    tests: [EQUAL],
  },
  {
    name: 'B9 a face index past 9 digits kept on the fast path (wraps in 32 bits)',
    edits: [{ file: BYTES, find: 'if (++digits > 9) return -1;', replace: 'if (++digits > 12) return -1;' }],
    tests: [EQUAL],
  },
  {
    name: 'B10 a face with a bad corner kept on the fast path',
    edits: [{ file: 'src/loaders/obj/reader.ts', find: "if (cornerLists.add(raw[k], raw[k + 1], raw[k + 2], vCount, tCount, nCount) !== '') {", replace: "if (cornerLists.add(raw[k], raw[k + 1], raw[k + 2], vCount, tCount, nCount) === '#') {" }],
    tests: [EQUAL],
  },
  {
    name: 'B11 an infinite coordinate kept on the fast path (no warning)',
    edits: [{ file: BYTES, find: 'if (end < 0 || !Number.isFinite(this.value)) return -1;', replace: 'if (end < 0) return -1;' }],
    tests: [EQUAL],
  },
  {
    name: 'B12 a second BOM not skipped',
    edits: [{ file: BYTES, find: 'this.pos = b[start] === 0xef && b[start + 1] === 0xbb && b[start + 2] === 0xbf ? start + 3 : start;', replace: 'this.pos = start;' }],
    tests: [EQUAL],
  },
  {
    name: 'B13 a fault\'s line quoted from 60 bytes back, not 60 characters',
    edits: [{ file: BYTES, find: 'from > this.pos - 240', replace: 'from > this.pos - 60' }],
    tests: [EQUAL],
  },
];
