// Raw OBJ lists → indexed triangle mesh: one vertex per distinct (position, uv, normal source)
// corner, generated normals per smoothing group, the index buffer sorted by material.
import { FACE_INTS, type ObjRaw } from './raw';
import type { Bounds, DrawGroup, ObjResult } from './types';

/** Key tag of a corner whose normal is generated smooth (`k` = smoothing slot)… */
const SMOOTH = -1;
/** …or flat (`k` = face number, so no other face shares the vertex). */
const FLAT_FACE = -2;

export function buildMesh(raw: ObjRaw): Omit<ObjResult, 'warnings'> {
  const welded = weldCorners(raw);
  const { positions, normals, uvs, colors, bounds } = vertexArrays(raw, welded);
  const { indices, groups } = indexByMaterial(raw, welded.cornerOut, welded.count);
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
  /** Per corner of the file: its output vertex. */
  cornerOut: Int32Array;
  /** REC ints per output vertex. */
  rec: Int32Array;
  /** Generated normals, summed area-weighted over the faces that share them (xyz per vertex). */
  acc: Float64Array;
}

/**
 * One output vertex per distinct (position, uv, normal source) corner; a generated normal is
 * shared by the corners of one position in one smoothing group (whatever their uv) and sums the
 * Newell normals of their faces.
 */
function weldCorners(raw: ObjRaw): Welded {
  const corners = raw.corners.data;
  const uvOf = raw.cornerUvs?.data ?? null, normalOf = raw.cornerNormals?.data ?? null;
  const faces = raw.faces.data;
  const faceCount = raw.faces.length / FACE_INTS;
  const cornerOut = new Int32Array(raw.corners.length);
  // Vertices sharing a position are chained from head[position]; chains are a few long.
  const head = new Int32Array(raw.positions.length / 3).fill(-1);
  // Most models have about one output vertex per position: room for that, doubled if need be.
  let rec = new Int32Array(REC * Math.max(64, raw.positions.length / 3));
  let acc = new Float64Array(rec.length / 2);
  const normal = new Float64Array(3);
  let outCount = 0;

  for (let f = 0; f < faceCount; f++) {
    const first = faces[f * FACE_INTS], count = faces[f * FACE_INTS + 1], smooth = faces[f * FACE_INTS + 4];
    newellNormal(raw.positions.data, corners, first, count, normal);
    for (let k = 0; k < count; k++) {
      const c = first + k;
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
        const r = REC * o;
        if (rec[r + N] === n && rec[r + K] === key) {
          if (rec[r + T] === t) break;
          if (shared < 0) shared = rec[r + REP];
        }
        o = rec[r + CHAIN];
      }
      if (o < 0) {
        if (REC * outCount === rec.length) {
          rec = doubled(rec);
          const more = new Float64Array(2 * acc.length);
          more.set(acc);
          acc = more;
        }
        o = outCount++;
        const r = REC * o;
        rec[r + V] = v;
        rec[r + T] = t;
        rec[r + N] = n;
        rec[r + K] = key;
        rec[r + CHAIN] = head[v];
        rec[r + REP] = shared >= 0 ? shared : o;
        head[v] = o;
      }
      cornerOut[c] = o;
      if (n < 0) {
        const a = 3 * rec[REC * o + REP];
        acc[a] += normal[0];
        acc[a + 1] += normal[1];
        acc[a + 2] += normal[2];
      }
    }
  }
  return { count: outCount, cornerOut, rec, acc };
}

function doubled(a: Int32Array<ArrayBuffer>): Int32Array<ArrayBuffer> {
  const b = new Int32Array(2 * a.length);
  b.set(a);
  return b;
}

/** Newell normal of the face of `count` corners from `first`, length twice its area: summing it weights faces by area. */
function newellNormal(pos: Float64Array, corners: Int32Array, first: number, count: number, out: Float64Array): void {
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
}

/** The output vertices' arrays (uvs only if some corner has one, colours if the file gave any) and their bounds. */
function vertexArrays(raw: ObjRaw, w: Welded): Pick<ObjResult, 'positions' | 'normals' | 'uvs' | 'colors' | 'bounds'> {
  const pos = raw.positions.data;
  const outCount = w.count;
  const positions = new Float32Array(outCount * 3);
  const normals = new Float32Array(outCount * 3);
  let hasUv = false;
  for (let o = 0; o < outCount && !hasUv; o++) hasUv = w.rec[REC * o + T] >= 0;
  const uvs = hasUv ? new Float32Array(outCount * 2) : null;
  const colors = raw.colors ? new Float32Array(outCount * 3) : null;
  const min: [number, number, number] = [Infinity, Infinity, Infinity];
  const max: [number, number, number] = [-Infinity, -Infinity, -Infinity];
  for (let o = 0; o < outCount; o++) {
    const p = 3 * w.rec[REC * o + V];
    for (let a = 0; a < 3; a++) {
      const x = pos[p + a];
      positions[3 * o + a] = x;
      if (x < min[a]) min[a] = x;
      if (x > max[a]) max[a] = x;
    }
    const n = w.rec[REC * o + N];
    if (n >= 0) writeUnit(normals, o, raw.normals.data, 3 * n);
    else writeUnit(normals, o, w.acc, 3 * w.rec[REC * o + REP]);
    if (uvs) {
      const t = w.rec[REC * o + T];
      if (t >= 0) {
        uvs[2 * o] = raw.uvs.data[2 * t];
        uvs[2 * o + 1] = raw.uvs.data[2 * t + 1];
      }
    }
    if (colors && raw.colors) colors.set(raw.colors.data.subarray(p, p + 3), 3 * o);
  }
  const bounds: Bounds = { min, max };
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

/** The index buffer with each material's triangles contiguous (file order within one). */
function indexByMaterial(raw: ObjRaw, cornerOut: Int32Array, outCount: number): { indices: Uint16Array | Uint32Array; groups: DrawGroup[] } {
  const faces = raw.faces.data;
  const faceCount = raw.faces.length / FACE_INTS;
  let triangleCount = 0;
  const materialCount = raw.materials.length;
  const perMaterial = new Int32Array(materialCount);
  const order: number[] = [];
  for (let f = 0; f < faceCount; f++) {
    const m = faces[f * FACE_INTS + 5];
    if (perMaterial[m] === 0) order.push(m);
    perMaterial[m] += faces[f * FACE_INTS + 3];
    triangleCount += faces[f * FACE_INTS + 3];
  }
  const offset = new Int32Array(materialCount);
  const groups: DrawGroup[] = [];
  let at = 0;
  for (const m of order) {
    offset[m] = at;
    groups.push({ material: raw.materials[m], start: 3 * at, count: 3 * perMaterial[m] });
    at += perMaterial[m];
  }
  const indices = outCount > 65535 ? new Uint32Array(3 * triangleCount) : new Uint16Array(3 * triangleCount);
  const tris = raw.triangles.data;
  for (let f = 0; f < faceCount; f++) {
    const m = faces[f * FACE_INTS + 5];
    const firstTriangle = faces[f * FACE_INTS + 2];
    const n = faces[f * FACE_INTS + 3];
    let w = 3 * offset[m];
    if (firstTriangle < 0) { // a triangle as written: its corners
      const c = faces[f * FACE_INTS];
      indices[w] = cornerOut[c];
      indices[w + 1] = cornerOut[c + 1];
      indices[w + 2] = cornerOut[c + 2];
    } else {
      for (let t = 3 * firstTriangle; t < 3 * (firstTriangle + n); t++) indices[w++] = cornerOut[tris[t]];
    }
    offset[m] += n;
  }
  return { indices, groups };
}
