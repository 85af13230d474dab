// One glTF primitive read and placed (src/loaders/gltf/primitives.ts, docs/gltf.md#primitives): its
// refusals and warnings with their paths, triangle lists of strips and fans, positions through a
// node matrix and normals through its cofactors (worked out by hand), mirrored winding, flat
// normals, dropped triangles and RGB colours given alpha 1.
import { describe, expect, it } from 'vitest';
import { refusal } from './helpers/refusal';
import { GltfFile } from '../../src/loaders/gltf/fields';
import { MAX_COORDINATE, positionCount, readPiece, triangles } from '../../src/loaders/gltf/primitives';

const FLOAT = 5126, UNSIGNED_SHORT = 5123;
const IDENTITY = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
const TYPES: Record<number, string> = { 1: 'SCALAR', 2: 'VEC2', 3: 'VEC3', 4: 'VEC4' };

/**
 * A file of float attributes (name → [size, values]) and uint16 indices, one buffer, one view each;
 * its primitive's `attributes` map each name to its accessor, and `p` adds to the primitive.
 */
function model(attrs: Record<string, [number, number[]]>, indices: number[] | null, p: Record<string, unknown> = {}, json: Record<string, unknown> = {}) {
  const chunks: Uint8Array[] = [];
  const accessors: Record<string, unknown>[] = [];
  const attributes: Record<string, number> = {};
  for (const [name, [size, values]] of Object.entries(attrs)) {
    attributes[name] = accessors.length;
    accessors.push({ bufferView: chunks.length, componentType: FLOAT, count: values.length / size, type: TYPES[size] });
    chunks.push(new Uint8Array(new Float32Array(values).buffer));
  }
  const primitive: Record<string, unknown> = { attributes, ...p };
  if (indices) {
    primitive.indices = accessors.length;
    accessors.push({ bufferView: chunks.length, componentType: UNSIGNED_SHORT, count: indices.length, type: 'SCALAR' });
    chunks.push(new Uint8Array(new Uint16Array([...indices, ...(indices.length % 2 ? [0] : [])]).buffer));
  }
  let at = 0;
  const bufferViews = chunks.map((c) => ({ buffer: 0, byteOffset: (at += c.length) - c.length, byteLength: c.length }));
  const data = new Uint8Array(at);
  chunks.forEach((c, i) => data.set(c, bufferViews[i].byteOffset));
  const file = new GltfFile('p.gltf', { accessors, bufferViews, buffers: [{ byteLength: at }], ...json });
  return { file, buffers: [data], p: primitive };
}

const PATH = 'meshes[0].primitives[0]';
function read(m: ReturnType<typeof model>, matrix: number[] = IDENTITY) {
  return readPiece(m.file, m.buffers, m.p, PATH, { mesh: 0, matrix: Float64Array.from(matrix), node: 'nodes[0]' });
}
const round = (a: ArrayLike<number>, digits = 6) => Array.from(a, (x) => Number(x.toFixed(digits)) + 0);
const unit = (v: number[]) => v.map((x) => x / Math.hypot(...v));


const TRI = [0, 0, 0, 1, 0, 0, 0, 1, 0];

describe('what a primitive must have', () => {
  it('counts POSITION without reading it: 0 without one, refusals by the path of the attribute', () => {
    const m = model({ POSITION: [3, TRI] }, null);
    expect(positionCount(m.file, m.p, PATH)).toBe(3);
    expect(positionCount(m.file, { attributes: {} }, PATH)).toBe(0);
    expect(refusal(() => positionCount(m.file, { attributes: 4 }, PATH))).toEqual({ path: `${PATH}.attributes`, message: `${PATH}.attributes is not an object` });
    expect(refusal(() => positionCount(m.file, { attributes: { POSITION: 'a' } }, PATH))).toEqual({
      path: `${PATH}.attributes.POSITION`, message: `${PATH}.attributes.POSITION is "a", not a number`,
    });
    expect(refusal(() => positionCount(m.file, { attributes: { POSITION: 9 } }, PATH))).toEqual({
      path: `${PATH}.attributes.POSITION`, message: 'accessors[9] does not exist (accessors has 1)',
    });
  });

  it('refuses a mode past TRIANGLE_FAN and attributes that are not an object', () => {
    expect(refusal(() => read(model({ POSITION: [3, TRI] }, null, { mode: 7 })))).toEqual({ path: `${PATH}.mode`, message: `${PATH}.mode is 7, not a glTF primitive mode` });
    expect(refusal(() => read(model({ POSITION: [3, TRI] }, null, { attributes: [] })))).toEqual({
      path: `${PATH}.attributes`, message: `${PATH}.attributes is not an object`,
    });
  });

  it('leaves out a primitive without POSITION, with a warning naming it', () => {
    const m = model({ NORMAL: [3, TRI] }, null);
    expect(read(m)).toBeNull();
    expect(m.file.warnings).toEqual([{ path: `${PATH}.attributes`, message: `${PATH} has no POSITION: not drawn` }]);
  });

  it('refuses an attribute by its path: not an index, missing, or of another count than POSITION', () => {
    expect(refusal(() => read(model({ POSITION: [3, TRI] }, null, { attributes: { POSITION: 0, NORMAL: -1 } })))).toEqual({
      path: `${PATH}.attributes.NORMAL`, message: `${PATH}.attributes.NORMAL is -1, not an index or count`,
    });
    expect(refusal(() => read(model({ POSITION: [3, TRI] }, null, { attributes: { POSITION: 0, NORMAL: 5 } })))).toEqual({
      path: `${PATH}.attributes.NORMAL`, message: 'accessors[5] does not exist (accessors has 1)',
    });
    expect(refusal(() => read(model({ POSITION: [3, TRI], NORMAL: [3, [0, 0, 1, 0, 0, 1]] }, null)))).toEqual({
      path: `${PATH}.attributes.NORMAL`, message: `${PATH}.attributes.NORMAL has 2 elements, POSITION has 3`,
    });
  });

  it('refuses indices and a material that do not exist, by the primitive\'s path', () => {
    expect(refusal(() => read(model({ POSITION: [3, TRI] }, null, { indices: 4 })))).toEqual({
      path: `${PATH}.indices`, message: 'accessors[4] does not exist (accessors has 1)',
    });
    expect(refusal(() => read(model({ POSITION: [3, TRI] }, null, { material: 2 }, { materials: [{}] })))).toEqual({
      path: `${PATH}.material`, message: 'materials[2] does not exist (materials has 1)',
    });
  });
});

describe('triangle lists', () => {
  it('keeps whole triangles of a list, and lists strips and fans by glTF\'s rules', () => {
    expect(Array.from(triangles(4, Uint32Array.from([5, 6, 7, 8, 9, 10, 11]), 12))).toEqual([5, 6, 7, 8, 9, 10]);
    expect(Array.from(triangles(4, null, 4))).toEqual([0, 1, 2]);
    expect(Array.from(triangles(4, null, 6))).toEqual([0, 1, 2, 3, 4, 5]);
    expect(Array.from(triangles(5, Uint32Array.from([9, 8, 7, 6, 5]), 10))).toEqual([9, 8, 7, 8, 6, 7, 7, 6, 5]);
    expect(Array.from(triangles(6, Uint32Array.from([9, 8, 7, 6, 5]), 10))).toEqual([8, 7, 9, 7, 6, 9, 6, 5, 9]);
    expect(Array.from(triangles(5, null, 2))).toEqual([]);
  });
});

describe('placed by the node matrix', () => {
  // Column-major: the columns (2, 1, 3), (1, 4, 1), (3, 2, 5), translation (10, 20, 30); determinant 4.
  const M = [2, 1, 3, 0, 1, 4, 1, 0, 3, 2, 5, 0, 10, 20, 30, 1];
  const P = [1, 2, 3, 3, -1, 2, -2, 1, 1];

  it('moves positions by the matrix and normals by its cofactors, made unit', () => {
    const r = read(model({ POSITION: [3, P], NORMAL: [3, P] }, [0, 1, 2]), M)!;
    // Row by row: (2x + y + 3z + 10, x + 4y + 2z + 20, 3x + y + 5z + 30).
    expect(round(r.positions)).toEqual([23, 35, 50, 21, 23, 48, 10, 24, 30]);
    // Cofactors, rows (18, 1, -11), (-2, 1, 1), (-10, -1, 7), times each normal.
    expect(round(r.normals, 5)).toEqual(round([...unit([-13, 3, 9]), ...unit([31, -5, -15]), ...unit([-46, 6, 26])], 5));
    expect(Array.from(r.indices)).toEqual([0, 1, 2]);
  });

  it('turns the winding and the normals under a mirroring matrix (determinant -2)', () => {
    // Columns (-3, -3, -1), (1, 0, -2), (2, 2, 0).
    const mirror = [-3, -3, -1, 0, 1, 0, -2, 0, 2, 2, 0, 0, 0, 0, 0, 1];
    const r = read(model({ POSITION: [3, TRI], NORMAL: [3, [0, 0, 1, 0, 0, 1, 0, 0, 1]] }, [0, 1, 2]), mirror)!;
    expect(Array.from(r.indices)).toEqual([0, 2, 1]);
    expect(round(r.positions)).toEqual([0, 0, 0, -3, -3, -1, 1, 0, -2]);
    // (0, 0, 1) by the cofactors (the cofactor matrix's third column: 6, -7, 3), times the sign -1.
    expect(round(r.normals, 5)).toEqual(round([...unit([-6, 7, -3]), ...unit([-6, 7, -3]), ...unit([-6, 7, -3])], 5));
  });

  it('keeps a zero normal zero under a matrix', () => {
    const r = read(model({ POSITION: [3, P], NORMAL: [3, [0, 0, 0, 1, 0, 0, 0, 0, 0]] }, [0, 1, 2]), M)!;
    expect(round(r.normals, 5)).toEqual(round([0, 0, 0, ...unit([18, -2, -10]), 0, 0, 0], 5));
  });

  it('keeps the winding under a matrix that flattens the model (determinant 0)', () => {
    const flat = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1];
    const r = read(model({ POSITION: [3, TRI], NORMAL: [3, [0, 0, 1, 0, 0, 1, 0, 0, 1]] }, [0, 1, 2]), flat)!;
    expect(Array.from(r.indices)).toEqual([0, 1, 2]);
  });

  it('gives each triangle of a file without normals its own vertices and its unit normal', () => {
    const r = read(model({ POSITION: [3, [1, 2, 3, 4, 6, 3, 2, 5, 7]] }, null))!;
    // u = (3, 4, 0), v = (1, 3, 4): u × v = (16, -12, 5).
    expect(round(r.normals, 5)).toEqual(round([...unit([16, -12, 5]), ...unit([16, -12, 5]), ...unit([16, -12, 5])], 5));
    expect(Array.from(r.indices)).toEqual([0, 1, 2]);
    const two = read(model({ POSITION: [3, [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 2]] }, [0, 1, 2, 0, 3, 1]))!;
    expect(round(two.positions)).toEqual([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 2, 1, 0, 0]);
    expect(round(two.normals)).toEqual([0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 1, 0, 0, 1, 0, 0, 1, 0]);
    // A degenerate triangle: a zero normal.
    expect(round(read(model({ POSITION: [3, [0, 0, 0, 1, 1, 1, 2, 2, 2]] }, null))!.normals)).toEqual(new Array(9).fill(0));
  });
});

describe('positions and colours', () => {
  it('keeps a triangle just within MAX_COORDINATE and drops the one past it, keeping the others in order', () => {
    const big = MAX_COORDINATE;
    // Float32 rounds 1e15 to 999999986991104; beyond, 2e15.
    const f = Math.fround(big);
    expect(f).toBeLessThanOrEqual(big);
    const positions = [0, 0, 0, 1, 0, 0, 0, 1, 0, f, 0, 0, 2e15, 0, 0];
    const r = read(model({ POSITION: [3, positions], NORMAL: [3, new Array(15).fill(0).map((_, i) => (i % 3 === 2 ? 1 : 0))] }, [0, 1, 2, 3, 1, 2, 1, 2, 4, 2, 1, 0]))!;
    expect(Array.from(r.indices)).toEqual([0, 1, 2, 3, 1, 2, 2, 1, 0]);
  });

  it('gives RGB colours alpha 1 and keeps RGBA ones', () => {
    const rgb = read(model({ POSITION: [3, TRI], NORMAL: [3, [0, 0, 1, 0, 0, 1, 0, 0, 1]], COLOR_0: [3, [0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9]] }, [0, 1, 2]))!;
    expect(round(rgb.colors!)).toEqual([0.1, 0.2, 0.3, 1, 0.4, 0.5, 0.6, 1, 0.7, 0.8, 0.9, 1]);
    const rgba = read(model({ POSITION: [3, TRI], NORMAL: [3, [0, 0, 1, 0, 0, 1, 0, 0, 1]], COLOR_0: [4, [0.1, 0.2, 0.3, 0.5, 0, 0, 0, 0, 1, 1, 1, 0.25]] }, [0, 1, 2]))!;
    expect(round(rgba.colors!)).toEqual([0.1, 0.2, 0.3, 0.5, 0, 0, 0, 0, 1, 1, 1, 0.25]);
  });
});

describe('normals under the identity, and positions out of range', () => {
  it('makes the file\'s normals unit where the node places the mesh as it is, a zero normal staying zero', () => {
    const r = read(model({ POSITION: [3, TRI], NORMAL: [3, [0, 3, 4, 0, 0, 0, -2, 0, 0]] }, [0, 1, 2]))!;
    // (0, 3, 4) / 5; (−2, 0, 0) / 2.
    expect(round(r.normals)).toEqual([0, 0.6, 0.8, 0, 0, 0, -1, 0, 0]);
  });

  it('says nothing of a position out of range that no triangle uses', () => {
    const m = model({ POSITION: [3, [...TRI, NaN, 0, 0]], NORMAL: [3, [0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1]] }, [0, 1, 2]);
    expect(Array.from(read(m)!.indices)).toEqual([0, 1, 2]);
    expect(m.file.warnings).toEqual([]);
  });
});

describe('tangents for a normal map', () => {
  const N = [0, 0, 1, 0, 0, 1, 0, 0, 1];
  const materials = (normalTexture: unknown) => ({ materials: [{ normalTexture }] });

  it('takes the file\'s TANGENT through the matrix, made unit, w turned where the matrix mirrors', () => {
    // diag(−1, 2, 1): determinant −2. (1, 1, 0) → (−1, 2, 0) / √5; (0, 0, 3) → (0, 0, 1); a zero tangent stays zero.
    const mirror = [-1, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
    const m = model({ POSITION: [3, TRI], NORMAL: [3, N], TANGENT: [4, [1, 1, 0, 1, 0, 0, 3, -1, 0, 0, 0, 1]] }, [0, 1, 2], { material: 0 }, materials({ index: 0 }));
    const r = read(m, mirror)!;
    const s = 1 / Math.sqrt(5);
    expect(round(r.tangents!, 5)).toEqual(round([-s, 2 * s, 0, -1, 0, 0, 1, 1, 0, 0, 0, -1], 5));
    // Unmirrored, w is the file's.
    expect(round(read(m)!.tangents!)).toEqual([1, 1, 0, 1, 0, 0, 1, -1, 0, 0, 0, 1].map((x, i) => (i === 0 || i === 1 ? Number((x / Math.SQRT2).toFixed(6)) : x)));
  });

  it('takes them through a general matrix, w kept where it does not mirror, a w of 0 read as +1', () => {
    // Columns (2, 1, 3), (1, 4, 1), (3, 2, 5), determinant 4: (1, 2, 3) → (2 + 2 + 9, 1 + 8 + 6, 3 + 2 + 15) = (13, 15, 20).
    const M = [2, 1, 3, 0, 1, 4, 1, 0, 3, 2, 5, 0, 10, 20, 30, 1];
    const m = model({ POSITION: [3, TRI], NORMAL: [3, N], TANGENT: [4, [1, 2, 3, -1, 1, 2, 3, 0, 1, 2, 3, 1]] }, [0, 1, 2], { material: 0 }, materials({ index: 0 }));
    const t = unit([13, 15, 20]);
    expect(round(read(m, M)!.tangents!, 5)).toEqual(round([...t, -1, ...t, 1, ...t, 1], 5));
    // A matrix that flattens (determinant 0) does not mirror: w as the file has it.
    const flat = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1];
    expect(Array.from(read(m, flat)!.tangents!).filter((_, i) => i % 4 === 3)).toEqual([-1, 1, 1]);
  });

  it('computes them from the UV set the normal map reads, none without that set, none without a normal map', () => {
    const uv0 = [0, 0, 1, 0, 0, 1], uv1 = [0, 0, 0, 1, 1, 0];
    const attrs = { POSITION: [3, TRI], NORMAL: [3, N], TEXCOORD_0: [2, uv0], TEXCOORD_1: [2, uv1] } as Record<string, [number, number[]]>;
    // TEXCOORD_0: u along +x, T = +x; TEXCOORD_1: u along +y, T = +y.
    const t0 = read(model(attrs, [0, 1, 2], { material: 0 }, materials({ index: 0 })))!.tangents!;
    expect(round(t0.subarray(0, 3))).toEqual([1, 0, 0]);
    const t1 = read(model(attrs, [0, 1, 2], { material: 0 }, materials({ index: 0, texCoord: 1 })))!.tangents!;
    expect(round(t1.subarray(0, 3))).toEqual([0, 1, 0]);
    const { TEXCOORD_1: _, ...onlyUv0 } = attrs;
    expect(read(model(onlyUv0, [0, 1, 2], { material: 0 }, materials({ index: 0, texCoord: 1 })))!.tangents).toBeNull();
    expect(read(model(attrs, [0, 1, 2], { material: 0 }, { materials: [{}] }))!.tangents).toBeNull();
    expect(read(model(attrs, [0, 1, 2]))!.tangents).toBeNull();
  });

  it('refuses a normal texture that is not an object, or its texCoord, by the material\'s path', () => {
    const m = (normalTexture: unknown) => model({ POSITION: [3, TRI], NORMAL: [3, N] }, [0, 1, 2], { material: 0 }, materials(normalTexture));
    expect(refusal(() => read(m(5)))).toEqual({ path: 'materials[0].normalTexture', message: 'materials[0].normalTexture is not an object' });
    expect(refusal(() => read(m({ index: 0, texCoord: -1 })))).toEqual({
      path: 'materials[0].normalTexture.texCoord', message: 'materials[0].normalTexture.texCoord is -1, not an index or count',
    });
  });
});
