// KHR_draco_mesh_compression (docs/gltf.md#compression): a primitive's attributes and indices
// decoded from a buffer view by the draco3d package's own decoder (a chunk and a wasm file of its
// own, fetched only by a file with such a primitive). The decoded values are laid out as the
// primitive's accessors declare them (component type, size), tightly packed, and read in place
// of those accessors' (absent) buffer views.
import { GltfFile, int, object, optionalObject, type Obj } from './fields';
import { bufferView } from './buffers';
import { BYTE, FLOAT, SHORT, UNSIGNED_BYTE, UNSIGNED_INT, UNSIGNED_SHORT } from './accessors';

export const DRACO = 'KHR_draco_mesh_compression';

/** The part of draco3d's decoder module this reader calls (its emscripten bindings). */
export interface DracoModule {
  DecoderBuffer: new () => { Init(data: Int8Array, length: number): void };
  Decoder: new () => DracoDecoder;
  Mesh: new () => { num_points(): number; num_faces(): number };
  _malloc(bytes: number): number;
  _free(ptr: number): void;
  HEAPU8: Uint8Array;
  destroy(o: object): void;
  DT_INT8: number; DT_UINT8: number; DT_INT16: number; DT_UINT16: number; DT_UINT32: number; DT_FLOAT32: number;
}

interface DracoDecoder {
  DecodeArrayToMesh(data: Int8Array, length: number, mesh: object): { ok(): boolean; error_msg(): string };
  GetAttributeByUniqueId(mesh: object, id: number): { num_components(): number } | null;
  GetAttributeDataArrayForAllPoints(mesh: object, attribute: object, type: number, bytes: number, ptr: number): boolean;
  GetTrianglesUInt32Array(mesh: object, bytes: number, ptr: number): boolean;
}

const BYTES: Readonly<Record<number, number>> = { [BYTE]: 1, [UNSIGNED_BYTE]: 1, [SHORT]: 2, [UNSIGNED_SHORT]: 2, [UNSIGNED_INT]: 4, [FLOAT]: 4 };
const SIZES: Readonly<Record<string, number>> = { SCALAR: 1, VEC2: 2, VEC3: 3, VEC4: 4 };

/** The primitives a file compresses with Draco: their path, the primitive and its extension object. */
export function dracoPrimitives(file: GltfFile): { path: string; primitive: Obj; ext: Obj }[] {
  const out: { path: string; primitive: Obj; ext: Obj }[] = [];
  file.list('meshes').forEach((m, i) => {
    const list = object(file, m, `meshes[${i}]`).primitives;
    if (!Array.isArray(list)) return;
    list.forEach((p, k) => {
      const path = `meshes[${i}].primitives[${k}]`;
      const primitive = object(file, p, path);
      const extensions = optionalObject(file, primitive, 'extensions', path);
      const ext = extensions && optionalObject(file, extensions, DRACO, `${path}.extensions`);
      if (ext) out.push({ path, primitive, ext });
    });
  });
  return out;
}

/** Each Draco primitive decoded: accessor index → its elements, packed as the accessor declares. */
export function decodeDraco(file: GltfFile, buffers: readonly Uint8Array[], draco: DracoModule): Map<number, Uint8Array> {
  const out = new Map<number, Uint8Array>();
  for (const { path, primitive, ext } of dracoPrimitives(file)) {
    const at = `${path}.extensions.${DRACO}`;
    const view = bufferView(file, buffers, int(file, ext, 'bufferView', at), `${at}.bufferView`);
    const data = new Int8Array(view.bytes.buffer, view.bytes.byteOffset, view.bytes.length);
    const decoder = new draco.Decoder();
    const mesh = new draco.Mesh();
    try {
      const status = decoder.DecodeArrayToMesh(data, data.length, mesh);
      if (!status.ok()) file.fail(at, `${at} does not decode (${status.error_msg()})`);
      const points = mesh.num_points();
      const ids = object(file, ext.attributes, `${at}.attributes`);
      const attributes = object(file, primitive.attributes, `${path}.attributes`);
      for (const [name, id] of Object.entries(ids)) {
        if (!Object.hasOwn(attributes, name)) continue; // not `attributes[name]`: a name like `constructor` is inherited
        const accessor = int(file, attributes, name, `${path}.attributes`);
        const attribute = decoder.GetAttributeByUniqueId(mesh, typeof id === 'number' ? id : -1);
        if (!attribute) file.fail(`${at}.attributes.${name}`, `${at} has no attribute ${JSON.stringify(id)} for ${name}`);
        out.set(accessor, attributeBytes(file, draco, decoder, mesh, attribute, accessor, points));
      }
      if (primitive.indices !== undefined) {
        const accessor = int(file, primitive, 'indices', path);
        out.set(accessor, indexBytes(file, draco, decoder, mesh, accessor));
      }
    } finally {
      draco.destroy(mesh);
      draco.destroy(decoder);
    }
  }
  return out;
}

function layout(file: GltfFile, accessor: number): { type: number; size: number; count: number } {
  const a = file.item('accessors', accessor, `accessors[${accessor}]`);
  const path = `accessors[${accessor}]`;
  const type = int(file, a, 'componentType', path);
  const size = Object.hasOwn(SIZES, String(a.type)) ? SIZES[String(a.type)] : undefined;
  if (BYTES[type] === undefined || size === undefined) file.fail(path, `${path} is not a type a Draco primitive can fill`);
  return { type, size, count: int(file, a, 'count', path) };
}

function attributeBytes(file: GltfFile, draco: DracoModule, decoder: DracoDecoder, mesh: object, attribute: object, accessor: number, points: number): Uint8Array {
  const { type, size, count } = layout(file, accessor);
  if (count !== points) file.fail(`accessors[${accessor}].count`, `accessors[${accessor}].count is ${count}, the Draco mesh has ${points} points`);
  const dataType = { [BYTE]: draco.DT_INT8, [UNSIGNED_BYTE]: draco.DT_UINT8, [SHORT]: draco.DT_INT16, [UNSIGNED_SHORT]: draco.DT_UINT16, [UNSIGNED_INT]: draco.DT_UINT32, [FLOAT]: draco.DT_FLOAT32 }[type]!;
  return copyOut(draco, points * size * BYTES[type], (bytes, ptr) => decoder.GetAttributeDataArrayForAllPoints(mesh, attribute, dataType, bytes, ptr));
}

function indexBytes(file: GltfFile, draco: DracoModule, decoder: DracoDecoder, mesh: { num_faces(): number }, accessor: number): Uint8Array {
  const { type, count } = layout(file, accessor);
  const n = mesh.num_faces() * 3;
  if (count !== n) file.fail(`accessors[${accessor}].count`, `accessors[${accessor}].count is ${count}, the Draco mesh has ${n} indices`);
  const all = new Uint32Array(copyOut(draco, 4 * n, (bytes, ptr) => decoder.GetTrianglesUInt32Array(mesh, bytes, ptr)).buffer);
  // Laid out as the accessor says (16 or 8 bits where it says so): read back through it.
  const packed = type === UNSIGNED_INT ? all : type === UNSIGNED_SHORT ? Uint16Array.from(all) : Uint8Array.from(all);
  return new Uint8Array(packed.buffer);
}

/** Bytes the decoder writes into its own memory, copied out and freed. */
function copyOut(draco: DracoModule, bytes: number, fill: (bytes: number, ptr: number) => boolean): Uint8Array {
  const ptr = draco._malloc(bytes);
  try {
    fill(bytes, ptr);
    return draco.HEAPU8.slice(ptr, ptr + bytes);
  } finally {
    draco._free(ptr);
  }
}
