// glTF 2.0 and GLB in, plain data out (docs/gltf.md): the default scene's meshes flattened into
// one vertex buffer with an index range per material, the materials as data, the images as
// references. The caller fetches external buffers (`gltfBuffers`) and hands them in.
import { readContainer, type Container } from './container';
import { externalBuffers, resolveBuffers, type ExternalBuffer } from './buffers';
import { GltfFile, object, str, type GltfWarning, type Obj } from './fields';
import { readMaterials, type GltfMaterial } from './materials';
import { meshInstances } from './nodes';
import { positionCount, readPiece, type Piece } from './primitives';
import { readImages, type GltfImage } from './images';
import { mergePieces, type Merged } from './merge';
import { DECODERS, type GltfDecoders } from './decoders';
import { decodeMeshopt, meshoptViews, type MeshoptDecoderLike } from './meshopt';
import { decodeDraco, dracoPrimitives } from './draco';

export type { GltfMaterial, GltfTextureRef, GltfSampler, AlphaMode } from './materials';
export type { GltfImage } from './images';
export type { GltfWarning } from './fields';
export type { ExternalBuffer } from './buffers';
export { isGlb } from './container';

/** Extensions read (docs/gltf.md#extensions); any other that a file requires is an error naming it. */
export const SUPPORTED_EXTENSIONS: readonly string[] = [
  'EXT_meshopt_compression', 'KHR_draco_mesh_compression', 'KHR_mesh_quantization', 'KHR_texture_transform', 'KHR_materials_emissive_strength', 'KHR_materials_unlit', 'EXT_texture_webp',
];

/** Vertices a model may have once its nodes are flattened: beyond, the file is refused before anything is read. */
export const MAX_VERTICES = 1 << 23;

/** The model's geometry (merge.ts: one vertex buffer, an index range per material) with its materials, images and warnings. */
export interface GltfResult extends Merged {
  materials: GltfMaterial[];
  images: GltfImage[];
  warnings: GltfWarning[];
}

/** A file opened: its container read and its JSON checked to be glTF 2.0 (no buffer read yet). */
export interface OpenGltf {
  file: GltfFile;
  container: Container;
}

export function openGltf(bytes: Uint8Array, url: string): OpenGltf {
  const container = readContainer(bytes, url);
  const probe = new GltfFile(url, {});
  const json = object(probe, container.json, 'JSON');
  const file = new GltfFile(url, json);
  const asset = object(file, json.asset, 'asset');
  const version = str(file, asset, 'version', 'asset');
  if (!/^2\.\d+$/.test(version)) file.fail('asset.version', `asset.version is ${JSON.stringify(version).slice(0, 20)}: only glTF 2.x is read`);
  checkExtensions(file);
  return { file, container };
}

/** The buffers to fetch before `readGltf`: their uri as written (relative to the model's URL). */
export function gltfBuffers(open: OpenGltf): ExternalBuffer[] {
  return externalBuffers(open.file);
}

/**
 * Decodes what the file compresses (EXT_meshopt_compression's views, KHR_draco_mesh_compression's
 * primitives), loading each decoder only
 * if the file needs it; `readGltf` then reads the decoded bytes. A decoder that cannot load is
 * an error naming the extension.
 */
export async function decompressGltf(open: OpenGltf, external: ReadonlyMap<number, Uint8Array> = new Map(), decoders: GltfDecoders = DECODERS): Promise<void> {
  const { file, container } = open;
  const meshopt = meshoptViews(file).length > 0;
  const draco = dracoPrimitives(file).length > 0;
  if (!meshopt && !draco) return;
  const buffers = resolveBuffers(file, container.bin, external);
  const unavailable = (name: string) => (e: unknown) =>
    file.fail('extensionsUsed', `the ${name} decoder could not be loaded (${e instanceof Error ? e.message : String(e)})`);
  if (meshopt) {
    const decoder: MeshoptDecoderLike = await decoders.meshopt().catch(unavailable('meshopt'));
    file.decodedViews = await decodeMeshopt(file, buffers, decoder);
  }
  if (draco) file.decodedAccessors = decodeDraco(file, buffers, await decoders.draco().catch(unavailable('Draco')));
}

export function readGltf(open: OpenGltf, external: ReadonlyMap<number, Uint8Array> = new Map()): GltfResult {
  const { file, container } = open;
  const buffers = resolveBuffers(file, container.bin, external);
  const instances = meshInstances(file);
  const meshes = file.list('meshes');
  let vertices = 0;
  for (const at of instances) {
    const mesh = file.item('meshes', at.mesh, `${at.node}.mesh`);
    primitivesOf(file, mesh, at.mesh).forEach((p, k) => { vertices += positionCount(file, p, `meshes[${at.mesh}].primitives[${k}]`); });
    if (vertices > MAX_VERTICES) file.fail(at.node, `the scene's meshes have over ${MAX_VERTICES} vertices once its nodes are placed: too large to draw`);
  }
  const pieces: Piece[] = [];
  for (const at of instances) {
    const primitives = primitivesOf(file, meshes[at.mesh] as Obj, at.mesh);
    primitives.forEach((p, k) => {
      const piece = readPiece(file, buffers, p, `meshes[${at.mesh}].primitives[${k}]`, at);
      if (piece && piece.indices.length > 0) pieces.push(piece);
    });
  }
  if (pieces.length === 0) file.fail(instances.length ? 'meshes' : 'scenes', 'the file has no triangles to draw');
  const materials = readMaterials(file);
  const images = readImages(file, buffers);
  return { ...mergePieces(pieces), materials, images, warnings: file.warnings };
}

function primitivesOf(file: GltfFile, mesh: Obj, index: number): Obj[] {
  const path = `meshes[${index}]`;
  const list = mesh.primitives;
  if (!Array.isArray(list)) file.fail(`${path}.primitives`, `${path}.primitives is not an array`);
  return list.map((p, k) => object(file, p, `${path}.primitives[${k}]`));
}

function checkExtensions(file: GltfFile): void {
  const names = (key: string) => {
    const v = file.json[key];
    if (v === undefined) return [];
    if (!Array.isArray(v) || !v.every((x) => typeof x === 'string')) file.fail(key, `${key} is not a list of names`);
    return v as string[];
  };
  const required = names('extensionsRequired');
  required.forEach((name, i) => {
    if (!SUPPORTED_EXTENSIONS.includes(name)) file.fail(`extensionsRequired[${i}]`, `the file requires ${name}, which is not supported`);
  });
  for (const name of names('extensionsUsed')) {
    if (!SUPPORTED_EXTENSIONS.includes(name) && !required.includes(name)) file.warn('extensionsUsed', `${name} is not supported: the file is drawn without it`);
  }
}
