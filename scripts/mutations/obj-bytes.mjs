// The OBJ parser over bytes: byte-scanner.ts's numbers, line ends, continuations and
// decoded names, and parseObjBytes's BOM. Each is caught by the comparison with the text parser
// (obj-bytes.test.ts) or by the million tokens against parseFloat (obj-bytes-numbers.test.ts).
// B14 on: the speed line's fast paths (plain lines, the weld by position, the line end added
// after the content, runs of material and smoothing), caught by obj-fast.test.ts's comparisons
// with the general way or by the loader's own tests. B27 on: faces of bare position indices
// read straight into the corner list (position-corners.ts); B33 on: a triangle's Newell normal.
const BYTES = 'src/loaders/obj/byte-scanner.ts';
const EQUAL = 'tests/unit/obj-bytes.test.ts';
const NUMBERS = 'tests/unit/obj-bytes-numbers.test.ts';
const FAST = 'tests/unit/obj-fast.test.ts';
const OBJ = 'tests/unit/obj.test.ts';
const POLYGONS = 'tests/unit/obj-polygons.test.ts';
const MESH = 'src/loaders/obj/build-mesh.ts';
const CORNERS = 'src/loaders/obj/corners.ts';
const POSITION_CORNERS = 'src/loaders/obj/position-corners.ts';

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
    edits: [{ file: 'src/loaders/obj/reader.ts', find: 'fault = cornerLists.add(raw[k], raw[k + 1], raw[k + 2], vCount, tCount, nCount);', replace: 'cornerLists.add(raw[k], raw[k + 1], raw[k + 2], vCount, tCount, nCount);' }],
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
  {
    name: 'B14 a file with uvs welded by position (its uvs lost)',
    edits: [{ file: MESH, find: 'let oneGroup = byPosition && uvOf === null && normalOf === null && runs[1] >= 0;', replace: 'let oneGroup = byPosition && normalOf === null && runs[1] >= 0;' }],
    tests: [OBJ, FAST],
  },
  {
    name: 'B15 a file under s off welded by position (smooth, not flat)',
    edits: [{ file: MESH, find: 'let oneGroup = byPosition && uvOf === null && normalOf === null && runs[1] >= 0;', replace: 'let oneGroup = byPosition && uvOf === null && normalOf === null && runs[1] >= -1;' }],
    tests: [POLYGONS, FAST],
  },
  {
    name: 'B16 a second smoothing group welded by position with the first',
    edits: [{ file: MESH, find: 'oneGroup = runs[r * RUN_INTS + 1] === runs[1];', replace: 'oneGroup = runs[r * RUN_INTS + 1] >= 0;' }],
    tests: [POLYGONS, FAST],
  },
  {
    name: 'B17 the weld by position shares no vertex between faces',
    edits: [{ file: MESH, find: 'let o = out[v];', replace: 'let o = -1;' }],
    tests: [OBJ, FAST],
  },
  {
    name: 'B18 a material that comes back after another not regrouped',
    edits: [{ file: MESH, find: 'else if (m !== runs[(r - 1) * RUN_INTS + 2]) inOrder = false;', replace: 'else if (m !== runs[(r - 1) * RUN_INTS + 2]) inOrder = true;' }],
    tests: [OBJ],
  },
  {
    name: 'B19 a usemtl starts no run (later faces keep the material before)',
    edits: [{ file: 'src/loaders/obj/reader.ts', find: 'if (r === 0 || d[r - 2] !== smooth || d[r - 1] !== material)', replace: 'if (r === 0 || d[r - 2] !== smooth)' }],
    tests: [OBJ],
  },
  {
    name: 'B20 every polygon drawn with the first polygon\'s triangles',
    edits: [{ file: MESH, find: 'for (let t = 3 * tri; t < 3 * (tri + kept); t++)', replace: 'for (let t = 0; t < 3 * kept; t++)' }],
    tests: [POLYGONS, FAST],
  },
  {
    name: 'B21 the first uv of the file read on the fast path (no uv list started)',
    edits: [{ file: CORNERS, find: 'else if (t !== 0) return false;', replace: 'else if (t !== t) return false;' }],
    tests: [FAST, EQUAL],
  },
  {
    name: 'B22 a vertex index out of range kept on the fast path',
    edits: [{ file: CORNERS, find: 'if (vi < 0) return false;', replace: 'if (vi < -2) return false;' }],
    tests: [FAST, EQUAL],
  },
  {
    name: 'B23 the line end added after the content read as content',
    edits: [{ file: BYTES, find: 'this.length = bytes.length;', replace: 'this.length = b.length;' }],
    tests: [NUMBERS, FAST],
  },
  {
    name: 'B24 the byte added after the content a digit, not a line end',
    edits: [{ file: BYTES, find: 'b[bytes.length] = LF;', replace: 'b[bytes.length] = 0x31;' }],
    tests: [FAST, EQUAL],
  },
  {
    name: 'B25 plain v lines read on the face path and f lines on the vertex path',
    edits: [{ file: BYTES, find: 'return c === LOWER_V ? 1 : c === LOWER_F ? 2 : 0;', replace: 'return c === LOWER_V ? 2 : c === LOWER_F ? 1 : 0;' }],
    tests: [FAST, EQUAL],
  },
  {
    name: 'B26 the general weld shares a vertex whatever its uv',
    edits: [{ file: MESH, find: 'if (rec[q + T] === t) break;', replace: 'break;' }],
    tests: [OBJ],
  },
  {
    name: 'B27 a bare face index one past the vertices read kept',
    edits: [{ file: POSITION_CORNERS, find: 'if (value === 0 || value > vCount) return -1;', replace: 'if (value === 0 || value > vCount + 1) return -1;' }],
    tests: [FAST, EQUAL],
  },
  {
    name: 'B28 a bare face index 0 kept (as position −1)',
    edits: [{ file: POSITION_CORNERS, find: 'if (value === 0 || value > vCount) return -1;', replace: 'if (value > vCount) return -1;' }],
    tests: [FAST, EQUAL],
  },
  {
    name: 'B29 a bare face read straight into the corners once the uv or normal list has started',
    edits: [{ file: CORNERS, find: 'return !this.anyBad && this.uvs === null && this.normals === null;', replace: 'return !this.anyBad;' }],
    tests: [FAST, EQUAL],
  },
  {
    name: 'B30 a bare face read straight into the corners after a bad element',
    edits: [{ file: CORNERS, find: 'return !this.anyBad && this.uvs === null && this.normals === null;', replace: 'return this.uvs === null && this.normals === null;' }],
    tests: [FAST, EQUAL],
  },
  {
    name: 'B31 a bare face of more corners than the room written past it',
    edits: [{ file: POSITION_CORNERS, find: 'if (count === room) return -1;', replace: 'if (count > room) return -1;' }],
    tests: [FAST],
  },
  {
    name: 'B32 a bare face of fewer than 3 corners kept (read as a triangle)',
    edits: [{ file: 'src/loaders/obj/reader.ts', find: 'corners.length = start + count;', replace: 'corners.length = start + Math.max(count, 3);' }],
    tests: [FAST, EQUAL],
  },
  {
    name: "B33 a triangle's Newell normal summed in another order (not the polygon loop's bits)",
    edits: [{ file: MESH, find: 'out[0] = 0 + (cy - ay) * (cz + az) + (ay - by) * (az + bz) + (by - cy) * (bz + cz);', replace: 'out[0] = 0 + (by - cy) * (bz + cz) + (cy - ay) * (cz + az) + (ay - by) * (az + bz);' }],
    tests: [FAST],
  },
  {
    name: "B34 a triangle's Newell normal summed without the loop's starting 0 (a −0 kept)",
    edits: [{ file: MESH, find: 'out[1] = 0 + (cz - az)', replace: 'out[1] = (cz - az)' }],
    tests: [FAST],
  },
  {
    name: 'B35 runs of a material that comes back copied in file order, not into their group',
    edits: [{ file: MESH, find: 'indices.set(fileOrder.subarray(runStart[r], runStart[r + 1]), offset[m]);', replace: 'indices.set(fileOrder.subarray(runStart[r], runStart[r + 1]), runStart[r]);' }],
    tests: [OBJ],
  },
  {
    name: 'B36 indices of a mesh over 65535 vertices put into 16 bits',
    edits: [{ file: MESH, find: 'const wide = w.count > 65535;', replace: 'const wide = false;' }],
    tests: [OBJ, FAST, 'tests/unit/obj-bytes-suite.test.ts'],
  },
];
