// EXT_meshopt_compression and KHR_draco_mesh_compression read through fake decoders (src/loaders/gltf/meshopt.ts and
// draco.ts, docs/gltf.md#compression): every value handed to a decoder and every byte taken back, each refusal's path
// and message, and Draco's memory freed and its objects destroyed even when decoding fails. No wasm: see gltf-compression.
import { describe, expect, it } from 'vitest';
import { LoadError } from '../../src/loaders/load-error';
import { decodeDraco, dracoPrimitives, type DracoModule } from '../../src/loaders/gltf/draco';
import { GltfFile } from '../../src/loaders/gltf/fields';
import { decodeMeshopt, isFallback, MAX_DECODED_BYTES, meshoptViews, type MeshoptDecoderLike } from '../../src/loaders/gltf/meshopt';

type Json = Record<string, unknown>;
const file = (json: Json) => new GltfFile('x.gltf', json);

/** The path and message of the LoadError `run` throws (or rejects with). */
async function refusal(run: () => unknown): Promise<{ path: string | undefined; message: string }> {
  try {
    await run();
  } catch (e) {
    expect(e).toBeInstanceOf(LoadError);
    return { path: (e as LoadError).path, message: (e as LoadError).detail.message };
  }
  throw new Error('read without an error');
}

/** A map's entries with their bytes as plain arrays, for exact comparison. */
const entries = (map: ReadonlyMap<number, Uint8Array>) => [...map].map(([k, v]) => [k, Array.from(v)]);

describe('EXT_meshopt_compression', () => {
  /** meshoptimizer's decoder in plain TypeScript: each call recorded, "decoding" by copying the source to the start of the target. */
  class FakeMeshopt implements MeshoptDecoderLike {
    readonly calls: { bytes: number; count: number; stride: number; source: number[]; mode: string; filter: string | undefined }[] = [];
    readyReads = 0;

    constructor(private readonly options: { ready?: Promise<void>; fault?: unknown } = {}) {}

    get ready(): Promise<void> {
      this.readyReads++;
      return this.options.ready ?? Promise.resolve();
    }

    decodeGltfBuffer(target: Uint8Array, count: number, size: number, source: Uint8Array, mode: string, filter?: string): void {
      this.calls.push({ bytes: target.length, count, stride: size, source: Array.from(source), mode, filter });
      if ('fault' in this.options) throw this.options.fault;
      target.set(source.subarray(0, Math.min(source.length, target.length)));
    }
  }

  const P = 'bufferViews[0].extensions.EXT_meshopt_compression';
  const views = (...m: Json[]) => file({ bufferViews: m.map((e) => ({ buffer: 1, byteLength: 8, extensions: { EXT_meshopt_compression: e } })) });
  /** A view of 2 elements of 4 bytes decoded from buffers[0]'s 4 bytes. */
  const M = { buffer: 0, byteLength: 4, byteStride: 4, count: 2, mode: 'ATTRIBUTES' };
  const ONE = [Uint8Array.of(1, 2, 3, 4)];

  it('lists the views carrying the extension with their index, and refuses any level that is not an object by its path', async () => {
    const m = { buffer: 0 };
    expect(meshoptViews(file({ bufferViews: [{ buffer: 0 }, { extensions: { OTHER: {} } }, { extensions: { EXT_meshopt_compression: m } }] })))
      .toEqual([[2, m]]);
    expect(meshoptViews(file({}))).toEqual([]);
    expect(await refusal(() => meshoptViews(file({ bufferViews: [{}, 5] })))).toEqual({
      path: 'bufferViews[1]', message: 'bufferViews[1] is not an object',
    });
    expect(await refusal(() => meshoptViews(file({ bufferViews: [{}, { extensions: 3 }] })))).toEqual({
      path: 'bufferViews[1].extensions', message: 'bufferViews[1].extensions is not an object',
    });
    expect(await refusal(() => meshoptViews(file({ bufferViews: [{}, { extensions: { EXT_meshopt_compression: true } }] })))).toEqual({
      path: 'bufferViews[1].extensions.EXT_meshopt_compression', message: 'bufferViews[1].extensions.EXT_meshopt_compression is not an object',
    });
  });

  it('takes a buffer as a fallback only when its extension says fallback: true, and refuses a non-object by its path', async () => {
    const f = file({});
    const buffer = (extensions: unknown) => ({ byteLength: 4, extensions });
    expect(isFallback(f, { byteLength: 4 }, 'buffers[2]')).toBe(false);
    expect(isFallback(f, buffer({ OTHER: { fallback: true } }), 'buffers[2]')).toBe(false);
    expect(isFallback(f, buffer({ EXT_meshopt_compression: {} }), 'buffers[2]')).toBe(false);
    expect(isFallback(f, buffer({ EXT_meshopt_compression: { fallback: 'true' } }), 'buffers[2]')).toBe(false);
    expect(isFallback(f, buffer({ EXT_meshopt_compression: { fallback: true } }), 'buffers[2]')).toBe(true);
    expect(await refusal(() => isFallback(f, buffer(3), 'buffers[2]'))).toEqual({
      path: 'buffers[2].extensions', message: 'buffers[2].extensions is not an object',
    });
    expect(await refusal(() => isFallback(f, buffer({ EXT_meshopt_compression: 1 }), 'buffers[2]'))).toEqual({
      path: 'buffers[2].extensions.EXT_meshopt_compression', message: 'buffers[2].extensions.EXT_meshopt_compression is not an object',
    });
  });

  it('does not touch the decoder, not even its readiness, for a file without such a view', async () => {
    const decoder = new FakeMeshopt();
    expect(entries(await decodeMeshopt(file({ bufferViews: [{ buffer: 0, byteLength: 4 }] }), ONE, decoder))).toEqual([]);
    expect(decoder.readyReads).toBe(0);
    expect(decoder.calls).toEqual([]);
  });

  it('waits for the decoder, then hands it each view\'s range of its buffer, count, stride, mode and filter (NONE by default)', async () => {
    let go = () => {};
    const decoder = new FakeMeshopt({ ready: new Promise<void>((resolve) => { go = resolve; }) });
    const buffers = [Uint8Array.of(1, 2, 3, 4, 5, 6), Uint8Array.of(10, 11, 12, 13, 14, 15, 16, 17)];
    // View 1 reads buffers[1] to its very end; view 2 buffers[0] from its start (no byteOffset).
    const f = file({
      bufferViews: [
        { buffer: 0, byteLength: 6 },
        { extensions: { EXT_meshopt_compression: { buffer: 1, byteOffset: 2, byteLength: 6, byteStride: 4, count: 3, mode: 'ATTRIBUTES' } } },
        { extensions: { EXT_meshopt_compression: { buffer: 0, byteLength: 2, byteStride: 2, count: 2, mode: 'INDICES', filter: 'OCTAHEDRAL' } } },
      ],
    });
    const decoded = decodeMeshopt(f, buffers, decoder);
    await Promise.resolve();
    expect(decoder.calls).toEqual([]);
    go();
    expect(entries(await decoded)).toEqual([[1, [12, 13, 14, 15, 16, 17, 0, 0, 0, 0, 0, 0]], [2, [1, 2, 0, 0]]]);
    expect(decoder.readyReads).toBe(1);
    expect(decoder.calls).toEqual([
      { bytes: 12, count: 3, stride: 4, source: [12, 13, 14, 15, 16, 17], mode: 'ATTRIBUTES', filter: 'NONE' },
      { bytes: 4, count: 2, stride: 2, source: [1, 2], mode: 'INDICES', filter: 'OCTAHEDRAL' },
    ]);
  });

  it('passes every meshopt mode and filter as the file says', async () => {
    const modes = ['ATTRIBUTES', 'TRIANGLES', 'INDICES'];
    const filters = ['NONE', 'OCTAHEDRAL', 'QUATERNION', 'EXPONENTIAL', 'COLOR'];
    const pairs = modes.flatMap((mode) => filters.map((filter) => ({ mode, filter })));
    const decoder = new FakeMeshopt();
    expect((await decodeMeshopt(views(...pairs.map((p) => ({ ...M, ...p }))), ONE, decoder)).size).toBe(15);
    expect(decoder.calls.map(({ mode, filter }) => ({ mode, filter }))).toEqual(pairs);
  });

  it('refuses a buffer index past the buffers and a range past its buffer\'s end, with the numbers', async () => {
    expect(await refusal(() => decodeMeshopt(views({ ...M, buffer: 1 }), ONE, new FakeMeshopt()))).toEqual({
      path: `${P}.buffer`, message: 'buffers[1] does not exist (buffers has 1)',
    });
    expect(await refusal(() => decodeMeshopt(views({ ...M, byteOffset: 1 }), ONE, new FakeMeshopt()))).toEqual({
      path: P, message: `${P} (bytes 1 to 5) runs past the end of buffers[0] (4 bytes)`,
    });
    expect(await refusal(() => decodeMeshopt(views({ ...M, byteStride: 257 }), ONE, new FakeMeshopt()))).toEqual({
      path: `${P}.byteStride`, message: `${P}.byteStride is 257, above 256`,
    });
  });

  it('refuses a mode or filter meshopt does not have, quoting at most 30 characters of it', async () => {
    const cases: [Json, string, string][] = [
      [{ mode: 'triangles' }, `${P}.mode`, `${P}.mode is "triangles", not ATTRIBUTES, TRIANGLES or INDICES`],
      [{ mode: 'TRIANGLES'.repeat(5) }, `${P}.mode`, `${P}.mode is "TRIANGLESTRIANGLESTRIANGLESTR, not ATTRIBUTES, TRIANGLES or INDICES`],
      [{ mode: undefined }, `${P}.mode`, `${P}.mode is missing, not a string`],
      [{ filter: 'octahedral' }, `${P}.filter`, `${P}.filter is "octahedral", not a meshopt filter`],
      [{ filter: 'EXPONENTIAL'.repeat(3) }, `${P}.filter`, `${P}.filter is "EXPONENTIALEXPONENTIALEXPONEN, not a meshopt filter`],
    ];
    for (const [change, path, message] of cases) {
      const decoder = new FakeMeshopt();
      expect(await refusal(() => decodeMeshopt(views({ ...M, ...change }), ONE, decoder)), JSON.stringify(change)).toEqual({ path, message });
      expect(decoder.calls).toEqual([]);
    }
  });

  it('decodes count × stride bytes up to exactly 2^29 and refuses one element more before calling the decoder', async () => {
    expect(MAX_DECODED_BYTES).toBe(2 ** 29);
    // The operating system hands out the 512 MB as untouched zero pages: the fake writes only the source's 4 bytes.
    const decoder = new FakeMeshopt();
    const big = await decodeMeshopt(views({ ...M, byteStride: 256, count: 2 ** 21 }), ONE, decoder);
    expect(big.get(0)?.length).toBe(2 ** 29);
    expect(decoder.calls.map(({ bytes, count, stride }) => ({ bytes, count, stride }))).toEqual([{ bytes: 2 ** 29, count: 2 ** 21, stride: 256 }]);
    const refused = new FakeMeshopt();
    expect(await refusal(() => decodeMeshopt(views({ ...M, byteStride: 256, count: 2 ** 21 + 1 }), ONE, refused))).toEqual({
      path: P, message: `${P} decodes to 536871168 bytes, above the 536870912 read`,
    });
    expect(refused.calls).toEqual([]);
  });

  it('refuses a stream the decoder throws on, with its message or the thrown value as text', async () => {
    expect(await refusal(() => decodeMeshopt(views(M), ONE, new FakeMeshopt({ fault: new RangeError('index out of range') })))).toEqual({
      path: P, message: `${P} does not decode (index out of range)`,
    });
    expect(await refusal(() => decodeMeshopt(views(M), ONE, new FakeMeshopt({ fault: 'malformed' })))).toEqual({
      path: P, message: `${P} does not decode (malformed)`,
    });
  });
});

describe('KHR_draco_mesh_compression', () => {
  type Decoder = InstanceType<DracoModule['Decoder']>;
  type Named = { name: string };

  /**
   * What every fake decoder decodes any stream to: `points` points, `faces` triangles (`triangles`), an attribute for each
   * unique id `components` lists (its component count). `error`: the status's message instead; `abort`: a method that throws.
   */
  interface Stream {
    points: number;
    faces: number;
    components?: Readonly<Record<number, number>>;
    triangles?: number[];
    error?: string;
    abort?: string;
  }

  /** The bytes the fake writes for attribute `id`: its offset plus 50 per id, so two attributes never agree. */
  const written = (id: number, bytes: number) => Array.from({ length: bytes }, (_, k) => (50 * id + k) & 255);

  /** draco3d's module in plain TypeScript: a heap of 400 bytes, a bump allocator, every call logged as text. */
  class FakeDraco implements DracoModule {
    readonly HEAPU8 = new Uint8Array(400);
    readonly DT_INT8 = 1; readonly DT_UINT8 = 2; readonly DT_INT16 = 3; readonly DT_UINT16 = 4; readonly DT_UINT32 = 6; readonly DT_FLOAT32 = 9;
    readonly log: string[] = [];
    readonly DecoderBuffer = class { Init(): void {} };
    readonly Decoder: new () => Decoder;
    readonly Mesh: new () => Named & { num_points(): number; num_faces(): number };
    private next = 16;

    constructor(stream: Stream) {
      const fake = this;
      const name = (o: object) => (o as Named).name;
      const call = (method: string, text: string) => {
        fake.log.push(text);
        if (stream.abort === method) throw new Error(`abort in ${method}`);
      };
      let meshes = 0;
      let decoders = 0;
      this.Mesh = class {
        readonly name = `mesh${++meshes}`;
        num_points(): number { return stream.points; }
        num_faces(): number { return stream.faces; }
      };
      this.Decoder = class {
        readonly name = `decoder${++decoders}`;
        DecodeArrayToMesh(data: Int8Array, length: number, mesh: object) {
          call('DecodeArrayToMesh', `${this.name}.DecodeArrayToMesh([${data.join(',')}], ${length}, ${name(mesh)})`);
          return { ok: () => stream.error === undefined, error_msg: () => stream.error ?? '' };
        }
        GetAttributeByUniqueId(mesh: object, id: number) {
          call('GetAttributeByUniqueId', `${this.name}.GetAttributeByUniqueId(${name(mesh)}, ${JSON.stringify(id)})`);
          const components = stream.components?.[id];
          return components === undefined ? null : { name: `attribute ${id}`, id, num_components: () => components };
        }
        GetAttributeDataArrayForAllPoints(mesh: object, attribute: object, type: number, bytes: number, ptr: number): boolean {
          const dt = Object.entries(fake).find(([k, v]) => k.startsWith('DT_') && v === type)?.[0] ?? String(type);
          const args = `${name(mesh)}, ${name(attribute)}, ${dt}, ${bytes}, ${ptr}`;
          call('GetAttributeDataArrayForAllPoints', `${this.name}.GetAttributeDataArrayForAllPoints(${args})`);
          fake.HEAPU8.set(written((attribute as { id: number }).id, bytes), ptr);
          return true;
        }
        GetTrianglesUInt32Array(mesh: object, bytes: number, ptr: number): boolean {
          call('GetTrianglesUInt32Array', `${this.name}.GetTrianglesUInt32Array(${name(mesh)}, ${bytes}, ${ptr})`);
          const heap = new DataView(fake.HEAPU8.buffer);
          for (let i = 0; i < bytes / 4; i++) heap.setUint32(ptr + 4 * i, stream.triangles![i], true);
          return true;
        }
      };
    }

    _malloc(bytes: number): number {
      const ptr = this.next;
      this.next += Math.ceil(bytes / 8) * 8;
      this.log.push(`_malloc(${bytes}) = ${ptr}`);
      return ptr;
    }

    _free(ptr: number): void {
      this.log.push(`_free(${ptr})`);
    }

    destroy(o: object): void {
      this.log.push(`destroy(${(o as Named).name})`);
    }
  }

  const AT = 'meshes[0].primitives[0].extensions.KHR_draco_mesh_compression';
  /** buffers[0]; bufferViews[0] is its bytes 2 to 5, the stream the fake "decodes". */
  const BUFFERS = [Uint8Array.of(9, 9, 1, 2, 3, 250)];
  /** POSITION (accessor 0, Draco id 0) as float VEC3, TEXCOORD_0 (1, id 1) as normalized unsigned-short VEC2, indices (2). */
  const ACCESSORS: Json[] = [
    { componentType: 5126, count: 4, type: 'VEC3' },
    { componentType: 5123, count: 4, type: 'VEC2', normalized: true },
    { componentType: 5123, count: 6, type: 'SCALAR' },
  ];
  const MESH: Stream = { points: 4, faces: 2, components: { 0: 3, 1: 2 }, triangles: [0, 1, 2, 2, 1, 3] };

  /** A file of one Draco primitive: the default's fields with `primitive`'s, its extension's with `ext`'s. */
  function dracoFile(accessors: unknown[], primitive: Json = {}, ext: Json = {}): GltfFile {
    const p = {
      attributes: { POSITION: 0, TEXCOORD_0: 1 }, indices: 2, ...primitive,
      extensions: { KHR_draco_mesh_compression: { bufferView: 0, attributes: { POSITION: 0, TEXCOORD_0: 1 }, ...ext } },
    };
    return file({
      meshes: [{ primitives: [p] }], accessors, buffers: [{ byteLength: 6 }], bufferViews: [{ buffer: 0, byteOffset: 2, byteLength: 4 }],
    });
  }

  /** The path and message `decodeDraco` refuses the file with, and the fake's log. */
  async function refused(f: GltfFile, stream: Stream = MESH): Promise<{ path: string | undefined; message: string; log: string[] }> {
    const draco = new FakeDraco(stream);
    return { ...await refusal(() => decodeDraco(f, BUFFERS, draco)), log: draco.log };
  }

  it('lists the primitives carrying the extension, skipping a mesh whose primitives are not a list', () => {
    const ext = { bufferView: 0, attributes: {} };
    const primitive = { attributes: {}, extensions: { KHR_draco_mesh_compression: ext } };
    const meshes = [{}, { primitives: 'all' }, { primitives: [{ attributes: {} }, { extensions: {} }, primitive] }];
    expect(dracoPrimitives(file({ meshes }))).toEqual([{ path: 'meshes[2].primitives[2]', primitive, ext }]);
  });

  it('refuses a mesh, primitive, extensions or extension that is not an object, by its path', async () => {
    const cases: [unknown[], string][] = [
      [[{ primitives: [] }, 5], 'meshes[1]'],
      [[{ primitives: [{}, 5] }], 'meshes[0].primitives[1]'],
      [[{ primitives: [{}, { extensions: 3 }] }], 'meshes[0].primitives[1].extensions'],
      [[{ primitives: [{}, { extensions: { KHR_draco_mesh_compression: true } }] }], 'meshes[0].primitives[1].extensions.KHR_draco_mesh_compression'],
    ];
    for (const [meshes, path] of cases) {
      expect(await refusal(() => dracoPrimitives(file({ meshes })))).toEqual({ path, message: `${path} is not an object` });
    }
  });

  it('decodes each listed attribute and the indices into the accessors\' layout, freeing and destroying all it made', () => {
    const draco = new FakeDraco(MESH);
    const out = decodeDraco(dracoFile(ACCESSORS), BUFFERS, draco);
    expect(entries(out)).toEqual([[0, written(0, 48)], [1, written(1, 16)], [2, [0, 0, 1, 0, 2, 0, 2, 0, 1, 0, 3, 0]]]);
    expect(draco.log).toEqual([
      'decoder1.DecodeArrayToMesh([1,2,3,-6], 4, mesh1)',
      'decoder1.GetAttributeByUniqueId(mesh1, 0)',
      '_malloc(48) = 16',
      'decoder1.GetAttributeDataArrayForAllPoints(mesh1, attribute 0, DT_FLOAT32, 48, 16)',
      '_free(16)',
      'decoder1.GetAttributeByUniqueId(mesh1, 1)',
      '_malloc(16) = 64',
      'decoder1.GetAttributeDataArrayForAllPoints(mesh1, attribute 1, DT_UINT16, 16, 64)',
      '_free(64)',
      '_malloc(24) = 80',
      'decoder1.GetTrianglesUInt32Array(mesh1, 24, 80)',
      '_free(80)',
      'destroy(mesh1)',
      'destroy(decoder1)',
    ]);
    const none = new FakeDraco(MESH);
    expect(entries(decodeDraco(file({ meshes: [{ primitives: [{ attributes: {} }] }] }), BUFFERS, none))).toEqual([]);
    expect(none.log).toEqual([]);
  });

  it('gives every component type and size points × components × bytes, asked for as the matching Draco data type', () => {
    const types: [number, string, number][] = [
      [5120, 'DT_INT8', 1], [5121, 'DT_UINT8', 1], [5122, 'DT_INT16', 2], [5123, 'DT_UINT16', 2], [5125, 'DT_UINT32', 4], [5126, 'DT_FLOAT32', 4],
    ];
    const sizes: [string, number][] = [['SCALAR', 1], ['VEC2', 2], ['VEC3', 3], ['VEC4', 4]];
    for (const [componentType, dt, bytes] of types) {
      for (const [type, size] of sizes) {
        const draco = new FakeDraco({ points: 3, faces: 0, components: { 7: size } });
        const f = dracoFile([{ componentType, count: 3, type }], { attributes: { COLOR_0: 0 }, indices: undefined }, { attributes: { COLOR_0: 7 } });
        const n = 3 * size * bytes;
        expect(entries(decodeDraco(f, BUFFERS, draco)), `${componentType} ${type}`).toEqual([[0, written(7, n)]]);
        expect(draco.log[3], `${componentType} ${type}`).toBe(`decoder1.GetAttributeDataArrayForAllPoints(mesh1, attribute 7, ${dt}, ${n}, 16)`);
      }
    }
  });

  it('packs the indices as the index accessor declares them: 32, 16 or 8 bits, little-endian', () => {
    const cases: [number, number[], number[]][] = [
      [5125, [0, 65537, 2], [0, 0, 0, 0, 1, 0, 1, 0, 2, 0, 0, 0]],
      [5123, [0, 257, 2], [0, 0, 1, 1, 2, 0]],
      [5121, [0, 1, 2], [0, 1, 2]],
    ];
    for (const [componentType, triangles, bytes] of cases) {
      const draco = new FakeDraco({ points: 3, faces: 1, triangles });
      const f = dracoFile([{ componentType, count: 3, type: 'SCALAR' }], { attributes: {}, indices: 0 }, { attributes: {} });
      expect(entries(decodeDraco(f, BUFFERS, draco)), String(componentType)).toEqual([[0, bytes]]);
      expect(draco.log).toEqual([
        'decoder1.DecodeArrayToMesh([1,2,3,-6], 4, mesh1)', '_malloc(12) = 16', 'decoder1.GetTrianglesUInt32Array(mesh1, 12, 16)', '_free(16)',
        'destroy(mesh1)', 'destroy(decoder1)',
      ]);
    }
  });

  it('decodes no indices for a primitive without, and skips an attribute of the stream the primitive does not list', () => {
    const draco = new FakeDraco(MESH);
    const out = decodeDraco(dracoFile(ACCESSORS, { attributes: { TEXCOORD_0: 1 }, indices: undefined }), BUFFERS, draco);
    expect(entries(out)).toEqual([[1, written(1, 16)]]);
    expect(draco.log).toEqual([
      'decoder1.DecodeArrayToMesh([1,2,3,-6], 4, mesh1)',
      'decoder1.GetAttributeByUniqueId(mesh1, 1)',
      '_malloc(16) = 16',
      'decoder1.GetAttributeDataArrayForAllPoints(mesh1, attribute 1, DT_UINT16, 16, 16)',
      '_free(16)',
      'destroy(mesh1)',
      'destroy(decoder1)',
    ]);
    // A stream attribute named like a property every object inherits is not listed by the primitive either.
    const inherited = new FakeDraco(MESH);
    const only = decodeDraco(dracoFile(ACCESSORS, { attributes: { TEXCOORD_0: 1 }, indices: undefined }, { attributes: { TEXCOORD_0: 1, constructor: 0 } }), BUFFERS, inherited);
    expect(entries(only)).toEqual([[1, written(1, 16)]]);
  });

  it('refuses a stream that does not decode with the decoder\'s message, and destroys the mesh and decoder', async () => {
    expect(await refused(dracoFile(ACCESSORS), { ...MESH, error: 'Unknown geometry type' })).toEqual({
      path: AT, message: `${AT} does not decode (Unknown geometry type)`,
      log: ['decoder1.DecodeArrayToMesh([1,2,3,-6], 4, mesh1)', 'destroy(mesh1)', 'destroy(decoder1)'],
    });
  });

  it('frees the memory and destroys the mesh and decoder when the decoder throws while filling it', () => {
    const draco = new FakeDraco({ ...MESH, abort: 'GetAttributeDataArrayForAllPoints' });
    expect(() => decodeDraco(dracoFile(ACCESSORS), BUFFERS, draco)).toThrow(new Error('abort in GetAttributeDataArrayForAllPoints'));
    expect(draco.log.slice(2)).toEqual([
      '_malloc(48) = 16',
      'decoder1.GetAttributeDataArrayForAllPoints(mesh1, attribute 0, DT_FLOAT32, 48, 16)',
      '_free(16)',
      'destroy(mesh1)',
      'destroy(decoder1)',
    ]);
  });

  it('refuses a view past the bufferViews, and attribute maps or accessor indices that are not ones, by their paths', async () => {
    const before = ['decoder1.DecodeArrayToMesh([1,2,3,-6], 4, mesh1)'];
    const after = ['destroy(mesh1)', 'destroy(decoder1)'];
    expect(await refused(dracoFile(ACCESSORS, {}, { bufferView: 1 }))).toEqual({
      path: `${AT}.bufferView`, message: 'bufferViews[1] does not exist (bufferViews has 1)', log: [],
    });
    expect(await refused(dracoFile(ACCESSORS, {}, { attributes: [0] }))).toEqual({
      path: `${AT}.attributes`, message: `${AT}.attributes is not an object`, log: [...before, ...after],
    });
    expect(await refused(dracoFile(ACCESSORS, { attributes: 'POSITION' }))).toEqual({
      path: 'meshes[0].primitives[0].attributes', message: 'meshes[0].primitives[0].attributes is not an object', log: [...before, ...after],
    });
    expect(await refused(dracoFile(ACCESSORS, { attributes: { POSITION: 0.5, TEXCOORD_0: 1 } }))).toEqual({
      path: 'meshes[0].primitives[0].attributes.POSITION', message: 'meshes[0].primitives[0].attributes.POSITION is 0.5, not an index or count',
      log: [...before, ...after],
    });
  });

  it('refuses an attribute the stream lacks by its name, asking for id -1 when the file\'s id is not a number', async () => {
    expect(await refused(dracoFile(ACCESSORS, {}, { attributes: { POSITION: 0, TEXCOORD_0: 5 } }))).toMatchObject({
      path: `${AT}.attributes.TEXCOORD_0`, message: `${AT} has no attribute 5 for TEXCOORD_0`,
    });
    const r = await refused(dracoFile(ACCESSORS, {}, { attributes: { POSITION: '0' } }));
    expect(r).toEqual({
      path: `${AT}.attributes.POSITION`, message: `${AT} has no attribute "0" for POSITION`,
      log: ['decoder1.DecodeArrayToMesh([1,2,3,-6], 4, mesh1)', 'decoder1.GetAttributeByUniqueId(mesh1, -1)', 'destroy(mesh1)', 'destroy(decoder1)'],
    });
  });

  it('refuses an accessor that is missing, or of a type or component type a Draco primitive cannot fill', async () => {
    const one = (accessor: unknown) => dracoFile([accessor], { attributes: { POSITION: 0 }, indices: undefined }, { attributes: { POSITION: 0 } });
    const fill = (a: string) => ({ path: a, message: `${a} is not a type a Draco primitive can fill` });
    expect(await refusal(() => decodeDraco(dracoFile([]), BUFFERS, new FakeDraco(MESH)))).toEqual({
      path: 'accessors[0]', message: 'accessors[0] does not exist (accessors has 0)',
    });
    expect(await refusal(() => decodeDraco(one(5), BUFFERS, new FakeDraco(MESH)))).toEqual({
      path: 'accessors[0]', message: 'accessors[0] is not an object',
    });
    const cases: [Json, { path: string; message: string }][] = [
      [{ count: 4, type: 'VEC3' }, { path: 'accessors[0].componentType', message: 'accessors[0].componentType is missing, not a number' }],
      [{ componentType: 5126, type: 'VEC3' }, { path: 'accessors[0].count', message: 'accessors[0].count is missing, not a number' }],
      [{ componentType: 5124, count: 4, type: 'VEC3' }, fill('accessors[0]')],
      [{ componentType: 5126, count: 4, type: 'MAT4' }, fill('accessors[0]')],
      [{ componentType: 5126, count: 4 }, fill('accessors[0]')],
      // A name every object inherits is no accessor type.
      [{ componentType: 5126, count: 4, type: 'constructor' }, fill('accessors[0]')],
      [{ componentType: 5126, count: 4, type: 'toString' }, fill('accessors[0]')],
    ];
    for (const [accessor, expected] of cases) {
      const r = await refused(one(accessor));
      expect(r, JSON.stringify(accessor)).toMatchObject(expected);
      expect(r.log.slice(-2)).toEqual(['destroy(mesh1)', 'destroy(decoder1)']);
      expect(r.log.filter((c) => c.startsWith('_malloc'))).toEqual([]);
    }
    // The index accessor goes through the same layout, by its own index.
    const indices = dracoFile([...ACCESSORS.slice(0, 2), { componentType: 5123, count: 6, type: 'VEC5' }]);
    expect(await refusal(() => decodeDraco(indices, BUFFERS, new FakeDraco(MESH)))).toEqual(fill('accessors[2]'));
  });

  it('refuses an accessor count that is not the stream\'s point count, or its triangle count × 3 for the indices', async () => {
    const wrong = (i: number, count: number) => ACCESSORS.map((a, k) => (k === i ? { ...a, count } : a));
    expect(await refused(dracoFile(wrong(1, 5)))).toMatchObject({
      path: 'accessors[1].count', message: 'accessors[1].count is 5, the Draco mesh has 4 points',
    });
    const r = await refused(dracoFile(wrong(2, 2)));
    expect(r).toMatchObject({ path: 'accessors[2].count', message: 'accessors[2].count is 2, the Draco mesh has 6 indices' });
    expect(r.log.slice(-3)).toEqual(['_free(64)', 'destroy(mesh1)', 'destroy(decoder1)']);
  });
});
