// The statement loop: OBJ text → flat lists of vertices, face corners and triangles, with
// faults turned into warnings. Building the drawable mesh is build-mesh.ts's job.
import { F64List, I32List } from './growable';
import type { Capacities } from './estimate';
import { addUnique, splitGroups, splitMtllib } from './names';
import { ByteScanner } from './byte-scanner';
import { Scanner } from './scanner';
import { FLAT, RUN_INTS, type ObjRaw } from './raw';
import { dropZeroArea, MAX_FACE_CORNERS, triangulate } from './triangulate';
import { shown, Warnings } from '../warnings';

export type { ObjRaw } from './raw';

/** Smoothing slot before any `s`: files that never say `s` (scans) are meant to be smooth. */
const DEFAULT_SMOOTH = 0;

/** Statements read and deliberately not drawn, reported once each without "unknown". */
const UNSUPPORTED = new Set(['l', 'p', 'vp', 'curv', 'curv2', 'surf', 'cstype', 'deg', 'bmat', 'step', 'parm',
  'trim', 'hole', 'scrv', 'sp', 'end', 'con', 'mg', 'bevel', 'c_interp', 'd_interp', 'lod', 'usemap', 'maplib',
  'shadow_obj', 'trace_obj', 'ctech', 'stech', 'call', 'csh']);

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
  private readonly corners: I32List;
  private cornerUvs: I32List | null = null;
  private cornerNormals: I32List | null = null;
  private readonly triangles: I32List;
  private readonly faces: I32List;
  private faceCount = 0;
  private triangleCount = 0;
  private readonly runs = new I32List(3 * RUN_INTS);
  /** The current run's smoothing slot and material (NaN before the first kept face). */
  private runSmooth = NaN;
  private runMaterial = NaN;
  private readonly warnings = new Warnings();
  // A bad v/vt/vn keeps its slot (so later indices still mean the same element), flagged here.
  private readonly badLine = [new Map<number, number>(), new Map<number, number>(), new Map<number, number>()];
  private anyBad = false;
  private readonly materials: (string | null)[] = [null];
  private readonly materialSlot = new Map<string, number>();
  private readonly smoothSlot = new Map<string, number>();
  private readonly objects: string[] = [];
  private readonly groupNames: string[] = [];
  private readonly mtllibs: string[] = [];
  private readonly seenObjects = new Set<string>();
  private readonly seenGroups = new Set<string>();
  private readonly seenLibs = new Set<string>();
  private material = 0;
  private smooth = DEFAULT_SMOOTH;
  private droppedFaces = 0;
  private firstDroppedLine = 0;
  /** The numbers of the statement being read (readValues). */
  private readonly values = new Float64Array(8);
  /** A plain face's raw indices (readPlainCorners): 3 per corner, up to 64 corners. */
  private readonly raw = new Int32Array(3 * 64);
  /** What readCorners found: the first fault ('' for none) and how many corners the face has. */
  private fault = '';
  private cornerCount = 0;

  constructor(private readonly sc: ObjScanner, capacities: Capacities | null = null) {
    const c = capacities;
    this.positions = new F64List(Math.max(1024, c?.positions ?? 0));
    this.uvs = new F64List(Math.max(1024, c?.uvs ?? 0));
    this.normals = new F64List(Math.max(1024, c?.normals ?? 0));
    this.corners = new I32List(Math.max(1024, c?.corners ?? 0));
    this.triangles = new I32List(Math.max(1024, c?.triangles ?? 0));
    this.faces = new I32List(Math.max(1024, c?.faces ?? 0));
  }

  read(): ObjRaw {
    const sc = this.sc;
    while (!sc.atEnd()) {
      sc.skipBlank();
      const line = sc.line;
      if (sc.atStatementEnd()) {
        sc.nextLine();
        continue;
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
    const { positions, colors, uvs, normals, corners, cornerUvs, cornerNormals, triangles, faces, faceCount, triangleCount, runs } = this;
    return {
      positions, colors, uvs, normals, corners, cornerUvs, cornerNormals, triangles, faces, faceCount, triangleCount, runs,
      materials: this.materials, objects: this.objects, groupNames: this.groupNames, mtllibs: this.mtllibs,
      warnings: this.warnings, droppedFaces: this.droppedFaces, firstDroppedLine: this.firstDroppedLine,
    };
  }

  /** Reads up to 8 numbers to the end of the statement; returns how many, or −1 if one is bad. */
  private readValues(): number {
    const { sc, values } = this;
    const plain = sc.readPlainNumbers(values);
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
      if (n < 8) values[n] = x;
      n++;
    }
  }

  /** Element `index` of list `kind` (v, vt, vn) is unusable, from a bad `line`. */
  private markBad(kind: number, index: number, line: number): void {
    this.badLine[kind].set(index, line);
    this.anyBad = true;
  }

  private dropFace(line: number, message: string): void {
    this.warnings.add(line, message);
    if (this.droppedFaces++ === 0) this.firstDroppedLine = line;
  }

  /** `v x y z [r g b]`: a position, and a colour once any vertex has one. */
  private vertex(line: number): void {
    const { sc, positions, values, warnings } = this;
    sc.pos += 1;
    const n = this.readValues();
    const index = positions.length / 3;
    if (n < 3) {
      this.markBad(0, index, line);
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
    const n = this.readValues();
    if (n < 1) {
      this.markBad(1, uvs.length / 2, line);
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
    const n = this.readValues();
    if (n < 3) {
      this.markBad(2, normals.length / 3, line);
      this.warnings.add(line, `normal with ${n < 0 ? 'a value that is not a number' : `${n} of its 3 values`}; faces using it are dropped`);
      normals.push3(NaN, NaN, NaN);
    } else {
      normals.push3(values[0], values[1], values[2]);
    }
  }

  /** `f v/t/n …`: its corners read, then the face kept (triangulated) or dropped with the reason. */
  private faceStatement(line: number): void {
    this.sc.pos += 1;
    const start = this.corners.length;
    this.readCorners();
    const { fault, cornerCount } = this;
    const count = this.corners.length - start;
    if (count < 3 || fault !== '') this.truncateCorners(start); // nothing of a dropped face kept
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
    if (this.readPlainCorners()) return;
    const sc = this.sc;
    let fault = '';
    let cornerCount = 0;
    const vCount = this.positions.length / 3, tCount = this.uvs.length / 2, nCount = this.normals.length / 3;
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
      if (++cornerCount > MAX_FACE_CORNERS && fault === '') fault = 'too many';
      if (fault !== '') continue;
      if (v !== v || t !== t || nn !== nn) fault = `${shown(sc.shownSpan(tokenStart, sc.tokenEnd()))} is not a face corner`;
      else fault = this.addCorner(v, t, nn, vCount, tCount, nCount);
    }
    this.fault = fault;
    this.cornerCount = cornerCount;
  }

  /** One corner's OBJ indices resolved onto the corner lists; else the fault ('' for none). */
  private addCorner(v: number, t: number, nn: number, vCount: number, tCount: number, nCount: number): string {
    const vi = resolve(v, vCount), ti = t === 0 ? -1 : resolve(t, tCount), ni = nn === 0 ? -1 : resolve(nn, nCount);
    if (vi < 0) return `vertex index ${v} is outside the ${vCount} vertices read so far`;
    if (t !== 0 && ti < 0) return `texture coordinate index ${t} is outside the ${tCount} read so far`;
    if (nn !== 0 && ni < 0) return `normal index ${nn} is outside the ${nCount} read so far`;
    if (this.anyBad) {
      const unusable = this.unusable(vi, ti, ni);
      if (unusable !== '') return unusable;
    }
    this.corners.push(vi);
    if (ti >= 0 || this.cornerUvs !== null) (this.cornerUvs ??= this.absentSoFar()).push(ti);
    if (ni >= 0 || this.cornerNormals !== null) (this.cornerNormals ??= this.absentSoFar()).push(ni);
    return '';
  }

  /** A list of −1 for each corner before the one just pushed: the first uv or normal of the file. */
  private absentSoFar(): I32List {
    const list = new I32List(this.corners.data.length);
    list.data.fill(-1, 0, this.corners.length - 1);
    list.length = this.corners.length - 1;
    return list;
  }

  /** Forgets the corners from `start` on. */
  private truncateCorners(start: number): void {
    this.corners.length = start;
    if (this.cornerUvs) this.cornerUvs.length = start;
    if (this.cornerNormals) this.cornerNormals.length = start;
  }

  /** Which element of the corner a bad line left unusable ('' for none). */
  private unusable(vi: number, ti: number, ni: number): string {
    const badLine = this.badLine;
    if (badLine[0].has(vi)) return `vertex ${vi + 1} (line ${badLine[0].get(vi)}) is not usable`;
    if (ti >= 0 && badLine[1].has(ti)) return `texture coordinate ${ti + 1} (line ${badLine[1].get(ti)}) is not usable`;
    if (ni >= 0 && badLine[2].has(ni)) return `normal ${ni + 1} (line ${badLine[2].get(ni)}) is not usable`;
    return '';
  }

  /**
   * readCorners for a plain face (the scanner's fast path) whose corners are all usable, as
   * the general way reads it; false, with nothing read, for any other face.
   */
  private readPlainCorners(): boolean {
    const { sc, corners, raw } = this;
    const from = sc.pos;
    const count = sc.readPlainCorners(raw);
    if (count < 0) return false;
    const first = corners.length;
    const vCount = this.positions.length / 3, tCount = this.uvs.length / 2, nCount = this.normals.length / 3;
    for (let k = 0; k < 3 * count; k += 3) {
      if (this.addCorner(raw[k], raw[k + 1], raw[k + 2], vCount, tCount, nCount) !== '') {
        this.truncateCorners(first);
        sc.pos = from; // the general way says what is wrong
        return false;
      }
    }
    this.fault = '';
    this.cornerCount = count;
    return true;
  }

  /** The face's `count` corners (read from `start`) and triangles kept, unless triangulating leaves no area. */
  private keepFace(line: number, start: number, count: number): void {
    const { corners, triangles, positions } = this;
    if (count === 3) {
      // A triangle as written is kept as written, with no entry in `triangles`.
      this.addFace(3, 1);
      return;
    }
    const firstTriangle = triangles.length / 3;
    const clipped = triangulate(positions.data, corners.data, start, count, triangles);
    // What triangulating a polygon makes of zero area is not kept.
    const kept = dropZeroArea(positions.data, corners.data, triangles, firstTriangle);
    if (kept === 0) {
      this.truncateCorners(start);
      this.dropFace(line, `face of ${count} vertices with no area (its corners are repeated or on one line); face dropped`);
      return;
    }
    if (!clipped) this.warnings.add(line, `face of ${count} vertices too large to ear-clip in time; part of it drawn as a fan`);
    this.addFace(count, kept);
    this.faces.push(kept);
  }

  /** A kept face onto `faces` (a polygon's kept triangles still to push), starting a run where the smoothing or material changed. */
  private addFace(count: number, kept: number): void {
    if (this.smooth !== this.runSmooth || this.material !== this.runMaterial) {
      this.runSmooth = this.smooth;
      this.runMaterial = this.material;
      this.runs.push3(this.faceCount, this.smooth, this.material);
    }
    this.faces.push(count);
    this.faceCount++;
    this.triangleCount += kept;
  }

  /** o, g, s, usemtl, mtllib; anything else is a warning, once per keyword. */
  private otherStatement(line: number): void {
    const sc = this.sc;
    const keyword = sc.readToken();
    sc.skipBlank();
    switch (keyword) {
      case 'o':
        addUnique(this.objects, this.seenObjects, [sc.restOfLine()]);
        break;
      case 'g':
        addUnique(this.groupNames, this.seenGroups, splitGroups(sc.restOfLine()));
        break;
      case 's': {
        const arg = sc.restOfLine().toLowerCase();
        if (arg === 'off' || arg === '0' || arg === '') this.smooth = FLAT;
        else {
          if (!this.smoothSlot.has(arg)) this.smoothSlot.set(arg, this.smoothSlot.size + 1);
          this.smooth = this.smoothSlot.get(arg)!;
        }
        break;
      }
      case 'usemtl': {
        const name = sc.restOfLine();
        if (!this.materialSlot.has(name)) {
          this.materialSlot.set(name, this.materials.length);
          this.materials.push(name);
        }
        this.material = this.materialSlot.get(name)!;
        break;
      }
      case 'mtllib':
        addUnique(this.mtllibs, this.seenLibs, splitMtllib(sc.restOfLine()));
        break;
      default:
        if (UNSUPPORTED.has(keyword)) this.warnings.addOncePerKeyword(keyword, line, `${shown(keyword)} statements are not supported; ignored`);
        else this.warnings.addOncePerKeyword(keyword.slice(0, 64), line, `unknown statement ${shown(keyword)}; ignored`);
    }
  }
}

/** Whitespace, a line end or the end of the text: what may follow a one- or two-letter keyword. */
function endsKeyword(c: number): boolean {
  return c !== c || c === 32 || c === 9 || c === 10 || c === 13 || c === 11 || c === 12;
}

/** 1-based or negative (relative) OBJ index → 0-based, or −2 when outside 0 .. count − 1. */
function resolve(index: number, count: number): number {
  const i = index > 0 ? index - 1 : count + index;
  return index !== 0 && i >= 0 && i < count ? i : -2;
}

/** The statement just read, shortened, for a message. */
function shownLine(sc: ObjScanner): string {
  return shown(sc.lineBefore().trim());
}
