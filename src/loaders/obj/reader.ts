// The statement loop: OBJ text → flat lists of vertices, face corners and triangles, with
// faults turned into warnings. Building the drawable mesh is build-mesh.ts's job.
import { CornerLists } from './corners';
import { F64List, I32List } from './growable';
import type { Capacities } from './estimate';
import { ByteScanner } from './byte-scanner';
import { readPositionCorners } from './position-corners';
import { Scanner } from './scanner';
import { RUN_INTS, type ObjRaw } from './raw';
import { Settings } from './settings';
import { dropZeroArea, MAX_FACE_CORNERS, triangulate } from './triangulate';
import { shown, Warnings } from '../warnings';

export type { ObjRaw } from './raw';

/** The most corners a face read on a fast path may have (a longer one is read the general way). */
const PLAIN_CORNERS = 64;

/** The cursor the reader walks: over text (scanner.ts) or UTF-8 bytes (byte-scanner.ts), the same statements either way. */
export type ObjScanner = Scanner | ByteScanner;

export function readObj(text: string): ObjRaw {
  return new ObjReader(new Scanner(text)).read();
}

/** UTF-8 bytes from `start` (past a byte-order mark); `capacities`: the lists' expected lengths. */
export function readObjBytes(bytes: Uint8Array, start: number, capacities: Capacities | null = null): ObjRaw {
  return new ObjReader(new ByteScanner(bytes, start), capacities).read();
}

/** The reader's state across statements: the lists being filled and the current material and smoothing. */
class ObjReader {
  private readonly positions: F64List;
  private colors: F64List | null = null;
  private readonly uvs: F64List;
  private readonly normals: F64List;
  /** The kept corners' position, uv and normal indices. */
  private readonly cornerLists: CornerLists;
  private readonly triangles: I32List;
  private readonly faces: I32List;
  private faceCount = 0;
  /** How many positions, uvs and normals have been read: the lists' lengths over 3, 2 and 3, kept as integers. */
  private vCount = 0;
  private tCount = 0;
  private nCount = 0;
  private triangleCount = 0;
  // Stryker disable next-line ArithmeticOperator: an initial size: the list grows (growable.ts)
  private readonly runs = new I32List(3 * RUN_INTS);
  private readonly warnings = new Warnings();
  /** The names read and the current material and smoothing slot. */
  private readonly settings = new Settings();
  private droppedFaces = 0;
  private firstDroppedLine = 0;
  /** The numbers of the statement being read (readValues). */
  private readonly values = new Float64Array(8);
  /** A plain face's raw indices (readPlainCorners): 3 per corner, up to PLAIN_CORNERS corners. */
  // Stryker disable next-line ArithmeticOperator: too short, it only hands faces to the general way (no room), which reads them alike
  private readonly raw = new Int32Array(3 * PLAIN_CORNERS);
  /** What readCorners found: the first fault ('' for none) and how many corners the face has. */
  // Stryker disable next-line StringLiteral: readCorners sets it before anything reads it
  private fault = '';
  private cornerCount = 0;

  /** `sc` when it reads bytes (the fast path for bare position indices reads them itself), else null. */
  private readonly byteScanner: ByteScanner | null;

  constructor(private readonly sc: ObjScanner, capacities: Capacities | null = null) {
    this.byteScanner = sc instanceof ByteScanner ? sc : null;
    const c = capacities;
    // An initial size only: a list too small grows (growable.ts), so no size changes what is read.
    // Stryker disable MethodExpression,LogicalOperator: initial sizes, see above
    this.positions = new F64List(Math.max(1024, c?.positions ?? 0));
    this.uvs = new F64List(Math.max(1024, c?.uvs ?? 0));
    this.normals = new F64List(Math.max(1024, c?.normals ?? 0));
    this.cornerLists = new CornerLists(Math.max(1024, c?.corners ?? 0));
    this.triangles = new I32List(Math.max(1024, c?.triangles ?? 0));
    this.faces = new I32List(Math.max(1024, c?.faces ?? 0));
    // Stryker restore MethodExpression,LogicalOperator
  }

  read(): ObjRaw {
    this.statements();
    return this.result();
  }

  /**
   * Every statement to the end. Only the loop: the JIT compiles it while it runs (on-stack), and
   * code after it, not yet run then, would throw that compiled code away at the end of each file.
   */
  private statements(): void {
    const sc = this.sc;
    while (!sc.atEnd()) {
      // The usual lines, `v x y z` and `f a b c`, straight to their statements, which try their
      // fast paths first: a line is never handed back to be dispatched and read again.
      const plain = sc.plainKeyword();
      // Stryker disable next-line ConditionalExpression: statement() sends a plain v or f line (no blank before it) to the same method
      if (plain === 0) {
        this.statement();
        continue;
      }
      if (plain === 1) this.vertex(sc.line);
      else this.faceStatement(sc.line);
      sc.nextLine();
    }
  }

  private result(): ObjRaw {
    const { positions, colors, uvs, normals, triangles, faces, faceCount, triangleCount, runs } = this;
    const { corners, uvs: cornerUvs, normals: cornerNormals } = this.cornerLists;
    return {
      positions, colors, uvs, normals, corners, cornerUvs, cornerNormals, triangles, faces, faceCount, triangleCount, runs,
      materials: this.settings.materials, objects: this.settings.objects, groupNames: this.settings.groupNames, mtllibs: this.settings.mtllibs,
      warnings: this.warnings, droppedFaces: this.droppedFaces, firstDroppedLine: this.firstDroppedLine,
    };
  }

  /** One statement from the cursor (blanks and comments skipped), the cursor then past its line. */
  private statement(): void {
    const sc = this.sc;
    sc.skipBlank();
    const line = sc.line;
    if (sc.atStatementEnd()) {
      sc.nextLine();
      return;
    }
    const c0 = sc.code(sc.pos);
    const c1 = sc.code(sc.pos + 1);
    const c2End = endsKeyword(sc.code(sc.pos + 2));
    if (c0 === 118 /* v */ && endsKeyword(c1)) this.vertex(line);
    else if (c0 === 118 && c1 === 116 /* vt */ && c2End) this.textureCoordinate(line);
    else if (c0 === 118 && c1 === 110 /* vn */ && c2End) this.normal(line);
    else if (c0 === 102 /* f */ && endsKeyword(c1)) this.faceStatement(line);
    else this.otherStatement(line);
    sc.nextLine();
  }

  /** Reads up to 8 numbers to the end of the statement; returns how many, or −1 if one is bad. */
  private readValues(): number {
    const { sc, values } = this;
    const plain = sc.readPlainNumbers(values);
    // Stryker disable next-line EqualityOperator: with no number on the fast path the general way reads none either: 0
    if (plain >= 0) return plain;
    let n = 0;
    let bad = false;
    for (;;) {
      sc.skipBlank();
      if (sc.atStatementEnd()) return bad ? -1 : n;
      const before = sc.pos;
      const x = sc.readNumber();
      if (sc.pos === before) sc.pos++; // never stall on a character no reader consumes
      if (!Number.isFinite(x)) bad = true;
      // Stryker disable next-line ConditionalExpression,EqualityOperator: values holds 8: a write past them is dropped
      if (n < 8) values[n] = x;
      n++;
    }
  }

  private dropFace(line: number, message: string): void {
    this.warnings.add(line, message);
    if (this.droppedFaces++ === 0) this.firstDroppedLine = line;
  }

  /** `v x y z [r g b]`: a position, and a colour once any vertex has one. */
  private vertex(line: number): void {
    this.sc.pos += 1;
    this.addVertex(line, this.readValues());
  }

  /** The vertex of the `n` numbers readValues read (−1: a bad one). */
  private addVertex(line: number, n: number): void {
    const { sc, positions, values, warnings } = this;
    const index = this.vCount++;
    if (n < 3) {
      this.cornerLists.markBad(0, index, line);
      warnings.add(line, n < 0 ? `vertex with a coordinate that is not a number (${shownLine(sc)}); faces using it are dropped`
        : `vertex with ${n} of its 3 coordinates; faces using it are dropped`);
      positions.push3(NaN, NaN, NaN);
    } else {
      positions.push3(values[0], values[1], values[2]);
      if (n > 7) warnings.add(line, `vertex with ${n} values; those after x y z r g b ignored`);
    }
    if (n >= 6 && this.colors === null) {
      this.colors = new F64List(positions.data.length);
      for (let k = 0; k < index; k++) this.colors.push3(1, 1, 1);
    }
    if (this.colors !== null) {
      if (n >= 6) this.colors.push3(values[3], values[4], values[5]);
      else this.colors.push3(1, 1, 1);
    }
  }

  /** `vt u [v [w]]`. */
  private textureCoordinate(line: number): void {
    const { sc, uvs, values } = this;
    sc.pos += 2;
    const n = this.readValues(), index = this.tCount++;
    if (n < 1) {
      this.cornerLists.markBad(1, index, line);
      this.warnings.add(line, `texture coordinate that is not a number (${shownLine(sc)}); faces using it are dropped`);
      uvs.push(NaN);
      uvs.push(NaN);
    } else {
      uvs.push(values[0]);
      uvs.push(n > 1 ? values[1] : 0);
    }
  }

  /** `vn x y z`. */
  private normal(line: number): void {
    const { normals, values } = this;
    this.sc.pos += 2;
    const n = this.readValues(), index = this.nCount++;
    if (n < 3) {
      this.cornerLists.markBad(2, index, line);
      this.warnings.add(line, `normal with ${n < 0 ? 'a value that is not a number' : `${n} of its 3 values`}; faces using it are dropped`);
      normals.push3(NaN, NaN, NaN);
    } else {
      normals.push3(values[0], values[1], values[2]);
    }
  }

  /** `f v/t/n …`: its corners read, then the face kept (triangulated) or dropped with the reason. */
  private faceStatement(line: number): void {
    this.sc.pos += 1;
    const corners = this.cornerLists.corners;
    const start = corners.length;
    this.readCorners();
    const { fault, cornerCount } = this;
    const count = corners.length - start;
    if (count < 3 || fault !== '') this.cornerLists.truncate(start); // nothing of a dropped face kept
    if (cornerCount > MAX_FACE_CORNERS) this.dropFace(line, `face of ${cornerCount} vertices, more than the ${MAX_FACE_CORNERS} a face may have; face dropped`);
    else if (fault !== '') this.dropFace(line, `${fault}; face dropped`);
    else if (count < 3) this.dropFace(line, `face with ${count} ${count === 1 ? 'vertex' : 'vertices'} (a face needs 3); face dropped`);
    else this.keepFace(line, start, count);
  }

  /**
   * The face's corners onto `corners` (and `cornerUvs`, `cornerNormals`), up to the first fault; the
   * rest of the statement is still read, to count its corners. Sets `fault` and `cornerCount`.
   */
  private readCorners(): void {
    if (this.readBareCorners() || this.readPlainCorners()) return;
    const sc = this.sc;
    let fault = '';
    let cornerCount = 0;
    const { vCount, tCount, nCount } = this;
    for (;;) {
      sc.skipBlank();
      if (sc.atStatementEnd()) break;
      const tokenStart = sc.pos;
      const v = sc.readIndexField();
      let t = 0, nn = 0;
      if (sc.skipSlash()) {
        t = sc.readIndexField();
        if (sc.skipSlash()) nn = sc.readIndexField();
      }
      if (sc.pos === tokenStart) {
        sc.pos++; // never stall on a character no reader consumes
        if (fault === '') fault = `${shown(sc.charAt(tokenStart))} is not a face corner`;
      }
      // Past the cap the line is still read to its end (to count it), but nothing is kept.
      // Stryker disable next-line ConditionalExpression: past the cap the face is dropped as too long whatever fault holds, if any
      if (++cornerCount > MAX_FACE_CORNERS && fault === '') fault = 'too many';
      if (fault !== '') continue;
      if (v !== v || t !== t || nn !== nn) fault = `${shown(sc.shownSpan(tokenStart, sc.tokenEnd()))} is not a face corner`;
      else fault = this.cornerLists.add(v, t, nn, vCount, tCount, nCount);
    }
    this.fault = fault;
    this.cornerCount = cornerCount;
  }

  /**
   * readCorners for `f 1 2 3` over bytes (position-corners.ts): bare position indices within
   * range, straight into the corner list while it holds nothing else (fewer than 3 are then
   * dropped as the general way drops them); false, the cursor unmoved, for any other face.
   */
  // Stryker disable next-line BlockStatement: undefined, as false, hands the face to the other ways, which read it alike
  private readBareCorners(): boolean {
    const { byteScanner: sc, cornerLists: lists } = this;
    // Stryker disable next-line ConditionalExpression: the same: false for every face
    if (sc === null || !lists.positionsOnly()) return false;
    const corners = lists.corners, start = corners.length;
    const count = readPositionCorners(sc, corners.reserve(PLAIN_CORNERS), start, PLAIN_CORNERS, this.vCount);
    // Stryker disable next-line EqualityOperator: a face of no corners read the general way has none either
    if (count < 0) return false;
    corners.length = start + count;
    this.fault = '';
    this.cornerCount = count;
    // Stryker disable next-line BooleanLiteral: false: at the line end now, the ways after this add no corner and no fault
    return true;
  }

  /**
   * readCorners for a plain face (the scanner's fast path), as the general way reads it, faults
   * and all: the line is read once, whatever its corners hold. False, the cursor unmoved, for a
   * face that is not plain.
   */
  private readPlainCorners(): boolean {
    const { sc, cornerLists, raw } = this;
    const count = sc.readPlainCorners(raw);
    // Stryker disable next-line EqualityOperator: a face of no corners read the general way has none either
    if (count < 0) return false;
    const { vCount, tCount, nCount } = this;
    let fault = '';
    // Straight into the lists when no corner needs more (addPlain); else corner by corner, which
    // starts the uv and normal lists, checks bad elements and names the first fault.
    // Stryker disable next-line ConditionalExpression,EqualityOperator: addPlain writes what add would, or leaves it to add (corners.ts)
    if (count < 3 || !cornerLists.addPlain(raw, count, vCount, tCount, nCount)) {
      for (let k = 0; k < 3 * count && fault === ''; k += 3) fault = cornerLists.add(raw[k], raw[k + 1], raw[k + 2], vCount, tCount, nCount);
    }
    this.fault = fault;
    this.cornerCount = count;
    return true;
  }

  /** The face's `count` corners (read from `start`) and triangles kept, unless triangulating leaves no area. */
  private keepFace(line: number, start: number, count: number): void {
    if (count === 3) {
      // A triangle as written is kept as written, with no entry in `triangles`.
      this.addFace(3, 1);
      return;
    }
    const { triangles, positions } = this;
    const corners = this.cornerLists.corners;
    const firstTriangle = triangles.length / 3;
    const clipped = triangulate(positions.data, corners.data, start, count, triangles);
    // What triangulating a polygon makes of zero area is not kept.
    const kept = dropZeroArea(positions.data, corners.data, triangles, firstTriangle);
    if (kept === 0) {
      this.cornerLists.truncate(start);
      this.dropFace(line, `face of ${count} vertices with no area (its corners are repeated or on one line); face dropped`);
      return;
    }
    if (!clipped) this.warnings.add(line, `face of ${count} vertices too large to ear-clip in time; part of it drawn as a fan`);
    this.addFace(count, kept);
    this.faces.push(kept);
  }

  /** A kept face onto `faces` (a polygon's kept triangles still to push), starting a run where the smoothing or material changed. */
  private addFace(count: number, kept: number): void {
    const { smooth, material } = this.settings;
    // A new run where the smoothing slot or material differs from the last run's (or there is none).
    const runs = this.runs, r = runs.length, d = runs.data;
    // Stryker disable next-line ConditionalExpression: at r = 0, d[−2] is undefined, no slot: a run is pushed either way
    if (r === 0 || d[r - 2] !== smooth || d[r - 1] !== material) runs.push3(this.faceCount, smooth, material);
    this.faces.push(count);
    this.faceCount++;
    this.triangleCount += kept;
  }

  /** o, g, s, usemtl, mtllib, or any other keyword (settings.ts). */
  private otherStatement(line: number): void {
    const sc = this.sc;
    const keyword = sc.readToken();
    sc.skipBlank();
    this.settings.statement(keyword, sc, line, this.warnings);
  }
}

/** Whitespace, a line end or the end of the text: what may follow a one- or two-letter keyword. */
function endsKeyword(c: number): boolean {
  return c !== c || c === 32 || c === 9 || c === 10 || c === 13 || c === 11 || c === 12;
}

/** The statement just read, shortened, for a message. */
function shownLine(sc: ObjScanner): string {
  return shown(sc.lineBefore().trim());
}
