// Compressed glTF (docs/gltf.md#compression): EXT_meshopt_compression decoded by meshoptimizer's own
// decoder, loaded only when a file has such a view; a model written compressed reads as the same
// model written plain; a meshopt stream that does not decode is an error naming its view.
import { EXTMeshoptCompression, KHRDracoMeshCompression, KHRMeshQuantization } from '@gltf-transform/extensions';
import draco3d from 'draco3d';
import { MeshoptDecoder, MeshoptEncoder } from 'meshoptimizer';
import { readFileSync } from 'node:fs';
import { describe, expect, it, vi } from 'vitest';
import { decompressGltf, openGltf, readGltf } from '../../src/loaders/gltf';
import type { GltfDecoders } from '../../src/loaders/gltf/decoders';
import { LoadError } from '../../src/loaders/load-error';
import { NODE_DECODERS, accessor, glbBin, glbJson, io, makeGlb, newDocument, parse, parseDecoded, primitive, validationErrors } from './helpers/gltf';

const file = (name: string) => new Uint8Array(readFileSync(new URL(`../data/gltf/${name}`, import.meta.url)));

/** A box-like model of 8 positions with normals and UVs, 12 triangles. */
function model() {
  const { doc, root } = newDocument();
  const p = [-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1];
  const n = p.map((x) => x / Math.sqrt(3));
  const uv = Array.from({ length: 16 }, (_, i) => (i % 3) / 4);
  const indices = [0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4, 3, 7, 6, 3, 6, 2, 0, 4, 7, 0, 7, 3, 1, 2, 6, 1, 6, 5];
  root.setMesh(doc.createMesh().addPrimitive(primitive(doc, p, indices, {
    NORMAL: accessor(doc, 'VEC3', new Float32Array(n)), TEXCOORD_0: accessor(doc, 'VEC2', new Float32Array(uv)),
  })));
  return doc;
}

/** Each triangle rotated to start at its smallest index, in order. */
function triangles(indices: Uint32Array): number[][] {
  const out: number[][] = [];
  for (let t = 0; t < indices.length; t += 3) {
    const tri = [indices[t], indices[t + 1], indices[t + 2]];
    const k = tri.indexOf(Math.min(...tri));
    out.push([tri[k], tri[(k + 1) % 3], tri[(k + 2) % 3]]);
  }
  return out;
}

async function meshoptGlb(): Promise<Uint8Array> {
  await MeshoptEncoder.ready;
  const doc = model();
  // The FILTER method stores normals octahedrally in quantized bytes: KHR_mesh_quantization with it.
  doc.createExtension(KHRMeshQuantization).setRequired(true);
  doc.createExtension(EXTMeshoptCompression).setRequired(true).setEncoderOptions({ method: EXTMeshoptCompression.EncoderMethod.FILTER });
  const bytes = await io().registerDependencies({ 'meshopt.encoder': MeshoptEncoder, 'meshopt.decoder': MeshoptDecoder }).writeBinary(doc);
  expect(await validationErrors(bytes), 'the test model is valid glTF').toEqual([]);
  return bytes;
}

describe('EXT_meshopt_compression', () => {
  it('reads a model written with meshopt as the same model written plain (normals to their octahedral quantization)', async () => {
    const compressed = await meshoptGlb();
    const json = glbJson(compressed);
    expect(json.extensionsRequired).toContain('EXT_meshopt_compression');
    expect(json.bufferViews.some((v: { extensions?: object }) => v.extensions)).toBe(true);
    const plain = parse(await io().writeBinary(model()));
    const decoded = await parseDecoded(compressed);
    // The index codec may start a triangle at another corner: the same triangles, the same winding.
    expect(triangles(decoded.indices)).toEqual(triangles(plain.indices));
    expect(decoded.positions).toEqual(plain.positions);
    expect(decoded.uv0).toEqual(plain.uv0);
    // Octahedral normals of 8-bit components: each within 0.02 of the float normal.
    const worst = Math.max(...decoded.normals.map((v, i) => Math.abs(v - plain.normals[i])));
    expect(worst).toBeLessThan(0.02);
    expect(worst).toBeGreaterThan(0); // they are quantized: the test reads the filter, not a copy
  });

  it('reads gltfpack\'s duck (meshopt, 9-bit quantization, texture transform), its fallback buffer never read', async () => {
    const r = await parseDecoded(file('Duck-meshopt.glb'), 'Duck-meshopt.glb');
    expect(r.warnings).toEqual([]);
    expect(r.indices.length / 3).toBe(4212); // the Khronos duck's triangle count
    // Its node's matrix takes the 9-bit positions back to the Khronos duck's, scaled by 0.01: y from 0.1 to 1.6.
    let min = Infinity, max = -Infinity;
    for (let i = 1; i < r.positions.length; i += 3) { min = Math.min(min, r.positions[i]); max = Math.max(max, r.positions[i]); }
    expect([Number(min.toFixed(1)), Number(max.toFixed(1))]).toEqual([0.1, 1.6]);
    expect(r.materials[0].baseColorTexture?.transform).not.toBeNull();
  });

  it('loads the meshopt decoder only for a file that has a compressed view', async () => {
    const decoders: GltfDecoders = { meshopt: vi.fn(async () => MeshoptDecoder), draco: vi.fn(NODE_DECODERS.draco) };
    const plain = openGltf(await io().writeBinary(model()), 'plain.glb');
    await decompressGltf(plain, new Map(), decoders);
    expect(decoders.meshopt).not.toHaveBeenCalled();
    await decompressGltf(openGltf(await meshoptGlb(), 'packed.glb'), new Map(), decoders);
    expect(decoders.meshopt).toHaveBeenCalledTimes(1);
    expect(decoders.draco).not.toHaveBeenCalled();
  });

  it('refuses a compressed view that does not decode, or lies past its buffer, naming it; and a decoder that cannot load', async () => {
    const glb = await meshoptGlb();
    const json = glbJson(glb);
    const bin = glbBin(glb).slice();
    const index = json.bufferViews.findIndex((v: { extensions?: object }) => v.extensions);
    const ext = json.bufferViews[index].extensions.EXT_meshopt_compression;
    const refusal = async (bytes: Uint8Array, decoders?: GltfDecoders) => {
      const open = openGltf(bytes, 'bad.glb');
      const e = await decompressGltf(open, new Map(), decoders ?? NODE_DECODERS).then(() => readGltf(open)).then(() => null, (x: unknown) => x);
      expect(e).toBeInstanceOf(LoadError);
      return (e as LoadError).detail;
    };
    const zeroed = bin.slice();
    zeroed.fill(0xff, ext.byteOffset ?? 0, (ext.byteOffset ?? 0) + ext.byteLength);
    expect(await refusal(makeGlb(json, zeroed))).toMatchObject({ path: `bufferViews[${index}].extensions.EXT_meshopt_compression` });
    const past = structuredClone(json);
    past.bufferViews[index].extensions.EXT_meshopt_compression.byteLength = bin.length + 64;
    expect(await refusal(makeGlb(past, bin))).toMatchObject({ path: `bufferViews[${index}].extensions.EXT_meshopt_compression`, message: expect.stringContaining('past the end') });
    const failing: GltfDecoders = { ...NODE_DECODERS, meshopt: () => Promise.reject(new Error('blocked by CSP')) };
    expect(await refusal(glb, failing)).toMatchObject({ path: 'extensionsUsed', message: expect.stringContaining('blocked by CSP') });
  });
});

async function dracoGlb(): Promise<Uint8Array> {
  const doc = model();
  doc.createExtension(KHRDracoMeshCompression).setRequired(true).setEncoderOptions({ quantizationBits: { POSITION: 16, NORMAL: 12, TEX_COORD: 14 } } as never);
  const bytes = await io().registerDependencies({
    'draco3d.encoder': await draco3d.createEncoderModule(), 'draco3d.decoder': await draco3d.createDecoderModule(),
  }).writeBinary(doc);
  expect(await validationErrors(bytes), 'the test model is valid glTF').toEqual([]);
  return bytes;
}

/** Each triangle as its three positions (rounded), sorted: the same mesh whatever the point order. */
function shape(r: { positions: Float32Array; indices: Uint32Array }, digits = 3): string[] {
  const out: string[] = [];
  for (let t = 0; t < r.indices.length; t += 3) {
    const corners = [0, 1, 2].map((k) => [...r.positions.subarray(3 * r.indices[t + k], 3 * r.indices[t + k] + 3)].map((x) => x.toFixed(digits)).join(' '));
    const k = corners.indexOf([...corners].sort()[0]);
    out.push([corners[k], corners[(k + 1) % 3], corners[(k + 2) % 3]].join(' | '));
  }
  return out.sort();
}

describe('KHR_draco_mesh_compression', () => {
  it('reads a model written with Draco as the same model written plain (positions to 16 bits)', async () => {
    const compressed = await dracoGlb();
    expect(glbJson(compressed).extensionsRequired).toContain('KHR_draco_mesh_compression');
    const plain = parse(await io().writeBinary(model()));
    const decoded = await parseDecoded(compressed);
    // Draco orders points and triangles its own way: compare triangles by their corners, same winding.
    expect(shape(decoded)).toEqual(shape(plain));
    expect(decoded.uv0!.length).toBe(decoded.positions.length / 3 * 2);
  });

  it("reads Draco's own test box (tests/data/gltf/Box_Draco.glb): 12 triangles of a unit cube, normals on its axes", async () => {
    const r = await parseDecoded(file('Box_Draco.glb'), 'Box_Draco.glb');
    expect(r.indices.length / 3).toBe(12);
    expect(Math.max(...r.positions.map(Math.abs))).toBeCloseTo(0.5, 5);
    for (let i = 0; i < r.normals.length; i += 3) {
      expect([...r.normals.subarray(i, i + 3)].map((x) => Math.abs(Math.round(x))).reduce((a, b) => a + b)).toBe(1);
    }
  });

  it('loads the Draco decoder only for a Draco file; refuses a stream that does not decode, naming the primitive', async () => {
    const decoders: GltfDecoders = { meshopt: vi.fn(NODE_DECODERS.meshopt), draco: vi.fn(NODE_DECODERS.draco) };
    const glb = await dracoGlb();
    await decompressGltf(openGltf(glb, 'a.glb'), new Map(), decoders);
    expect([vi.mocked(decoders.meshopt).mock.calls.length, vi.mocked(decoders.draco).mock.calls.length]).toEqual([0, 1]);
    const json = glbJson(glb);
    const bin = glbBin(glb).slice();
    const view = json.bufferViews[json.meshes[0].primitives[0].extensions.KHR_draco_mesh_compression.bufferView];
    bin.fill(0x5a, (view.byteOffset ?? 0) + 4, (view.byteOffset ?? 0) + view.byteLength);
    const open = openGltf(makeGlb(json, bin), 'bad.glb');
    const e = await decompressGltf(open, new Map(), NODE_DECODERS).then(() => null, (x: unknown) => x);
    expect(e).toBeInstanceOf(LoadError);
    expect((e as LoadError).detail).toMatchObject({ path: 'meshes[0].primitives[0].extensions.KHR_draco_mesh_compression' });
  });
});
