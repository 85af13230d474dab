// glTF test models made by the tests (docs/gltf.md#test-models): built with glTF-Transform, written
// as GLB or .gltf, and checked by the Khronos validator before a test reads them — a model the
// validator refuses is a broken test, not a loader's fault. Broken files are made from valid
// ones by hand, each test saying what it breaks.
import { Accessor, Document, NodeIO, Primitive, type Node as GltfNode, type Material } from '@gltf-transform/core';
import { ALL_EXTENSIONS } from '@gltf-transform/extensions';
import { validateBytes } from 'gltf-validator';
import { expect } from 'vitest';
import { decompressGltf, openGltf, readGltf, gltfBuffers, type GltfResult } from '../../../src/loaders/gltf';
import type { GltfDecoders } from '../../../src/loaders/gltf/decoders';
import type { DracoModule } from '../../../src/loaders/gltf/draco';

export const io = () => new NodeIO().registerExtensions(ALL_EXTENSIONS);

/** A document with one scene, one buffer and a default node for meshes. */
export function newDocument(): { doc: Document; root: GltfNode } {
  const doc = new Document();
  doc.createBuffer();
  const root = doc.createNode('root');
  doc.createScene('scene').addChild(root);
  return { doc, root };
}

export function accessor(doc: Document, type: 'SCALAR' | 'VEC2' | 'VEC3' | 'VEC4', array: ArrayLike<number> & { buffer: ArrayBufferLike }, normalized = false): Accessor {
  return doc.createAccessor().setType(type).setArray(array as never).setNormalized(normalized).setBuffer(doc.getRoot().listBuffers()[0]);
}

/** A primitive of `positions` (xyz), with `indices` if given and the attributes named. */
export function primitive(doc: Document, positions: number[], indices: number[] | null, extra: Record<string, Accessor> = {}, material?: Material): Primitive {
  const p = doc.createPrimitive().setAttribute('POSITION', accessor(doc, 'VEC3', new Float32Array(positions)));
  if (indices) p.setIndices(accessor(doc, 'SCALAR', new Uint16Array(indices)));
  for (const [name, a] of Object.entries(extra)) p.setAttribute(name, a);
  if (material) p.setMaterial(material);
  return p;
}

/** Validator issues at severity error (0), as codes with their pointers. */
export async function validationErrors(bytes: Uint8Array, external: Record<string, Uint8Array> = {}): Promise<string[]> {
  const report = await validateBytes(bytes, {
    maxIssues: 0, writeTimestamp: false,
    // The validator asks by the decoded name; the files are keyed by the URI as written.
    externalResourceFunction: (uri: string) => {
      const bytes = external[uri] ?? Object.entries(external).find(([k]) => decodeURIComponent(k) === uri)?.[1];
      return bytes ? Promise.resolve(bytes) : Promise.reject(new Error(`no ${uri}`));
    },
  });
  return report.issues.messages.filter((m) => m.severity === 0).map((m) => `${m.code} ${m.pointer ?? ''}`);
}

/** The document as GLB bytes, validated. */
export async function glbOf(doc: Document): Promise<Uint8Array> {
  const bytes = await io().writeBinary(doc);
  expect(await validationErrors(bytes), 'the test model is valid glTF').toEqual([]);
  return bytes;
}

/** The document as .gltf JSON bytes and its resources (buffers, images) by URI, validated. */
export async function gltfOf(doc: Document): Promise<{ json: Uint8Array; resources: Record<string, Uint8Array> }> {
  const { json, resources } = await io().writeJSON(doc);
  const bytes = new TextEncoder().encode(JSON.stringify(json));
  expect(await validationErrors(bytes, resources), 'the test model is valid glTF').toEqual([]);
  return { json: bytes, resources };
}

/** Reads a file as the element does: open, its external buffers from `resources` by URI, read. */
export function parse(bytes: Uint8Array, url = 'model.glb', resources: Record<string, Uint8Array> = {}): GltfResult {
  const open = openGltf(bytes, url);
  const external = new Map<number, Uint8Array>();
  for (const b of gltfBuffers(open)) if (resources[b.uri]) external.set(b.index, resources[b.uri]);
  return readGltf(open, external);
}

/**
 * The decoders in Node: meshoptimizer's as the page imports it; draco3d's module reading its wasm
 * from disk (the page's fetches it beside its chunk, src/loaders/gltf/decoders.ts).
 */
export const NODE_DECODERS: GltfDecoders = {
  meshopt: () => import('meshoptimizer/decoder').then((m) => m.MeshoptDecoder),
  draco: () => import('draco3d').then((m) => (m.default ?? m).createDecoderModule() as Promise<DracoModule>),
};

/** As `parse`, decoding what the file compresses first. */
export async function parseDecoded(bytes: Uint8Array, url = 'model.glb', resources: Record<string, Uint8Array> = {}): Promise<GltfResult> {
  const open = openGltf(bytes, url);
  const external = new Map<number, Uint8Array>();
  for (const b of gltfBuffers(open)) if (resources[b.uri]) external.set(b.index, resources[b.uri]);
  await decompressGltf(open, external, NODE_DECODERS);
  return readGltf(open, external);
}

/** A GLB's JSON chunk, for tests that break a valid file by hand. */
// eslint-disable-next-line @typescript-eslint/no-explicit-any -- a file to break by hand: any shape
export function glbJson(bytes: Uint8Array): Record<string, any> {
  const length = new DataView(bytes.buffer, bytes.byteOffset).getUint32(12, true);
  return JSON.parse(new TextDecoder().decode(bytes.subarray(20, 20 + length)));
}

/** A GLB of `json` and `bin` (both padded to 4 bytes, as the container requires). */
export function makeGlb(json: unknown, bin: Uint8Array | null): Uint8Array {
  const text = new TextEncoder().encode(JSON.stringify(json));
  const jsonLength = Math.ceil(text.length / 4) * 4;
  const binLength = bin ? Math.ceil(bin.length / 4) * 4 : 0;
  const total = 12 + 8 + jsonLength + (bin ? 8 + binLength : 0);
  const out = new Uint8Array(total);
  const view = new DataView(out.buffer);
  view.setUint32(0, 0x46546c67, true);
  view.setUint32(4, 2, true);
  view.setUint32(8, total, true);
  view.setUint32(12, jsonLength, true);
  view.setUint32(16, 0x4e4f534a, true);
  out.fill(0x20, 20, 20 + jsonLength);
  out.set(text, 20);
  if (bin) {
    view.setUint32(20 + jsonLength, binLength, true);
    view.setUint32(24 + jsonLength, 0x004e4942, true);
    out.set(bin, 28 + jsonLength);
  }
  return out;
}

/** A GLB's BIN chunk. */
export function glbBin(bytes: Uint8Array): Uint8Array {
  const view = new DataView(bytes.buffer, bytes.byteOffset);
  const jsonLength = view.getUint32(12, true);
  const at = 20 + jsonLength;
  return bytes.subarray(at + 8, at + 8 + view.getUint32(at, true));
}
