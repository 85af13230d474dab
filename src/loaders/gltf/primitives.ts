// One glTF primitive placed in the model (docs/gltf.md#primitives): its attributes read, its
// triangles listed (triangles, strips and fans; points and lines left out with a warning), its
// positions and normals taken through the node's world matrix, flat normals where the file has
// none (as the glTF specification asks), and triangles with a non-finite or absurd position dropped.
import { FLOAT, SHORT, BYTE, UNSIGNED_BYTE, UNSIGNED_SHORT, readAccessor, readIndices, type Expect } from './accessors';
import { GltfFile, int, object, type Obj } from './fields';
import type { MeshInstance } from './nodes';
import { computeTangents } from './tangents';

/** A primitive in model space: per-vertex arrays and triangles (3 indices each). */
export interface Piece {
  positions: Float32Array;
  normals: Float32Array;
  uv0: Float32Array | null;
  uv1: Float32Array | null;
  /** RGBA per vertex (COLOR_0; RGB gets alpha 1). */
  colors: Float32Array | null;
  indices: Uint32Array;
  /** materials[i], or null for the default material. */
  material: number | null;
  /** xyzw per vertex where the material has a normal map (the file's, else computed: tangents.ts), else null. */
  tangents: Float32Array | null;
}

/** Coordinates beyond this (after the node's matrix) are a corrupt file, not a model: their triangles are dropped. */
export const MAX_COORDINATE = 1e15;

const POSITION: Expect = { types: ['VEC3'], components: [FLOAT, BYTE, UNSIGNED_BYTE, SHORT, UNSIGNED_SHORT] };
const NORMAL: Expect = { types: ['VEC3'], components: [FLOAT, BYTE, SHORT] };
const TEXCOORD: Expect = { types: ['VEC2'], components: [FLOAT, BYTE, UNSIGNED_BYTE, SHORT, UNSIGNED_SHORT] };
const COLOR: Expect = { types: ['VEC3', 'VEC4'], components: [FLOAT, UNSIGNED_BYTE, UNSIGNED_SHORT] };
const TANGENT: Expect = { types: ['VEC4'], components: [FLOAT, BYTE, SHORT] };

const TRIANGLES = 4, TRIANGLE_STRIP = 5, TRIANGLE_FAN = 6;

/** The POSITION count of a primitive, read without reading the data (for the budget). */
export function positionCount(file: GltfFile, p: Obj, path: string): number {
  const attributes = object(file, p.attributes, `${path}.attributes`);
  if (attributes.POSITION === undefined) return 0;
  const a = file.item('accessors', int(file, attributes, 'POSITION', `${path}.attributes`), `${path}.attributes.POSITION`);
  return int(file, a, 'count', `accessors[${attributes.POSITION as number}]`);
}

export function readPiece(file: GltfFile, buffers: readonly Uint8Array[], p: Obj, path: string, at: MeshInstance): Piece | null {
  const mode = int(file, p, 'mode', path, TRIANGLES);
  if (mode < TRIANGLES) {
    file.warn(`${path}.mode`, 'points and lines are not drawn (the first named; any others too)');
    return null;
  }
  if (mode > TRIANGLE_FAN) file.fail(`${path}.mode`, `${path}.mode is ${mode}, not a glTF primitive mode`);
  const attrs = object(file, p.attributes, `${path}.attributes`);
  if (attrs.POSITION === undefined) {
    file.warn(`${path}.attributes`, `${path} has no POSITION: not drawn`);
    return null;
  }
  const attribute = (name: string, expect: Expect) => attrs[name] === undefined ? null
    : readAccessor(file, buffers, int(file, attrs, name, `${path}.attributes`), `${path}.attributes.${name}`, expect);
  const position = attribute('POSITION', POSITION)!;
  const n = position.count;
  const same = (name: string, expect: Expect) => {
    const a = attribute(name, expect);
    if (a && a.count !== n) file.fail(`${path}.attributes.${name}`, `${path}.attributes.${name} has ${a.count} elements, POSITION has ${n}`);
    return a;
  };
  const normal = same('NORMAL', NORMAL);
  const uv0 = same('TEXCOORD_0', TEXCOORD);
  const uv1 = same('TEXCOORD_1', TEXCOORD);
  const color = same('COLOR_0', COLOR);
  const listed = p.indices === undefined ? null : readIndices(file, buffers, int(file, p, 'indices', path), `${path}.indices`, n);
  let indices = triangles(mode, listed, n);
  const identity = isIdentity(at.matrix);
  const positions = identity ? position.values : transformPoints(position.values, at.matrix);
  indices = dropBad(file, positions, indices, `${path}.attributes.POSITION`);
  // Stryker disable next-line EqualityOperator: one step more swaps two slots past the end, which a typed array ignores
  if (det3(at.matrix) < 0) for (let t = 0; t < indices.length; t += 3) [indices[t + 1], indices[t + 2]] = [indices[t + 2], indices[t + 1]];
  const material = p.material === undefined ? null : int(file, p, 'material', path);
  if (material !== null) file.item('materials', material, `${path}.material`);
  const colors = color ? rgba(color.values, color.size) : null;
  const piece: Piece = { positions, normals: new Float32Array(0), uv0: uv0?.values ?? null, uv1: uv1?.values ?? null, colors, indices, material, tangents: null };
  const shaded = normal ? { ...piece, normals: transformNormals(normal.values, at.matrix, identity) } : flatShaded(piece);
  const mapUv = normalMapUv(file, material);
  if (mapUv !== null) {
    const given = normal ? same('TANGENT', TANGENT) : null;
    const uvs = mapUv === 0 ? shaded.uv0 : shaded.uv1;
    if (given) shaded.tangents = transformTangents(given.values, at.matrix);
    else if (uvs) shaded.tangents = computeTangents(shaded.positions, shaded.normals, uvs, shaded.indices);
  }
  return shaded;
}

/** The UV set a material's normal map reads, or null when it has none. */
function normalMapUv(file: GltfFile, material: number | null): number | null {
  if (material === null) return null;
  // Stryker disable next-line StringLiteral: readPiece has refused a material past the list by then, with its own path
  const m = file.item('materials', material, `materials[${material}]`);
  if (m.normalTexture === undefined) return null;
  return int(file, object(file, m.normalTexture, `materials[${material}].normalTexture`), 'texCoord', `materials[${material}].normalTexture`, 0);
}

/** The file's tangents through the matrix's 3×3 part, unit; w turned where the matrix mirrors. */
function transformTangents(v: Float32Array, m: Float64Array): Float32Array {
  const out = new Float32Array(v.length), mirror = det3(m) < 0 ? -1 : 1;
  // Stryker disable next-line EqualityOperator: one step more writes past the end of out, which a typed array ignores
  for (let i = 0; i < v.length; i += 4) {
    const x = m[0] * v[i] + m[4] * v[i + 1] + m[8] * v[i + 2];
    const y = m[1] * v[i] + m[5] * v[i + 1] + m[9] * v[i + 2];
    const z = m[2] * v[i] + m[6] * v[i + 1] + m[10] * v[i + 2];
    const len = Math.sqrt(x * x + y * y + z * z) || 1;
    out[i] = x / len; out[i + 1] = y / len; out[i + 2] = z / len;
    const w = v[i + 3] < 0 ? -1 : 1;
    // Stryker disable next-line ArithmeticOperator: mirror is 1 or −1, for which w / mirror = w * mirror
    out[i + 3] = w * mirror;
  }
  return out;
}

/** The triangle list of a primitive's vertex order (glTF's strip and fan rules). */
export function triangles(mode: number, listed: Uint32Array | null, vertexCount: number): Uint32Array {
  const order = listed ?? Uint32Array.from({ length: vertexCount }, (_, i) => i);
  const m = order.length;
  if (mode === TRIANGLES) {
    const whole = m - (m % 3);
    // Stryker disable next-line ConditionalExpression,EqualityOperator: slicing a whole list gives the same triangles, copied
    return whole === m ? order : order.slice(0, whole);
  }
  const count = Math.max(0, m - 2);
  const out = new Uint32Array(3 * count);
  // Stryker disable next-line EqualityOperator: one step more writes past the end of out, which a typed array ignores
  for (let i = 0; i < count; i++) {
    if (mode === TRIANGLE_STRIP) {
      out[3 * i] = order[i];
      out[3 * i + 1] = order[i + 1 + (i % 2)];
      out[3 * i + 2] = order[i + 2 - (i % 2)];
    } else {
      out[3 * i] = order[i + 1];
      out[3 * i + 1] = order[i + 2];
      out[3 * i + 2] = order[0];
    }
  }
  return out;
}

// Stryker disable next-line BlockStatement: a fast path only; the general path gives the same values under the identity
function isIdentity(m: Float64Array): boolean {
  // Stryker disable next-line all: a fast path only; the general path gives the same values under the identity (its cofactors are itself)
  for (let i = 0; i < 16; i++) if (m[i] !== (i % 5 === 0 ? 1 : 0)) return false;
  // Stryker disable next-line BooleanLiteral: a fast path only (see above)
  return true;
}

function transformPoints(v: Float32Array, m: Float64Array): Float32Array {
  const out = new Float32Array(v.length);
  // Stryker disable next-line EqualityOperator: one step more writes past the end of out, which a typed array ignores
  for (let i = 0; i < v.length; i += 3) {
    const x = v[i], y = v[i + 1], z = v[i + 2];
    out[i] = m[0] * x + m[4] * y + m[8] * z + m[12];
    out[i + 1] = m[1] * x + m[5] * y + m[9] * z + m[13];
    out[i + 2] = m[2] * x + m[6] * y + m[10] * z + m[14];
  }
  return out;
}

function det3(m: Float64Array): number {
  return m[0] * (m[5] * m[10] - m[6] * m[9]) - m[4] * (m[1] * m[10] - m[2] * m[9]) + m[8] * (m[1] * m[6] - m[2] * m[5]);
}

/**
 * Normals through the inverse transpose of the matrix's 3×3 part (its cofactors, signed by its
 * determinant), unit length; under the identity, the file's normals made unit in place.
 */
function transformNormals(v: Float32Array, m: Float64Array, identity: boolean): Float32Array {
  // Stryker disable next-line ConditionalExpression,BlockStatement: the general path gives the same values under the identity (its cofactors are itself)
  if (identity) {
    // Stryker disable next-line EqualityOperator: one step more reads and writes v[length], which a typed array ignores
    for (let i = 0; i < v.length; i += 3) {
      const len = Math.sqrt(v[i] * v[i] + v[i + 1] * v[i + 1] + v[i + 2] * v[i + 2]);
      const k = len > 0 ? 1 / len : 0;
      v[i] *= k;
      v[i + 1] *= k;
      v[i + 2] *= k;
    }
    return v;
  }
  const s = Math.sign(det3(m)) || 1;
  const cofactors = [
    m[5] * m[10] - m[6] * m[9], m[6] * m[8] - m[4] * m[10], m[4] * m[9] - m[5] * m[8],
    m[2] * m[9] - m[1] * m[10], m[0] * m[10] - m[2] * m[8], m[1] * m[8] - m[0] * m[9],
    m[1] * m[6] - m[2] * m[5], m[2] * m[4] - m[0] * m[6], m[0] * m[5] - m[1] * m[4],
  ];
  // Stryker disable next-line ArithmeticOperator: s is 1 or −1, for which x / s = x * s
  const c = cofactors.map((x) => x * s);
  const out = new Float32Array(v.length);
  // Stryker disable next-line EqualityOperator: one step more writes past the end of out, which a typed array ignores
  for (let i = 0; i < v.length; i += 3) {
    const x = v[i], y = v[i + 1], z = v[i + 2];
    const nx = c[0] * x + c[3] * y + c[6] * z, ny = c[1] * x + c[4] * y + c[7] * z, nz = c[2] * x + c[5] * y + c[8] * z;
    const len = Math.sqrt(nx * nx + ny * ny + nz * nz);
    // A zero normal stays zero: the renderers light it as facing nowhere rather than dividing by 0.
    const k = len > 0 ? 1 / len : 0;
    out[i] = nx * k;
    out[i + 1] = ny * k;
    out[i + 2] = nz * k;
  }
  return out;
}

/** Triangles whose three positions are finite and within MAX_COORDINATE; one warning if any is not. */
function dropBad(file: GltfFile, p: Float32Array, indices: Uint32Array, path: string): Uint32Array {
  // Stryker disable next-line BooleanLiteral: a fast path only: the triangle by triangle check below returns the same indices when all are in range
  let all = true;
  // Stryker disable next-line all: a fast path only (see above); no float32 is exactly 1e15, so < and <= agree
  for (let i = 0; i < p.length && all; i++) all = Math.abs(p[i]) <= MAX_COORDINATE;
  // Stryker disable next-line ConditionalExpression: a fast path only (see above)
  if (all) return indices;
  const good = (i: number) => {
    // Stryker disable next-line EqualityOperator: no float32 is exactly 1e15 (MAX_COORDINATE), so < and <= agree
    for (let a = 3 * i; a < 3 * i + 3; a++) if (!(Math.abs(p[a]) <= MAX_COORDINATE)) return false;
    return true;
  };
  let kept = 0;
  const out = new Uint32Array(indices.length);
  for (let t = 0; t < indices.length; t += 3) {
    if (good(indices[t]) && good(indices[t + 1]) && good(indices[t + 2])) {
      out[kept++] = indices[t];
      out[kept++] = indices[t + 1];
      out[kept++] = indices[t + 2];
    }
  }
  if (kept === indices.length) return indices;
  file.warn(path, `${(indices.length - kept) / 3} triangles with a position not finite or beyond ±${MAX_COORDINATE} are not drawn (${path})`);
  return out.slice(0, kept);
}

function rgba(v: Float32Array, size: number): Float32Array {
  if (size === 4) return v;
  const out = new Float32Array((v.length / 3) * 4);
  // Stryker disable next-line EqualityOperator: one step more writes past the end of out, which a typed array ignores
  for (let i = 0, o = 0; i < v.length; i += 3, o += 4) {
    out[o] = v[i];
    out[o + 1] = v[i + 1];
    out[o + 2] = v[i + 2];
    out[o + 3] = 1;
  }
  return out;
}

/** Every triangle its own three vertices, each with the triangle's normal (a degenerate one: 0). */
function flatShaded(p: Piece): Piece {
  const t = p.indices;
  const expand = (a: Float32Array | null, size: number) => {
    if (!a) return null;
    const out = new Float32Array(t.length * size);
    // Stryker disable next-line EqualityOperator: one step more sets an empty subarray (t[length] is undefined) at the end
    for (let i = 0; i < t.length; i++) out.set(a.subarray(t[i] * size, t[i] * size + size), i * size);
    return out;
  };
  const positions = expand(p.positions, 3)!;
  const normals = new Float32Array(positions.length);
  // Stryker disable next-line EqualityOperator: one step more writes past the end of normals, which a typed array ignores
  for (let i = 0; i < positions.length; i += 9) {
    const ux = positions[i + 3] - positions[i], uy = positions[i + 4] - positions[i + 1], uz = positions[i + 5] - positions[i + 2];
    const vx = positions[i + 6] - positions[i], vy = positions[i + 7] - positions[i + 1], vz = positions[i + 8] - positions[i + 2];
    const nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    const len = Math.hypot(nx, ny, nz);
    const k = len > 0 ? 1 / len : 0;
    // Stryker disable next-line EqualityOperator: c = 9 writes the next triangle's first normal, which its own step writes again (past the end for the last)
    for (let c = 0; c < 9; c += 3) {
      normals[i + c] = nx * k;
      normals[i + c + 1] = ny * k;
      normals[i + c + 2] = nz * k;
    }
  }
  const indices = Uint32Array.from({ length: t.length }, (_, i) => i);
  return { positions, normals, uv0: expand(p.uv0, 2), uv1: expand(p.uv1, 2), colors: expand(p.colors, 4), indices, material: p.material, tangents: null };
}
