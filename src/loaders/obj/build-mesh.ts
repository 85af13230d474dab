// Raw OBJ lists → indexed triangle mesh: one vertex per distinct (position, uv, normal source)
// corner, generated normals per smoothing group, the index buffer sorted by material.
import { RUN_INTS, type ObjRaw } from './raw';
import type { Bounds, DrawGroup, ObjResult } from './types';

/** Key tag of a corner whose normal is generated smooth (`k` = smoothing slot)… */
const SMOOTH = -1;
/** …or flat (`k` = face number, so no other face shares the vertex). */
const FLAT_FACE = -2;

/** `byPosition`: a file of one smoothing group with neither uvs nor normals welds by position alone (tests turn it off to compare). */
export function buildMesh(raw: ObjRaw, byPosition = true): Omit<ObjResult, 'warnings'> {
  const welded = weldCorners(raw, byPosition);
  const { positions, normals, uvs, colors, bounds } = vertexArrays(raw, welded);
  const { indices, groups } = indexByMaterial(raw, welded);
  return {
    positions, normals, uvs, colors, indices, groups, bounds,
    mtllibs: raw.mtllibs, objects: raw.objects, groupNames: raw.groupNames,
  };
}

/**
 * Ints per output vertex record while welding: position, uv and normal index (a negative
 * normal: generated, SMOOTH or FLAT_FACE), key, the next vertex of the same position, and the
 * vertex whose entry of `acc` holds its generated normal. One record, not six arrays: a corner
 * looks at all of a vertex's fields, and they share a cache line.
 */
const REC = 6;
const V = 0, T = 1, N = 2, K = 3, CHAIN = 4, REP = 5;

/** The output vertices: one per distinct corner, with where each comes from. */
interface Welded {
  count: number;
  /** The triangles' output vertices, in file order (3 per triangle). */
  fileOrder: Uint32Array;
  /** Per run of raw.runs: where its triangles start in `fileOrder`, and one entry more: the end. */
  runStart: Int32Array;
  /** REC ints per output vertex; null from weldPositions, whose vertices need only `positionOf`. */
  rec: Int32Array<ArrayBuffer> | null;
  /** weldPositions's output vertices' positions (each its own generated normal in `acc`), else null. */
  positionOf: Int32Array | null;
  /** Generated normals, summed area-weighted over the faces that share them (xyz per vertex). */
  acc: Float64Array<ArrayBuffer>;
}

/** Output vertices of the polygon being welded, by corner (then mapped through its triangles). */
let polygonOut = new Int32Array(64);

/** What both welds start from: the output arrays, and room for about one vertex a position (in `rec` if `records`). */
function weldStart(raw: ObjRaw, records: boolean): Welded {
  const room = Math.max(64, raw.positions.length / 3);
  return {
    count: 0,
    fileOrder: new Uint32Array(3 * raw.triangleCount),
    runStart: new Int32Array(raw.runs.length / RUN_INTS + 1),
    rec: records ? new Int32Array(REC * room) : null,
    positionOf: records ? null : new Int32Array(room),
    acc: new Float64Array(3 * room),
  };
}

/**
 * One output vertex per distinct (position, uv, normal source) corner; a generated normal is
 * shared by the corners of one position in one smoothing group (whatever their uv) and sums the
 * Newell normals of their faces. The triangles' vertices are written as the faces are welded.
 */
function weldCorners(raw: ObjRaw, byPosition: boolean): Welded {
  const uvOf = raw.cornerUvs?.data ?? null, normalOf = raw.cornerNormals?.data ?? null;
  const runs = raw.runs.data, runCount = raw.runs.length / RUN_INTS;
  let oneGroup = byPosition && uvOf === null && normalOf === null && runs[1] >= 0;
  for (let r = 1; r < runCount && oneGroup; r++) oneGroup = runs[r * RUN_INTS + 1] === runs[1];
  if (oneGroup) return weldPositions(raw);
  const corners = raw.corners.data, pos = raw.positions.data, faces = raw.faces.data;
  const welded = weldStart(raw, true);
  const { fileOrder, runStart } = welded;
  let rec = welded.rec!, acc = welded.acc;
  // Vertices sharing a position are chained from head[position]; chains are a few long.
  const head = new Int32Array(raw.positions.length / 3).fill(-1);
  const normal = new Float64Array(3);
  let outCount = 0;
  let at = 0, c = 0, f = 0, w = 0, tri = 0; // in faces, corners, face numbers, fileOrder, raw.triangles
  for (let r = 0; r < runCount; r++) {
    runStart[r] = w;
    const smooth = runs[r * RUN_INTS + 1];
    const end = r + 1 < runCount ? runs[(r + 1) * RUN_INTS] : raw.faceCount;
    for (; f < end; f++) {
      const count = faces[at++];
      if (count > polygonOut.length) polygonOut = new Int32Array(Math.max(count, 2 * polygonOut.length));
      let haveNormal = false; // the face's Newell normal, once a corner needs it
      for (let k = 0; k < count; k++, c++) {
        const v = corners[c], t = uvOf ? uvOf[c] : -1;
        let n = normalOf ? normalOf[c] : -1;
        let key = 0;
        if (n < 0) {
          key = smooth >= 0 ? smooth : f;
          n = smooth >= 0 ? SMOOTH : FLAT_FACE;
        }
        let o = head[v];
        let shared = -1; // a vertex of the same position and smoothing group, maybe another uv
        while (o >= 0) {
          const q = REC * o;
          if (rec[q + N] === n && rec[q + K] === key) {
            if (rec[q + T] === t) break;
            if (shared < 0) shared = rec[q + REP];
          }
          o = rec[q + CHAIN];
        }
        if (o < 0) {
          if (REC * outCount === rec.length) {
            rec = doubled(rec);
            const more = new Float64Array(2 * acc.length);
            more.set(acc);
            acc = more;
          }
          o = outCount++;
          const q = REC * o;
          rec[q + V] = v;
          rec[q + T] = t;
          rec[q + N] = n;
          rec[q + K] = key;
          rec[q + CHAIN] = head[v];
          rec[q + REP] = shared >= 0 ? shared : o;
          head[v] = o;
        }
        if (count === 3) fileOrder[w++] = o;
        else polygonOut[k] = o;
        if (n < 0) {
          if (!haveNormal) haveNormal = newellNormal(pos, corners, c - k, count, normal);
          const a = 3 * rec[REC * o + REP];
          acc[a] += normal[0];
          acc[a + 1] += normal[1];
          acc[a + 2] += normal[2];
        }
      }
      if (count > 3) {
        w = polygonTriangles(raw.triangles.data, tri, faces[at], c - count, fileOrder, w);
        tri += faces[at++];
      }
    }
  }
  runStart[runCount] = w;
  return { count: outCount, fileOrder, runStart, rec, positionOf: null, acc };
}

/**
 * weldCorners for a file of one smoothing group with neither uvs nor normals (a scan, most
 * often): one output vertex per position used, in order of first use, each its own normal.
 */
function weldPositions(raw: ObjRaw): Welded {
  const corners = raw.corners.data, pos = raw.positions.data, faces = raw.faces.data;
  const runs = raw.runs.data, runCount = raw.runs.length / RUN_INTS;
  const welded = weldStart(raw, false);
  const { fileOrder, runStart, acc } = welded;
  const positionOf = welded.positionOf!;
  const out = new Int32Array(raw.positions.length / 3).fill(-1); // per position: its output vertex
  const normal = new Float64Array(3);
  let outCount = 0;
  let at = 0, c = 0, f = 0, w = 0, tri = 0;
  for (let r = 0; r < runCount; r++) {
    runStart[r] = w;
    const end = r + 1 < runCount ? runs[(r + 1) * RUN_INTS] : raw.faceCount;
    for (; f < end; f++) {
      const count = faces[at++];
      if (count > polygonOut.length) polygonOut = new Int32Array(Math.max(count, 2 * polygonOut.length));
      newellNormal(pos, corners, c, count, normal);
      const nx = normal[0], ny = normal[1], nz = normal[2];
      for (let k = 0; k < count; k++, c++) {
        const v = corners[c];
        let o = out[v];
        if (o < 0) {
          o = out[v] = outCount++;
          positionOf[o] = v;
        }
        if (count === 3) fileOrder[w++] = o;
        else polygonOut[k] = o;
        acc[3 * o] += nx;
        acc[3 * o + 1] += ny;
        acc[3 * o + 2] += nz;
      }
      if (count > 3) {
        w = polygonTriangles(raw.triangles.data, tri, faces[at], c - count, fileOrder, w);
        tri += faces[at++];
      }
    }
  }
  runStart[runCount] = w;
  welded.count = outCount;
  return welded;
}

/** A polygon's `kept` triangles from triangle `tri` of `tris` (corner numbers from `first`) onto fileOrder at `w`, through polygonOut; returns the next w. */
function polygonTriangles(tris: Int32Array, tri: number, kept: number, first: number, fileOrder: Uint32Array, w: number): number {
  for (let t = 3 * tri; t < 3 * (tri + kept); t++) fileOrder[w++] = polygonOut[tris[t] - first];
  return w;
}

function doubled(a: Int32Array<ArrayBuffer>): Int32Array<ArrayBuffer> {
  const b = new Int32Array(2 * a.length);
  b.set(a);
  return b;
}

/** Newell normal of the face of `count` corners from `first`, length twice its area: summing it weights faces by area. */
export function newellNormal(pos: Float64Array, corners: Int32Array, first: number, count: number, out: Float64Array): true {
  if (count === 3) return triangleNormal(pos, 3 * corners[first], 3 * corners[first + 1], 3 * corners[first + 2], out);
  let nx = 0, ny = 0, nz = 0;
  let j = 3 * corners[first + count - 1];
  for (let k = 0; k < count; k++) {
    const i = 3 * corners[first + k];
    nx += (pos[j + 1] - pos[i + 1]) * (pos[j + 2] + pos[i + 2]);
    ny += (pos[j + 2] - pos[i + 2]) * (pos[j] + pos[i]);
    nz += (pos[j] - pos[i]) * (pos[j + 1] + pos[i + 1]);
    j = i;
  }
  out[0] = nx; out[1] = ny; out[2] = nz;
  return true;
}

/**
 * newellNormal of the triangle of positions `a`, `b`, `c` (offsets in `pos`): the same terms
 * summed in the same order (edge c→a, a→b, b→c, from 0), so the same bits, each coordinate read once.
 */
function triangleNormal(pos: Float64Array, a: number, b: number, c: number, out: Float64Array): true {
  const ax = pos[a], ay = pos[a + 1], az = pos[a + 2];
  const bx = pos[b], by = pos[b + 1], bz = pos[b + 2];
  const cx = pos[c], cy = pos[c + 1], cz = pos[c + 2];
  out[0] = 0 + (cy - ay) * (cz + az) + (ay - by) * (az + bz) + (by - cy) * (bz + cz);
  out[1] = 0 + (cz - az) * (cx + ax) + (az - bz) * (ax + bx) + (bz - cz) * (bx + cx);
  out[2] = 0 + (cx - ax) * (cy + ay) + (ax - bx) * (ay + by) + (bx - cx) * (by + cy);
  return true;
}

/** The output vertices' arrays (uvs only if some corner has one, colours if the file gave any) and their bounds. */
function vertexArrays(raw: ObjRaw, w: Welded): Pick<ObjResult, 'positions' | 'normals' | 'uvs' | 'colors' | 'bounds'> {
  const pos = raw.positions.data, fileNormals = raw.normals.data, fileUvs = raw.uvs.data, fileColors = raw.colors?.data ?? null;
  const { rec, positionOf, acc, count: outCount } = w;
  const positions = new Float32Array(outCount * 3);
  const normals = new Float32Array(outCount * 3);
  let hasUv = false;
  for (let o = 0; rec && o < outCount && !hasUv; o++) hasUv = rec[REC * o + T] >= 0;
  const uvs = hasUv ? new Float32Array(outCount * 2) : null;
  const colors = fileColors ? new Float32Array(outCount * 3) : null;
  let minX = Infinity, minY = Infinity, minZ = Infinity, maxX = -Infinity, maxY = -Infinity, maxZ = -Infinity;
  for (let o = 0; o < outCount; o++) {
    const q = REC * o, p = 3 * (rec ? rec[q + V] : positionOf![o]);
    const x = pos[p], y = pos[p + 1], z = pos[p + 2];
    positions[3 * o] = x;
    positions[3 * o + 1] = y;
    positions[3 * o + 2] = z;
    if (x < minX) minX = x;
    if (x > maxX) maxX = x;
    if (y < minY) minY = y;
    if (y > maxY) maxY = y;
    if (z < minZ) minZ = z;
    if (z > maxZ) maxZ = z;
    const n = rec ? rec[q + N] : SMOOTH;
    if (n >= 0) writeUnit(normals, o, fileNormals, 3 * n);
    else writeUnit(normals, o, acc, 3 * (rec ? rec[q + REP] : o));
    if (uvs && rec) {
      const t = rec[q + T];
      if (t >= 0) {
        uvs[2 * o] = fileUvs[2 * t];
        uvs[2 * o + 1] = fileUvs[2 * t + 1];
      }
    }
    if (colors && fileColors) {
      colors[3 * o] = fileColors[p];
      colors[3 * o + 1] = fileColors[p + 1];
      colors[3 * o + 2] = fileColors[p + 2];
    }
  }
  const bounds: Bounds = { min: [minX, minY, minZ], max: [maxX, maxY, maxZ] };
  return { positions, normals, uvs, colors, bounds };
}

/** Unit vector of src[s..s+2] into normals[o]; +z for a zero vector (a degenerate face). */
function writeUnit(normals: Float32Array, o: number, src: Float64Array, s: number): void {
  const x = src[s], y = src[s + 1], z = src[s + 2];
  const length = Math.sqrt(x * x + y * y + z * z);
  if (length > 0 && Number.isFinite(length)) {
    // `+ 0` turns −0 into 0, so equal normals are equal bit for bit.
    normals[3 * o] = x / length + 0;
    normals[3 * o + 1] = y / length + 0;
    normals[3 * o + 2] = z / length + 0;
  } else {
    normals[3 * o + 2] = 1;
  }
}

/**
 * The index buffer with each material's triangles contiguous (file order within one), in the
 * order of the materials' first use: the welded file order itself when no material comes back
 * after another, else its runs copied to their material's place.
 */
function indexByMaterial(raw: ObjRaw, w: Welded): { indices: Uint16Array | Uint32Array; groups: DrawGroup[] } {
  const runs = raw.runs.data, runCount = raw.runs.length / RUN_INTS;
  const { fileOrder, runStart } = w;
  const perMaterial = new Int32Array(raw.materials.length);
  const order: number[] = [];
  let inOrder = true;
  for (let r = 0; r < runCount; r++) {
    const m = runs[r * RUN_INTS + 2];
    if (perMaterial[m] === 0) order.push(m);
    else if (m !== runs[(r - 1) * RUN_INTS + 2]) inOrder = false; // back to an earlier material
    perMaterial[m] += runStart[r + 1] - runStart[r];
  }
  const offset = new Int32Array(raw.materials.length);
  const groups: DrawGroup[] = [];
  let at = 0;
  for (const m of order) {
    offset[m] = at;
    groups.push({ material: raw.materials[m], start: at, count: perMaterial[m] });
    at += perMaterial[m];
  }
  const wide = w.count > 65535;
  if (inOrder && wide) return { indices: fileOrder, groups };
  // One copy, straight into the final type: in file order, or each run moved to its material's group.
  const indices = wide ? new Uint32Array(fileOrder.length) : new Uint16Array(fileOrder.length);
  if (inOrder) indices.set(fileOrder);
  else {
    for (let r = 0; r < runCount; r++) {
      const m = runs[r * RUN_INTS + 2];
      indices.set(fileOrder.subarray(runStart[r], runStart[r + 1]), offset[m]);
      offset[m] += runStart[r + 1] - runStart[r];
    }
  }
  return { indices, groups };
}
