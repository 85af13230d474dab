// glTF accessors read value by value (src/loaders/gltf/accessors.ts, docs/gltf.md#accessors): each
// refusal of a count, type, component type, stride or range with its path and message; normalized
// bytes and shorts scaled and clamped by hand-computed values; unaligned strides; sparse substitutions
// checked index by index.
import { describe, expect, it } from 'vitest';
import { refusal } from './helpers/refusal';
import { GltfFile } from '../../src/loaders/gltf/fields';
import {
  BYTE, FLOAT, MAX_ELEMENTS, SHORT, UNSIGNED_BYTE, UNSIGNED_INT, UNSIGNED_SHORT, readAccessor, readIndices, type Expect,
} from '../../src/loaders/gltf/accessors';

const ANY: Expect = { types: ['SCALAR', 'VEC2', 'VEC3', 'VEC4'], components: [BYTE, UNSIGNED_BYTE, SHORT, UNSIGNED_SHORT, UNSIGNED_INT, FLOAT] };
const VEC3: Expect = { types: ['VEC3'], components: [FLOAT, SHORT] };

/** One buffer of `data`; views as given; accessors as given. */
function read(accessors: Record<string, unknown>[], views: Record<string, unknown>[], data: Uint8Array, expect: Expect = ANY, index = 0) {
  const file = new GltfFile('a.gltf', { accessors, bufferViews: views, buffers: [{ byteLength: data.length }] });
  return readAccessor(file, [data], index, 'meshes[0].primitives[0].attributes.X', expect);
}
const values = (...args: Parameters<typeof read>) => Array.from(read(...args).values);
const bytesOf = (a: ArrayBufferView) => new Uint8Array(a.buffer, a.byteOffset, a.byteLength);
const floats = (...v: number[]) => bytesOf(new Float32Array(v));
const whole = (data: Uint8Array) => [{ buffer: 0, byteLength: data.length }];


describe('counts, types and component types', () => {
  it('reads a count of 1, refuses a count of 0 and one above MAX_ELEMENTS', () => {
    const data = floats(1, 2, 3);
    expect(values([{ bufferView: 0, componentType: FLOAT, count: 1, type: 'VEC3' }], whole(data), data)).toEqual([1, 2, 3]);
    expect(refusal(() => read([{ bufferView: 0, componentType: FLOAT, count: 0, type: 'VEC3' }], whole(data), data))).toEqual({
      path: 'accessors[0].count', message: 'accessors[0].count is 0',
    });
    expect(refusal(() => read([{ componentType: FLOAT, count: MAX_ELEMENTS + 1, type: 'SCALAR' }], [], data))).toEqual({
      path: 'accessors[0].count', message: `accessors[0].count is ${MAX_ELEMENTS + 1}, above the ${MAX_ELEMENTS} elements read`,
    });
  });

  it('reads MAX_ELEMENTS zeros', () => {
    const a = read([{ componentType: UNSIGNED_BYTE, count: MAX_ELEMENTS, type: 'SCALAR' }], [], new Uint8Array(0));
    expect(a.values.length).toBe(MAX_ELEMENTS);
    expect(a.values[MAX_ELEMENTS - 1]).toBe(0);
  });

  it('refuses an unknown type (shown short), a type the attribute may not have, an unknown or unallowed component type', () => {
    const data = floats(1, 2, 3);
    const a = (o: Record<string, unknown>) => [{ bufferView: 0, componentType: FLOAT, count: 1, type: 'VEC3', ...o }];
    expect(refusal(() => read(a({ type: 'VEC7' }), whole(data), data))).toEqual({ path: 'accessors[0].type', message: 'accessors[0].type is "VEC7", not an accessor type' });
    expect(refusal(() => read(a({ type: 'V'.repeat(50) }), whole(data), data)).message).toBe(`accessors[0].type is "${'V'.repeat(39)}, not an accessor type`);
    expect(refusal(() => read(a({ type: 'VEC2' }), whole(data), data, VEC3))).toEqual({ path: 'accessors[0].type', message: 'accessors[0].type is VEC2 where VEC3 is needed' });
    expect(refusal(() => read(a({ type: 'MAT2' }), whole(data), data, { types: ['VEC3', 'VEC4'], components: [FLOAT] })).message)
      .toBe('accessors[0].type is MAT2 where VEC3 or VEC4 is needed');
    expect(refusal(() => read(a({ componentType: 1234 }), whole(data), data))).toEqual({
      path: 'accessors[0].componentType', message: 'accessors[0].componentType 1234 is not a glTF component type',
    });
    expect(refusal(() => read(a({ componentType: UNSIGNED_INT }), whole(data), data, VEC3))).toEqual({
      path: 'accessors[0].componentType', message: 'accessors[0].componentType is UNSIGNED_INT, not one this attribute may have',
    });
  });

  it('names each component type an attribute may not have', () => {
    const data = floats(1, 2, 3);
    const names = [[BYTE, 'BYTE'], [UNSIGNED_BYTE, 'UNSIGNED_BYTE'], [SHORT, 'SHORT'], [UNSIGNED_SHORT, 'UNSIGNED_SHORT'], [UNSIGNED_INT, 'UNSIGNED_INT'], [FLOAT, 'FLOAT']] as const;
    for (const [componentType, name] of names) {
      expect(refusal(() => read([{ bufferView: 0, componentType, count: 1, type: 'SCALAR' }], whole(data), data, { types: ['SCALAR'], components: [] })).message)
        .toBe(`accessors[0].componentType is ${name}, not one this attribute may have`);
    }
  });

  it('refuses a normalized FLOAT or UNSIGNED_INT accessor', () => {
    const data = floats(1, 2, 3);
    for (const [componentType, name] of [[FLOAT, 'FLOAT'], [UNSIGNED_INT, 'UNSIGNED_INT']] as const) {
      expect(refusal(() => read([{ bufferView: 0, componentType, count: 3, type: 'SCALAR', normalized: true }], whole(data), data))).toEqual({
        path: 'accessors[0].normalized', message: `accessors[0] is normalized, which a ${name} accessor cannot be`,
      });
    }
  });
});

describe('values', () => {
  it('scales normalized components: BYTE by 1/127, UNSIGNED_BYTE by 1/255, SHORT by 1/32767, UNSIGNED_SHORT by 1/65535', () => {
    const cases = [
      [BYTE, new Int8Array([64, -127, -128, 127]), [64 / 127, -1, -1, 1]],
      [UNSIGNED_BYTE, new Uint8Array([51, 0, 255, 102]), [0.2, 0, 1, 0.4]],
      [SHORT, new Int16Array([16384, -32767, -32768, 32767]), [16384 / 32767, -1, -1, 1]],
      [UNSIGNED_SHORT, new Uint16Array([13107, 0, 65535, 26214]), [0.2, 0, 1, 0.4]],
    ] as const;
    for (const [componentType, array, expected] of cases) {
      const data = bytesOf(array);
      const got = values([{ bufferView: 0, componentType, count: 1, type: 'VEC4', normalized: true }], whole(data), data);
      got.forEach((v, i) => expect(v, `${componentType}[${i}]`).toBeCloseTo(expected[i], 6));
    }
  });

  it('reads integers that are not normalized as they are, below -1 included', () => {
    for (const [componentType, array] of [[BYTE, new Int8Array([-5, -128, 3, 0])], [SHORT, new Int16Array([-5, -300, 3, 0])]] as const) {
      const data = bytesOf(array);
      expect(values([{ bufferView: 0, componentType, count: 1, type: 'VEC4' }], whole(data), data)).toEqual(Array.from(array));
    }
  });

  it('reads at an unaligned offset and with a stride that is not a multiple of the component size', () => {
    // Floats 1, 2, 3 from byte 1; then floats 5 bytes apart from byte 0.
    const data = new Uint8Array(16);
    const view = new DataView(data.buffer);
    [1, 2, 3].forEach((v, i) => view.setFloat32(1 + 4 * i, v, true));
    expect(values([{ bufferView: 0, byteOffset: 1, componentType: FLOAT, count: 3, type: 'SCALAR' }], whole(data), data)).toEqual([1, 2, 3]);
    const strided = new Uint8Array(16);
    const sv = new DataView(strided.buffer);
    [7, 8, 9].forEach((v, i) => sv.setFloat32(5 * i, v, true));
    const views = [{ buffer: 0, byteLength: 16, byteStride: 5 }];
    expect(values([{ bufferView: 0, componentType: FLOAT, count: 3, type: 'SCALAR' }], views, strided)).toEqual([7, 8, 9]);
  });

  it('refuses a stride shorter than an element, and an accessor past the end of its view, with the bytes it names', () => {
    const data = floats(1, 2, 3, 4, 5, 6);
    const views = [{ buffer: 0, byteLength: 24, byteStride: 8 }];
    expect(refusal(() => read([{ bufferView: 0, componentType: FLOAT, count: 2, type: 'VEC3' }], views, data))).toEqual({
      path: 'bufferViews[0].byteStride', message: "a stride of 8 bytes is less than accessors[0]'s element (12 bytes)",
    });
    expect(refusal(() => read([{ bufferView: 0, byteOffset: 4, componentType: FLOAT, count: 2, type: 'VEC3' }], whole(data), data))).toEqual({
      path: 'accessors[0]', message: 'accessors[0] reads bytes 4 to 28 of bufferViews[0], which has 24',
    });
  });

  it('reads indices below the vertex count and refuses one at it', () => {
    const data = bytesOf(new Uint16Array([0, 2, 1, 2]));
    const file = new GltfFile('a.gltf', { accessors: [{ bufferView: 0, componentType: UNSIGNED_SHORT, count: 4, type: 'SCALAR' }], bufferViews: whole(data) });
    expect(Array.from(readIndices(file, [data], 0, 'p.indices', 3))).toEqual([0, 2, 1, 2]);
    expect(refusal(() => readIndices(file, [data], 0, 'p.indices', 2))).toEqual({
      path: 'accessors[0]', message: "accessors[0][1] is 2: past the primitive's 2 vertices",
    });
  });
});

describe('sparse accessors', () => {
  /** Base VEC3 floats (4 elements of 9s) in view 0; sparse indices (uint8) in view 1; sparse values (VEC3 floats) in view 2. */
  function sparse(indices: number[], replacements: number[], s: Record<string, unknown> = {}, indexType = UNSIGNED_BYTE) {
    const base = floats(...new Array(12).fill(9));
    const idx = indexType === UNSIGNED_BYTE ? new Uint8Array(indices) : bytesOf(new Uint16Array(indices));
    const vals = floats(...replacements);
    const data = new Uint8Array(48 + 8 + vals.length);
    data.set(base, 0);
    data.set(idx, 48);
    data.set(vals, 56);
    const views = [{ buffer: 0, byteLength: 48 }, { buffer: 0, byteOffset: 48, byteLength: idx.length }, { buffer: 0, byteOffset: 56, byteLength: vals.length }];
    const accessor = {
      bufferView: 0, componentType: FLOAT, count: 4, type: 'VEC3',
      sparse: { count: indices.length, indices: { bufferView: 1, componentType: indexType }, values: { bufferView: 2 }, ...s },
    };
    return () => read([accessor], views, data);
  }

  it('replaces the elements listed, VEC3 by VEC3, with 16-bit indices too', () => {
    expect(Array.from(sparse([1, 3], [1, 2, 3, 4, 5, 6])().values)).toEqual([9, 9, 9, 1, 2, 3, 9, 9, 9, 4, 5, 6]);
    expect(Array.from(sparse([0, 1, 2, 3], new Array(12).fill(0).map((_, i) => i))().values)).toEqual([0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11]);
    expect(Array.from(sparse([2], [7, 7, 7], {}, UNSIGNED_SHORT)().values)).toEqual([9, 9, 9, 9, 9, 9, 7, 7, 7, 9, 9, 9]);
  });

  it('refuses a sparse count of 0 or above the accessor\'s', () => {
    expect(refusal(sparse([1], [1, 2, 3], { count: 0 }))).toEqual({ path: 'accessors[0].sparse.count', message: 'accessors[0].sparse.count is 0, outside [1, 4]' });
    expect(refusal(sparse([1], [1, 2, 3], { count: 5 }))).toEqual({ path: 'accessors[0].sparse.count', message: 'accessors[0].sparse.count is 5, outside [1, 4]' });
  });

  it('refuses sparse indices that do not increase or reach the count, naming the first', () => {
    const message = (i: number, v: number) => `accessors[0].sparse.indices[${i}] is ${v}: indices must increase and stay below 4`;
    expect(refusal(sparse([1, 1], [1, 2, 3, 4, 5, 6]))).toEqual({ path: 'accessors[0].sparse.indices', message: message(1, 1) });
    expect(refusal(sparse([2, 1], [1, 2, 3, 4, 5, 6]))).toEqual({ path: 'accessors[0].sparse.indices', message: message(1, 1) });
    expect(refusal(sparse([4], [1, 2, 3]))).toEqual({ path: 'accessors[0].sparse.indices', message: message(0, 4) });
  });

  it('refuses sparse parts that are not objects, a signed or float index type, and parts past their views', () => {
    expect(refusal(sparse([1], [1, 2, 3], { indices: 3 }))).toEqual({ path: 'accessors[0].sparse.indices', message: 'accessors[0].sparse.indices is not an object' });
    expect(refusal(sparse([1], [1, 2, 3], { values: 3 }))).toEqual({ path: 'accessors[0].sparse.values', message: 'accessors[0].sparse.values is not an object' });
    expect(refusal(sparse([1], [1, 2, 3], { indices: { bufferView: 1 } }))).toEqual({
      path: 'accessors[0].sparse.indices.componentType', message: 'accessors[0].sparse.indices.componentType is missing, not a number',
    });
    for (const componentType of [BYTE, SHORT, FLOAT]) {
      expect(refusal(sparse([1], [1, 2, 3], { indices: { bufferView: 1, componentType } }))).toEqual({
        path: 'accessors[0].sparse.indices.componentType', message: `accessors[0].sparse.indices.componentType ${componentType} is not an unsigned integer type`,
      });
    }
    expect(refusal(sparse([1], [1, 2, 3], { indices: { componentType: UNSIGNED_BYTE } }))).toEqual({
      path: 'accessors[0].sparse.indices.bufferView', message: 'accessors[0].sparse.indices.bufferView is missing, not a number',
    });
    expect(refusal(sparse([1], [1, 2, 3], { values: { bufferView: 7 } }))).toEqual({
      path: 'accessors[0].sparse.values.bufferView', message: 'bufferViews[7] does not exist (bufferViews has 3)',
    });
    expect(refusal(sparse([1], [1, 2, 3], { values: { bufferView: 2, byteOffset: -4 } }))).toEqual({
      path: 'accessors[0].sparse.values.byteOffset', message: 'accessors[0].sparse.values.byteOffset is -4, not an index or count',
    });
    expect(refusal(sparse([1], [1, 2, 3], { values: { bufferView: 2, byteOffset: 4 } }))).toEqual({
      path: 'accessors[0].sparse.values', message: 'accessors[0].sparse.values reads bytes 4 to 16 of bufferViews[2], which has 12',
    });
    expect(refusal(sparse([1, 2], [1, 2, 3, 4, 5, 6], { indices: { bufferView: 1, componentType: UNSIGNED_INT } }))).toEqual({
      path: 'accessors[0].sparse.indices', message: 'accessors[0].sparse.indices reads bytes 0 to 8 of bufferViews[1], which has 2',
    });
  });
});
