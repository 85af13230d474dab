// glTF accessors to arrays (docs/gltf.md#accessors): every component type, normalized or not,
// tightly packed or strided, with or without a buffer view, with sparse substitutions. Every
// range is checked against the bytes of its view before a value is read.
import { bufferView } from './buffers';
import { GltfFile, int, object, optionalObject, str, type Obj } from './fields';

export const BYTE = 5120, UNSIGNED_BYTE = 5121, SHORT = 5122, UNSIGNED_SHORT = 5123, UNSIGNED_INT = 5125, FLOAT = 5126;

const COMPONENT_BYTES: Readonly<Record<number, number>> = { [BYTE]: 1, [UNSIGNED_BYTE]: 1, [SHORT]: 2, [UNSIGNED_SHORT]: 2, [UNSIGNED_INT]: 4, [FLOAT]: 4 };
const COMPONENT_NAMES: Readonly<Record<number, string>> = {
  [BYTE]: 'BYTE', [UNSIGNED_BYTE]: 'UNSIGNED_BYTE', [SHORT]: 'SHORT', [UNSIGNED_SHORT]: 'UNSIGNED_SHORT', [UNSIGNED_INT]: 'UNSIGNED_INT', [FLOAT]: 'FLOAT',
};
const SIZES: Readonly<Record<string, number>> = { SCALAR: 1, VEC2: 2, VEC3: 3, VEC4: 4, MAT2: 4, MAT3: 9, MAT4: 16 };

/**
 * Elements an accessor may have: above it a count is a corrupt or hostile file (a buffer-backed
 * accessor is bounded by its bytes before this; this bounds one made of zeros and sparse values).
 */
export const MAX_ELEMENTS = 1 << 25;

export interface Expect {
  /** The accessor types allowed (e.g. ['VEC3']). */
  types: readonly string[];
  /** The component types allowed, and for each whether it must, may or must not be normalized. */
  components: readonly number[];
}

export interface Accessor {
  /** `size` values per element, as floats: normalized integers mapped to [0, 1] or [−1, 1]. */
  values: Float32Array;
  size: number;
  count: number;
  componentType: number;
  normalized: boolean;
}

interface Layout {
  componentType: number;
  bytes: number;
  size: number;
  normalized: boolean;
}

/** accessors[index] as floats; `from` names where the index was read (for the error of a missing one). */
export function readAccessor(file: GltfFile, buffers: readonly Uint8Array[], index: number, from: string, expect: Expect): Accessor {
  const path = `accessors[${index}]`;
  const a = file.item('accessors', index, from);
  const layout = layoutOf(file, a, path, expect);
  const count = int(file, a, 'count', path);
  if (count < 1) file.fail(`${path}.count`, `${path}.count is 0`);
  if (count > MAX_ELEMENTS) file.fail(`${path}.count`, `${path}.count is ${count}, above the ${MAX_ELEMENTS} elements read`);
  const values = new Float32Array(count * layout.size);
  const decoded = file.decodedAccessors.get(index);
  if (decoded) readInto(values, 0, decoded, 0, layout.size * layout.bytes, count, layout);
  else if (a.bufferView !== undefined) {
    const viewIndex = int(file, a, 'bufferView', path);
    const view = bufferView(file, buffers, viewIndex, `${path}.bufferView`);
    const offset = int(file, a, 'byteOffset', path, 0);
    const elementBytes = layout.size * layout.bytes;
    const stride = view.stride ?? elementBytes;
    if (stride < elementBytes) file.fail(`bufferViews[${viewIndex}].byteStride`, `a stride of ${stride} bytes is less than ${path}'s element (${elementBytes} bytes)`);
    const end = offset + stride * (count - 1) + elementBytes;
    if (end > view.bytes.length) {
      file.fail(path, `${path} reads bytes ${offset} to ${end} of bufferViews[${viewIndex}], which has ${view.bytes.length}`);
    }
    readInto(values, 0, view.bytes, offset, stride, count, layout);
  }
  const sparse = optionalObject(file, a, 'sparse', path);
  if (sparse) applySparse(file, buffers, sparse, `${path}.sparse`, values, count, layout);
  return { values, size: layout.size, count, componentType: layout.componentType, normalized: layout.normalized };
}

/** An index accessor: unsigned integers, each below `vertexCount`. */
export function readIndices(file: GltfFile, buffers: readonly Uint8Array[], index: number, from: string, vertexCount: number): Uint32Array {
  const { values } = readAccessor(file, buffers, index, from, { types: ['SCALAR'], components: [UNSIGNED_BYTE, UNSIGNED_SHORT, UNSIGNED_INT] });
  const out = new Uint32Array(values.length);
  // Stryker disable next-line EqualityOperator: values[length] is undefined, never >= the vertex count, and out[length] is no element
  for (let i = 0; i < values.length; i++) {
    const v = values[i];
    if (v >= vertexCount) file.fail(`accessors[${index}]`, `accessors[${index}][${i}] is ${v}: past the primitive's ${vertexCount} vertices`);
    out[i] = v;
  }
  return out;
}

function layoutOf(file: GltfFile, a: Obj, path: string, expect: Expect): Layout {
  const type = str(file, a, 'type', path);
  const size = SIZES[type];
  if (size === undefined) file.fail(`${path}.type`, `${path}.type is ${JSON.stringify(type).slice(0, 40)}, not an accessor type`);
  if (!expect.types.includes(type)) file.fail(`${path}.type`, `${path}.type is ${type} where ${expect.types.join(' or ')} is needed`);
  const componentType = int(file, a, 'componentType', path);
  const bytes = COMPONENT_BYTES[componentType];
  if (bytes === undefined) file.fail(`${path}.componentType`, `${path}.componentType ${componentType} is not a glTF component type`);
  if (!expect.components.includes(componentType)) {
    file.fail(`${path}.componentType`, `${path}.componentType is ${COMPONENT_NAMES[componentType]}, not one this attribute may have`);
  }
  const normalized = a.normalized === true;
  if (normalized && (componentType === FLOAT || componentType === UNSIGNED_INT)) {
    file.fail(`${path}.normalized`, `${path} is normalized, which a ${COMPONENT_NAMES[componentType]} accessor cannot be`);
  }
  return { componentType, bytes, size, normalized };
}

const ARRAYS = {
  [BYTE]: Int8Array, [UNSIGNED_BYTE]: Uint8Array, [SHORT]: Int16Array, [UNSIGNED_SHORT]: Uint16Array, [UNSIGNED_INT]: Uint32Array, [FLOAT]: Float32Array,
} as const;

/** Elements `count` from `bytes` at `offset`, `stride` bytes apart, into `out` from element `first`. */
function readInto(out: Float32Array, first: number, bytes: Uint8Array, offset: number, stride: number, count: number, l: Layout): void {
  const elementBytes = l.size * l.bytes;
  let source = bytes.buffer as ArrayBuffer;
  let start = bytes.byteOffset + offset;
  // Stryker disable next-line ConditionalExpression,ArithmeticOperator: packing an aligned accessor too reads the same values
  if (start % l.bytes !== 0 || stride % l.bytes !== 0) {
    // Unaligned (a hand-made file's offset or stride): its elements copied once, packed and aligned.
    const packed = new Uint8Array(count * elementBytes);
    for (let k = 0; k < count; k++) packed.set(bytes.subarray(offset + k * stride, offset + k * stride + elementBytes), k * elementBytes);
    source = packed.buffer;
    start = 0;
    stride = elementBytes;
  }
  const step = stride / l.bytes;
  const src = new ARRAYS[l.componentType as keyof typeof ARRAYS](source, start, step * (count - 1) + l.size);
  const scale = l.normalized ? normalizer(l.componentType) : 1;
  // Stryker disable next-line ConditionalExpression: a normalized unsigned value is never below -1 (FLOAT and UNSIGNED_INT are refused)
  const signed = l.normalized && (l.componentType === BYTE || l.componentType === SHORT);
  // Stryker disable next-line ArithmeticOperator,EqualityOperator: first is 0 in every call; an extra k writes NaN past out's end
  for (let k = 0, o = first * l.size; k < count; k++) {
    for (let c = 0, s = k * step; c < l.size; c++, o++) {
      const v = src[s + c] * scale;
      // Stryker disable next-line EqualityOperator: at v = -1 both branches give -1
      out[o] = signed && v < -1 ? -1 : v;
    }
  }
}

/** glTF's normalization: c / (2^bits − 1) unsigned, max(c / (2^(bits−1) − 1), −1) signed. */
function normalizer(componentType: number): number {
  switch (componentType) {
    case BYTE: return 1 / 127;
    case UNSIGNED_BYTE: return 1 / 255;
    case SHORT: return 1 / 32767;
    default: return 1 / 65535;
  }
}

function applySparse(file: GltfFile, buffers: readonly Uint8Array[], s: Obj, path: string, out: Float32Array, count: number, l: Layout): void {
  const n = int(file, s, 'count', path);
  if (n < 1 || n > count) file.fail(`${path}.count`, `${path}.count is ${n}, outside [1, ${count}]`);
  const indices = object(file, s.indices, `${path}.indices`);
  const values = object(file, s.values, `${path}.values`);
  const indexType = int(file, indices, 'componentType', `${path}.indices`);
  if (indexType !== UNSIGNED_BYTE && indexType !== UNSIGNED_SHORT && indexType !== UNSIGNED_INT) {
    file.fail(`${path}.indices.componentType`, `${path}.indices.componentType ${indexType} is not an unsigned integer type`);
  }
  const at = new Float32Array(n);
  const indexLayout: Layout = { componentType: indexType, bytes: COMPONENT_BYTES[indexType], size: 1, normalized: false };
  readSparsePart(file, buffers, indices, `${path}.indices`, at, n, indexLayout);
  const replaced = new Float32Array(n * l.size);
  readSparsePart(file, buffers, values, `${path}.values`, replaced, n, l);
  // Stryker disable next-line EqualityOperator: at i = n the target is undefined (no check fails) and an empty subarray is set
  for (let i = 0; i < n; i++) {
    const target = at[i];
    // Stryker disable next-line ConditionalExpression,EqualityOperator: at i = 0, at[-1] is undefined: target <= undefined is false
    if (target >= count || (i > 0 && target <= at[i - 1])) {
      file.fail(`${path}.indices`, `${path}.indices[${i}] is ${target}: indices must increase and stay below ${count}`);
    }
    out.set(replaced.subarray(i * l.size, (i + 1) * l.size), target * l.size);
  }
}

function readSparsePart(file: GltfFile, buffers: readonly Uint8Array[], part: Obj, path: string, out: Float32Array, n: number, l: Layout): void {
  const viewIndex = int(file, part, 'bufferView', path);
  const view = bufferView(file, buffers, viewIndex, `${path}.bufferView`);
  const offset = int(file, part, 'byteOffset', path, 0);
  const bytes = l.size * l.bytes;
  if (offset + n * bytes > view.bytes.length) {
    file.fail(path, `${path} reads bytes ${offset} to ${offset + n * bytes} of bufferViews[${viewIndex}], which has ${view.bytes.length}`);
  }
  readInto(out, 0, view.bytes, offset, bytes, n, l);
}
