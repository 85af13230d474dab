// The statement loop: OBJ text → flat lists of vertices, face corners and triangles, with
// faults turned into warnings. Building the drawable mesh is build-mesh.ts's job.
import { F64List, I32List } from './growable';
import { addUnique, splitGroups, splitMtllib } from './names';
import { Scanner } from './scanner';
import { dropZeroArea, MAX_FACE_CORNERS, triangulate } from './triangulate';
import { shown, Warnings } from '../warnings';

/** Smoothing slot of faces under `s off` / `s 0`: flat normals. */
export const FLAT = -1;
/** Smoothing slot before any `s`: files that never say `s` (scans) are meant to be smooth. */
const DEFAULT_SMOOTH = 0;
/** Ints per face record: first corner, corner count, first triangle, triangle count, smoothing slot, material. */
export const FACE_INTS = 6;

/** Statements read and deliberately not drawn, reported once each without "unknown". */
const UNSUPPORTED = new Set(['l', 'p', 'vp', 'curv', 'curv2', 'surf', 'cstype', 'deg', 'bmat', 'step', 'parm',
  'trim', 'hole', 'scrv', 'sp', 'end', 'con', 'mg', 'bevel', 'c_interp', 'd_interp', 'lod', 'usemap', 'maplib',
  'shadow_obj', 'trace_obj', 'ctech', 'stech', 'call', 'csh']);

export interface ObjRaw {
  positions: F64List;
  /** rgb per vertex once any vertex had a colour (earlier ones filled with white), else null. */
  colors: F64List | null;
  uvs: F64List;
  normals: F64List;
  /** Per kept corner: position, uv, normal indices (0-based; −1 when absent). */
  corners: I32List;
  /** Per kept triangle: three global corner numbers. */
  triangles: I32List;
  faces: I32List;
  materials: (string | null)[];
  objects: string[];
  groupNames: string[];
  mtllibs: string[];
  warnings: Warnings;
  droppedFaces: number;
  firstDroppedLine: number;
}

export function readObj(text: string): ObjRaw {
  const sc = new Scanner(text);
  const positions = new F64List();
  let colors: F64List | null = null;
  const uvs = new F64List();
  const normals = new F64List();
  const corners = new I32List();
  const triangles = new I32List();
  const faces = new I32List();
  const face = new I32List(64);
  const warnings = new Warnings();
  // A bad v/vt/vn keeps its slot (so later indices still mean the same element), flagged here.
  const badLine = [new Map<number, number>(), new Map<number, number>(), new Map<number, number>()];
  const materials: (string | null)[] = [null];
  const materialSlot = new Map<string, number>();
  const smoothSlot = new Map<string, number>();
  const objects: string[] = [], groupNames: string[] = [], mtllibs: string[] = [];
  const seenObjects = new Set<string>(), seenGroups = new Set<string>(), seenLibs = new Set<string>();
  let material = 0;
  let smooth = DEFAULT_SMOOTH;
  let droppedFaces = 0;
  let firstDroppedLine = 0;
  const values = new Float64Array(8);

  /** Reads up to 8 numbers to the end of the statement; returns how many, or −1 if one is bad. */
  const readValues = (): number => {
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
  };

  const dropFace = (line: number, message: string): void => {
    warnings.add(line, message);
    if (droppedFaces++ === 0) firstDroppedLine = line;
  };

  while (!sc.atEnd()) {
    sc.skipBlank();
    const line = sc.line;
    if (sc.atStatementEnd()) {
      sc.nextLine();
      continue;
    }
    const c0 = text.charCodeAt(sc.pos);
    const c1 = text.charCodeAt(sc.pos + 1);
    const c1End = endsKeyword(c1);
    const c2 = text.charCodeAt(sc.pos + 2);
    const c2End = endsKeyword(c2);

    if (c0 === 118 /* v */ && c1End) {
      sc.pos += 1;
      const n = readValues();
      const index = positions.length / 3;
      if (n < 3) {
        badLine[0].set(index, line);
        warnings.add(line, n < 0 ? `vertex with a coordinate that is not a number (${shownLine(text, sc)}); faces using it are dropped`
          : `vertex with ${n} of its 3 coordinates; faces using it are dropped`);
        positions.push3(NaN, NaN, NaN);
      } else {
        positions.push3(values[0], values[1], values[2]);
        if (n > 7) warnings.add(line, `vertex with ${n} values; those after x y z r g b ignored`);
      }
      if (n >= 6 && colors === null) {
        colors = new F64List(positions.data.length);
        for (let k = 0; k < index; k++) colors.push3(1, 1, 1);
      }
      if (colors !== null) {
        if (n >= 6) colors.push3(values[3], values[4], values[5]);
        else colors.push3(1, 1, 1);
      }
    } else if (c0 === 118 && c1 === 116 /* vt */ && c2End) {
      sc.pos += 2;
      const n = readValues();
      if (n < 1) {
        badLine[1].set(uvs.length / 2, line);
        warnings.add(line, `texture coordinate that is not a number (${shownLine(text, sc)}); faces using it are dropped`);
        uvs.push(NaN);
        uvs.push(NaN);
      } else {
        uvs.push(values[0]);
        uvs.push(n > 1 ? values[1] : 0);
      }
    } else if (c0 === 118 && c1 === 110 /* vn */ && c2End) {
      sc.pos += 2;
      const n = readValues();
      if (n < 3) {
        badLine[2].set(normals.length / 3, line);
        warnings.add(line, `normal with ${n < 0 ? 'a value that is not a number' : `${n} of its 3 values`}; faces using it are dropped`);
        normals.push3(NaN, NaN, NaN);
      } else {
        normals.push3(values[0], values[1], values[2]);
      }
    } else if (c0 === 102 /* f */ && c1End) {
      sc.pos += 1;
      face.clear();
      let fault = '';
      let cornerCount = 0;
      const vCount = positions.length / 3, tCount = uvs.length / 2, nCount = normals.length / 3;
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
          if (fault === '') fault = `${shown(text.charAt(tokenStart))} is not a face corner`;
        }
        // Past the cap the line is still read to its end (to count it), but nothing is kept.
        if (++cornerCount > MAX_FACE_CORNERS && fault === '') fault = 'too many';
        if (fault !== '') continue;
        const vi = resolve(v, vCount), ti = t === 0 ? -1 : resolve(t, tCount), ni = nn === 0 ? -1 : resolve(nn, nCount);
        if (v !== v || t !== t || nn !== nn) fault = `${shown(text.slice(tokenStart, sc.tokenEnd()))} is not a face corner`;
        else if (vi < 0) fault = `vertex index ${v} is outside the ${vCount} vertices read so far`;
        else if (t !== 0 && ti < 0) fault = `texture coordinate index ${t} is outside the ${tCount} read so far`;
        else if (nn !== 0 && ni < 0) fault = `normal index ${nn} is outside the ${nCount} read so far`;
        else if (badLine[0].size > 0 && badLine[0].has(vi)) fault = `vertex ${vi + 1} (line ${badLine[0].get(vi)}) is not usable`;
        else if (ti >= 0 && badLine[1].size > 0 && badLine[1].has(ti)) fault = `texture coordinate ${ti + 1} (line ${badLine[1].get(ti)}) is not usable`;
        else if (ni >= 0 && badLine[2].size > 0 && badLine[2].has(ni)) fault = `normal ${ni + 1} (line ${badLine[2].get(ni)}) is not usable`;
        else face.push3(vi, ti, ni);
      }
      const count = face.length / 3;
      if (cornerCount > MAX_FACE_CORNERS) dropFace(line, `face of ${cornerCount} vertices, more than the ${MAX_FACE_CORNERS} a face may have; face dropped`);
      else if (fault !== '') dropFace(line, `${fault}; face dropped`);
      else if (count < 3) dropFace(line, `face with ${count} ${count === 1 ? 'vertex' : 'vertices'} (a face needs 3); face dropped`);
      else {
        const start = corners.length / 3;
        for (let k = 0; k < face.length; k++) corners.push(face.data[k]);
        const firstTriangle = triangles.length / 3;
        const clipped = triangulate(positions.data, corners.data, start, count, triangles);
        // A triangle as written is kept as written; what triangulating a polygon makes of zero area is not.
        const kept = count === 3 ? 1 : dropZeroArea(positions.data, corners.data, triangles, firstTriangle);
        if (kept === 0) {
          corners.length = 3 * start;
          dropFace(line, `face of ${count} vertices with no area (its corners are repeated or on one line); face dropped`);
        } else {
          if (!clipped) warnings.add(line, `face of ${count} vertices too large to ear-clip in time; part of it drawn as a fan`);
          faces.push3(start, count, firstTriangle);
          faces.push3(kept, smooth, material);
        }
      }
    } else {
      const keyword = sc.readToken();
      sc.skipBlank();
      switch (keyword) {
        case 'o':
          addUnique(objects, seenObjects, [sc.restOfLine()]);
          break;
        case 'g':
          addUnique(groupNames, seenGroups, splitGroups(sc.restOfLine()));
          break;
        case 's': {
          const arg = sc.restOfLine().toLowerCase();
          if (arg === 'off' || arg === '0' || arg === '') smooth = FLAT;
          else {
            if (!smoothSlot.has(arg)) smoothSlot.set(arg, smoothSlot.size + 1);
            smooth = smoothSlot.get(arg)!;
          }
          break;
        }
        case 'usemtl': {
          const name = sc.restOfLine();
          if (!materialSlot.has(name)) {
            materialSlot.set(name, materials.length);
            materials.push(name);
          }
          material = materialSlot.get(name)!;
          break;
        }
        case 'mtllib':
          addUnique(mtllibs, seenLibs, splitMtllib(sc.restOfLine()));
          break;
        default:
          if (UNSUPPORTED.has(keyword)) warnings.addOncePerKeyword(keyword, line, `${shown(keyword)} statements are not supported; ignored`);
          else warnings.addOncePerKeyword(keyword.slice(0, 64), line, `unknown statement ${shown(keyword)}; ignored`);
      }
    }
    sc.nextLine();
  }

  return {
    positions, colors, uvs, normals, corners, triangles, faces, materials, objects, groupNames, mtllibs,
    warnings, droppedFaces, firstDroppedLine,
  };
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
function shownLine(text: string, sc: Scanner): string {
  let start = sc.pos;
  while (start > 0 && start > sc.pos - 60 && text.charCodeAt(start - 1) !== 10) start--;
  return shown(text.slice(start, sc.pos).trim());
}
