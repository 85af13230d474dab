// Broken glTF files (docs/gltf.md#errors): each is refused with a LoadError naming the file and the
// place (the JSON path, or the GLB chunk), or read with a warning where the rest can be drawn —
// never a TypeError, never a read past the end, never an allocation of a declared size the file
// does not have. Each case starts from a valid model and breaks one thing.
import { describe, expect, it } from 'vitest';
import { LoadError } from '../../src/loaders/load-error';
import { MAX_ELEMENTS } from '../../src/loaders/gltf/accessors';
import { instrumented } from './helpers/collections';
import { glbBin, glbJson, glbOf, makeGlb, newDocument, parse, primitive } from './helpers/gltf';

const TRI = [0, 0, 0, 1, 0, 0, 0, 1, 0];

/** A valid indexed triangle as (json, bin) to break. */
async function valid(): Promise<{ json: Record<string, any>; bin: Uint8Array }> {
  const { doc, root } = newDocument();
  root.setMesh(doc.createMesh().addPrimitive(primitive(doc, TRI, [0, 1, 2])));
  const glb = await glbOf(doc);
  return { json: glbJson(glb), bin: glbBin(glb).slice() };
}

/** The LoadError `bytes` is refused with: its path and message. */
function refusal(bytes: Uint8Array, url = 'broken.glb'): { path: string | undefined; message: string } {
  try {
    parse(bytes, url);
  } catch (e) {
    expect(e).toBeInstanceOf(LoadError);
    const err = e as LoadError;
    expect(err.url).toBe(url);
    expect(err.message).toContain(url);
    return { path: err.path, message: err.detail.message };
  }
  throw new Error('read without an error');
}

const positionAccessor = (json: Record<string, any>) => json.meshes[0].primitives[0].attributes.POSITION as number;
const indexAccessor = (json: Record<string, any>) => json.meshes[0].primitives[0].indices as number;

describe('GLB containers that are cut short or lie about their sizes', () => {
  it('refuses a GLB whose header, chunk header or chunk runs past the end of the file', async () => {
    const { json, bin } = await valid();
    const glb = makeGlb(json, bin);
    expect(refusal(glb.subarray(0, 10))).toMatchObject({ path: 'GLB header' });
    expect(refusal(glb.subarray(0, glb.length - 4))).toMatchObject({ path: 'GLB header', message: expect.stringContaining('truncated') });
    // The header's length made to match a cut file: then the BIN chunk is what runs past the end.
    const cut = glb.slice(0, glb.length - 4);
    new DataView(cut.buffer).setUint32(8, cut.length, true);
    expect(refusal(cut)).toMatchObject({ path: expect.stringMatching(/^GLB chunk 1/), message: expect.stringContaining('truncated') });
    const jsonCut = glb.slice(0, 24);
    new DataView(jsonCut.buffer).setUint32(8, 24, true);
    expect(refusal(jsonCut)).toMatchObject({ path: 'GLB chunk 0 (byte 12)' });
  });

  it('refuses a BIN chunk shorter than the buffer it holds, and a byteLength of 2 GB, without allocating it', async () => {
    const { json, bin } = await valid();
    json.buffers[0].byteLength = bin.length + 8;
    expect(refusal(makeGlb(json, bin))).toMatchObject({ path: 'buffers[0].byteLength' });
    json.buffers[0].byteLength = 2 ** 31;
    expect(refusal(makeGlb(json, bin))).toMatchObject({ path: 'buffers[0].byteLength', message: expect.stringContaining('2147483648') });
  });

  it('refuses an HTML page, JSON that is not glTF, and glTF 1.0', () => {
    const text = (s: string) => new TextEncoder().encode(s);
    expect(refusal(text('<!doctype html><title>404</title>'), 'a.gltf')).toMatchObject({ path: 'JSON' });
    expect(refusal(text('[1, 2]'), 'a.gltf')).toMatchObject({ path: 'JSON' });
    expect(refusal(text('{"hello": 1}'), 'a.gltf')).toMatchObject({ path: 'asset' });
    expect(refusal(text('{"asset": {"version": "1.0"}}'), 'a.gltf')).toMatchObject({ path: 'asset.version' });
  });
});

describe('accessors and buffer views past their data', () => {
  it('refuses an accessor that reads past its buffer view, and a view past its buffer', async () => {
    const { json, bin } = await valid();
    json.accessors[positionAccessor(json)].count = 4;
    expect(refusal(makeGlb(json, bin))).toMatchObject({ path: `accessors[${positionAccessor(json)}]` });
    const again = await valid();
    const view = again.json.accessors[positionAccessor(again.json)].bufferView;
    again.json.bufferViews[view].byteLength += 4096;
    expect(refusal(makeGlb(again.json, again.bin))).toMatchObject({ path: `bufferViews[${view}]` });
  });

  it('refuses a missing accessor, buffer view or buffer by the path that names it', async () => {
    const { json, bin } = await valid();
    json.meshes[0].primitives[0].attributes.POSITION = 7;
    expect(refusal(makeGlb(json, bin))).toMatchObject({ path: 'meshes[0].primitives[0].attributes.POSITION', message: expect.stringContaining('accessors[7]') });
    const b = await valid();
    b.json.accessors[0].bufferView = 9;
    expect(refusal(makeGlb(b.json, b.bin))).toMatchObject({ path: 'accessors[0].bufferView' });
    const c = await valid();
    c.json.bufferViews[0].buffer = 3;
    expect(refusal(makeGlb(c.json, c.bin))).toMatchObject({ path: 'bufferViews[0].buffer' });
  });

  it('refuses an index past the vertex count, naming the index accessor', async () => {
    const { json, bin } = await valid();
    const at = json.bufferViews[json.accessors[indexAccessor(json)].bufferView].byteOffset ?? 0;
    new DataView(bin.buffer).setUint16(at + 2, 3, true);
    expect(refusal(makeGlb(json, bin))).toMatchObject({ path: `accessors[${indexAccessor(json)}]`, message: expect.stringContaining('is 3') });
  });

  it('refuses an accessor of a huge count with no buffer view before allocating it', async () => {
    const { json, bin } = await valid();
    delete json.accessors[indexAccessor(json)].bufferView;
    json.accessors[indexAccessor(json)].count = MAX_ELEMENTS + 1;
    expect(refusal(makeGlb(json, bin))).toMatchObject({ path: `accessors[${indexAccessor(json)}].count` });
    // As positions, the same count is refused sooner: by the vertex budget of the placed meshes.
    const b = await valid();
    delete b.json.accessors[positionAccessor(b.json)].bufferView;
    b.json.accessors[positionAccessor(b.json)].count = MAX_ELEMENTS + 1;
    expect(refusal(makeGlb(b.json, b.bin))).toMatchObject({ path: 'nodes[0]', message: expect.stringContaining('too large') });
  });

  it('refuses wrong types where a number, an object or a list is needed', async () => {
    for (const [field, value, path] of [
      ['count', '3', 'count'], ['componentType', 1234, 'componentType'], ['type', 'VEC7', 'type'], ['byteOffset', -4, 'byteOffset'],
    ] as const) {
      const { json, bin } = await valid();
      json.accessors[positionAccessor(json)][field] = value;
      expect(refusal(makeGlb(json, bin)), field).toMatchObject({ path: `accessors[${positionAccessor(json)}].${path}` });
    }
  });
});

describe('positions and node graphs a renderer cannot use', () => {
  it('draws what it can of NaN and 1e30 positions, with one warning naming the accessor', async () => {
    const { json, bin } = await valid();
    // Two more triangles, over the same three positions plus a NaN one and a 1e30 one.
    const quad = new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0, NaN, 0, 0, 1e30, 0, 0]);
    const positions = new Uint8Array(quad.buffer);
    const indices = new Uint8Array(new Uint16Array([0, 1, 2, 0, 3, 1, 4, 1, 2]).buffer);
    const data = new Uint8Array(positions.length + indices.length + 2);
    data.set(positions, 0);
    data.set(indices, positions.length);
    json.buffers = [{ byteLength: data.length }];
    json.bufferViews = [{ buffer: 0, byteOffset: 0, byteLength: positions.length }, { buffer: 0, byteOffset: positions.length, byteLength: indices.length }];
    json.accessors = [
      { bufferView: 0, componentType: 5126, count: 5, type: 'VEC3' },
      { bufferView: 1, componentType: 5123, count: 9, type: 'SCALAR' },
    ];
    json.meshes[0].primitives[0] = { attributes: { POSITION: 0 }, indices: 1 };
    void bin;
    const r = parse(makeGlb(json, data));
    expect(r.positions.length / 3).toBe(3); // flat: one triangle's three vertices
    expect(r.warnings).toEqual([{ path: 'meshes[0].primitives[0].attributes.POSITION', message: expect.stringContaining('2 triangles') }]);
  });

  it('refuses a node graph with a cycle, or a node with two parents, naming the second way to it', async () => {
    const { json, bin } = await valid();
    json.nodes.push({ children: [0] });
    json.nodes[0].children = [1];
    expect(refusal(makeGlb(json, bin))).toMatchObject({ path: 'nodes[1].children[0]', message: expect.stringContaining('nodes[0]') });
    const two = await valid();
    two.json.nodes.push({ children: [0] }, { children: [0] });
    two.json.scenes[0].nodes = [1, 2];
    expect(refusal(makeGlb(two.json, two.bin))).toMatchObject({ path: 'nodes[2].children[0]' });
  });

  // No speed is asserted (the bench measures); a recursive walk would overflow the stack, and a hang fails by the timeout.
  it('walks a million nodes in a chain without recursion', { timeout: 60_000 }, async () => {
    const { json, bin } = await valid();
    // Under Stryker's instrumentation (~100× slower) 100,000: still far deeper than a recursive walk survives.
    const n = instrumented ? 100_000 : 1_000_000;
    const mesh = json.nodes[0].mesh;
    json.nodes = Array.from({ length: n }, (_, i) => (i + 1 < n ? { children: [i + 1] } : { mesh }));
    json.scenes[0].nodes = [0];
    const r = parse(makeGlb(json, bin));
    expect(r.indices.length).toBe(3);
  });
});

describe('extensions', () => {
  it('refuses a required extension it does not read, naming it; warns once of an unused one', async () => {
    const { json, bin } = await valid();
    json.extensionsUsed = ['KHR_materials_volume', 'EXT_lights_image_based', 'KHR_mesh_quantization'];
    json.extensionsRequired = ['KHR_mesh_quantization', 'KHR_materials_volume'];
    expect(refusal(makeGlb(json, bin))).toMatchObject({ path: 'extensionsRequired[1]', message: 'the file requires KHR_materials_volume, which is not supported' });
    delete json.extensionsRequired;
    expect(parse(makeGlb(json, bin)).warnings.map((w) => w.message)).toEqual([
      'KHR_materials_volume is not supported: the file is drawn without it',
      'EXT_lights_image_based is not supported: the file is drawn without it',
    ]);
  });
});
