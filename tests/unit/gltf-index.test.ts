// The glTF reader's entry points (src/loaders/gltf/index.ts, docs/gltf.md#extensions and #errors)
// on files written by hand: the version accepted, every supported extension accepted when required
// and any other refused or warned, decoders asked for only when a file compresses something and
// named when they fail, the vertex budget at its exact edge, and the refusals of meshes.
import { describe, expect, it } from 'vitest';
import { LoadError } from '../../src/loaders/load-error';
import type { GltfDecoders } from '../../src/loaders/gltf/decoders';
import { decompressGltf, MAX_VERTICES, openGltf, readGltf, SUPPORTED_EXTENSIONS } from '../../src/loaders/gltf/index';

type Json = Record<string, unknown>;
const encode = (json: Json) => new TextEncoder().encode(JSON.stringify(json));
const open = (json: Json) => openGltf(encode({ asset: { version: '2.0' }, ...json }), 'x.gltf');
const read = (json: Json) => readGltf(open(json));

/** Three vertices of one triangle, little-endian float32, as a data: URI. */
const TRIANGLE = `data:application/octet-stream;base64,${Buffer.from(new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0]).buffer).toString('base64')}`;
/** A file whose meshes are `meshes`, their accessors reading the triangle (accessor 0: three vertices, 1: two). */
const withMeshes = (meshes: unknown[], nodes: unknown[] = meshes.map((_, i) => ({ mesh: i }))): Json => ({
  scenes: [{ nodes: nodes.map((_, i) => i) }], nodes, meshes,
  buffers: [{ byteLength: 36, uri: TRIANGLE }], bufferViews: [{ buffer: 0, byteLength: 36 }],
  accessors: [
    { bufferView: 0, componentType: 5126, count: 3, type: 'VEC3', min: [0, 0, 0], max: [1, 1, 0] },
    { bufferView: 0, componentType: 5126, count: 2, type: 'VEC3', min: [0, 0, 0], max: [1, 0, 0] },
  ],
});

async function refusalOf(run: () => unknown): Promise<{ path: string | undefined; message: string }> {
  try {
    await run();
  } catch (e) {
    expect(e).toBeInstanceOf(LoadError);
    return { path: (e as LoadError).path, message: (e as LoadError).detail.message };
  }
  throw new Error('read without an error');
}

describe('openGltf: version and extensions', () => {
  it('reads glTF 2.x, any minor version, and refuses anything else quoting it', async () => {
    for (const version of ['2.0', '2.1', '2.10']) expect(openGltf(encode({ asset: { version } }), 'x.gltf').file.json).toEqual({ asset: { version } });
    for (const version of ['1.0', '12.0', '2.0x', '2', '']) {
      expect(await refusalOf(() => openGltf(encode({ asset: { version } }), 'x.gltf'))).toEqual({
        path: 'asset.version', message: `asset.version is ${JSON.stringify(version)}: only glTF 2.x is read`,
      });
    }
    expect((await refusalOf(() => openGltf(encode({ asset: { version: `3.0-${'a'.repeat(30)}` } }), 'x.gltf'))).message)
      .toBe(`asset.version is "3.0-${'a'.repeat(15)}: only glTF 2.x is read`);
    expect(await refusalOf(() => openGltf(encode({ asset: {} }), 'x.gltf'))).toEqual({ path: 'asset.version', message: 'asset.version is missing, not a string' });
  });

  it('accepts every supported extension as required, and refuses any other naming it', async () => {
    expect(SUPPORTED_EXTENSIONS).toEqual([
      'EXT_meshopt_compression', 'KHR_draco_mesh_compression', 'KHR_mesh_quantization', 'KHR_texture_transform',
      'KHR_materials_emissive_strength', 'KHR_materials_unlit', 'EXT_texture_webp',
    ]);
    for (const name of SUPPORTED_EXTENSIONS) expect(open({ extensionsUsed: [name], extensionsRequired: [name] }).file.warnings).toEqual([]);
    expect(await refusalOf(() => open({ extensionsRequired: ['KHR_mesh_quantization', 'KHR_texture_basisu'] }))).toEqual({
      path: 'extensionsRequired[1]', message: 'the file requires KHR_texture_basisu, which is not supported',
    });
  });

  it('warns once, without refusing, of an unsupported extension that is used but not required', () => {
    expect(open({ extensionsUsed: ['KHR_materials_unlit', 'KHR_materials_sheen'] }).file.warnings).toEqual([
      { path: 'extensionsUsed', message: 'KHR_materials_sheen is not supported: the file is drawn without it' },
    ]);
  });

  it('refuses extension lists that are not lists of names', async () => {
    for (const [key, value] of [['extensionsUsed', 'KHR_materials_unlit'], ['extensionsRequired', [1]], ['extensionsUsed', ['KHR_materials_unlit', null]]] as const) {
      expect(await refusalOf(() => open({ [key]: value }))).toEqual({ path: key, message: `${key} is not a list of names` });
    }
  });
});

describe('decompressGltf', () => {
  const failing: GltfDecoders = { meshopt: () => Promise.reject(new Error('no meshopt')), draco: () => Promise.reject(new Error('no draco')) };

  it('asks for no decoder, and reads no buffer, when the file compresses nothing', async () => {
    // Buffer 0 is external and not handed in: reading it would be an error.
    await expect(decompressGltf(open({ buffers: [{ byteLength: 4, uri: 'away.bin' }] }), new Map(), failing)).resolves.toBeUndefined();
  });

  it('names the decoder that could not be loaded, and why', async () => {
    const buffers = [{ byteLength: 4, uri: 'data:application/octet-stream;base64,AAAAAA==' }];
    const meshopt = open({ buffers, bufferViews: [{ buffer: 0, byteLength: 4, extensions: { EXT_meshopt_compression: { buffer: 0, byteLength: 4, byteStride: 4, count: 1 } } }] });
    expect(await refusalOf(() => decompressGltf(meshopt, new Map(), failing))).toEqual({
      path: 'extensionsUsed', message: 'the meshopt decoder could not be loaded (no meshopt)',
    });
    const draco = open({ buffers, meshes: [{ primitives: [{ attributes: {}, extensions: { KHR_draco_mesh_compression: { bufferView: 0, attributes: {} } } }] }] });
    expect(await refusalOf(() => decompressGltf(draco, new Map(), { ...failing, draco: () => Promise.reject('a string') }))).toEqual({
      path: 'extensionsUsed', message: 'the Draco decoder could not be loaded (a string)',
    });
  });
});

describe('readGltf: meshes', () => {
  it('reads a triangle, leaving out a primitive with no whole triangle (no empty group for its material)', () => {
    const r = read({ ...withMeshes([{ primitives: [{ attributes: { POSITION: 1 }, material: 1 }, { attributes: { POSITION: 0 }, material: 0 }] }]), materials: [{}, {}] });
    expect([...r.indices]).toEqual([0, 1, 2]);
    expect(r.groups).toEqual([{ material: 0, start: 0, count: 3 }]);
  });

  it('refuses a file with no triangle, naming the meshes or, without any mesh placed, the scenes', async () => {
    expect(await refusalOf(() => read(withMeshes([{ primitives: [{ attributes: { POSITION: 1 } }] }])))).toEqual({
      path: 'meshes', message: 'the file has no triangles to draw',
    });
    expect(await refusalOf(() => read({ ...withMeshes([]), nodes: [{}], scenes: [{ nodes: [0] }] }))).toEqual({
      path: 'scenes', message: 'the file has no triangles to draw',
    });
  });

  it('names the node whose mesh is missing, and a mesh whose primitives are not a list of objects', async () => {
    expect(await refusalOf(() => read(withMeshes([{ primitives: [] }], [{ mesh: 0 }, { mesh: 4 }])))).toEqual({
      path: 'nodes[1].mesh', message: 'meshes[4] does not exist (meshes has 1)',
    });
    expect(await refusalOf(() => read(withMeshes([{ primitives: [] }, { primitives: {} }])))).toEqual({
      path: 'meshes[1].primitives', message: 'meshes[1].primitives is not an array',
    });
    expect(await refusalOf(() => read(withMeshes([{ primitives: [{ attributes: { POSITION: 0 } }, 3] }])))).toEqual({
      path: 'meshes[0].primitives[1]', message: 'meshes[0].primitives[1] is not an object',
    });
  });

  it('allows exactly MAX_VERTICES placed vertices and refuses one more, before reading any', async () => {
    const counted = (count: number) => {
      const json = withMeshes([{ primitives: [{ attributes: { POSITION: 0 } }] }]);
      (json.accessors as Json[])[0] = { ...(json.accessors as Json[])[0], count };
      return json;
    };
    const over = await refusalOf(() => read(counted(MAX_VERTICES + 1)));
    expect(over).toEqual({ path: 'nodes[0]', message: `the scene's meshes have over ${MAX_VERTICES} vertices once its nodes are placed: too large to draw` });
    // At the budget the accessor is read, and found longer than its buffer view.
    const at = await refusalOf(() => read(counted(MAX_VERTICES)));
    expect(at.message).not.toContain('too large to draw');
    expect(at.path).toMatch(/^accessors\[0\]/);
  });
});
