// A glTF model's load after its file is fetched (docs/gltf.md#loading): a chunk of its own, which
// only a page with a glTF model fetches. Its external buffers are fetched relative to the model's
// URL; the file is read in a worker (on this thread where no worker can start); its images become
// URLs (embedded ones blob: URLs) and its materials the values an object's material is made from.
import { LoadError, warningText } from '../../loaders/load-error';
import { decompressGltf, gltfBuffers, openGltf, readGltf, type GltfImage, type GltfMaterial, type GltfResult, type OpenGltf } from '../../loaders/gltf';
import { gltfAsObj, materialKey, transformAsObj } from '../../loaders/gltf/as-obj';
import type { GltfJobRequest, GltfJobResponse } from '../../loaders/gltf-job';
import type { PbrMaterial, PbrTextureOf } from '../../scene/pbr-material';
import { absoluteUrl } from '../absolute-url';
import { fetchBytes } from './model-fetch';
import type { LoadedModel } from './model-loader';
import type { MtlValues } from './object-material';

/** Files (with their buffers) at least this big are read off the main thread. */
export const GLTF_WORKER_THRESHOLD = 256 * 1024;

export async function loadGltfModel(bytes: Uint8Array, url: string, signal: AbortSignal): Promise<LoadedModel> {
  const open = openGltf(bytes, url);
  const external = new Map<number, Uint8Array>();
  for (const b of gltfBuffers(open)) {
    const at = `buffers[${b.index}].uri`;
    const bufferUrl = absoluteUrl(b.uri, url);
    if (bufferUrl === null) throw new LoadError(url, `${at} ${JSON.stringify(b.uri)} is not a usable URL`, at);
    try {
      external.set(b.index, await fetchBytes(bufferUrl, signal));
    } catch (e) {
      if (signal.aborted) throw e;
      const why = e instanceof LoadError ? e.detail.message : e instanceof Error ? e.message : String(e);
      throw new LoadError(url, `buffers[${b.index}] (${bufferUrl}) could not be loaded: ${why}`, at);
    }
  }
  let size = bytes.length;
  for (const b of external.values()) size += b.length;
  const result = (size >= GLTF_WORKER_THRESHOLD ? await readInWorker(bytes, url, external) : null) ?? await readHere(open, external);
  signal.throwIfAborted();
  return modelOf(result, url);
}

/** The read model as the element keeps it: its geometry as an OBJ's, its materials by group key. */
export function modelOf(result: GltfResult, url: string): LoadedModel {
  const obj = gltfAsObj(result);
  const imageUrls = result.images.map((im) => imageUrl(im, url));
  const materials = new Map<string, MtlValues>();
  result.materials.forEach((m, i) => materials.set(materialKey(i), standIn(withUrls(m, imageUrls))));
  const warnings = obj.warnings.map((w) => warningText(url, w));
  return { url, obj, bezier: null, bezierAt: null, byu: false, gltf: true, materials, warnings };
}

function imageUrl(image: GltfImage, base: string): string | null {
  if (image.kind === 'uri') return absoluteUrl(image.uri, base);
  if (typeof URL.createObjectURL !== 'function') return null;
  // Kept for the page's life, as the model is (one load per URL per page).
  return URL.createObjectURL(new Blob([image.bytes as Uint8Array<ArrayBuffer>], { type: image.mimeType || 'application/octet-stream' }));
}

function withUrls(m: GltfMaterial, urls: (string | null)[]): PbrMaterial {
  const map = (t: PbrTextureOf<{ image: number }> | null): PbrTextureOf<{ url: string }> | null => {
    const u = t ? urls[t.source.image] : null;
    // The model's UVs are turned the OBJ way up (as-obj.ts): so is each texture's transform.
    return t && u ? { ...t, source: { url: u }, transform: t.transform && transformAsObj(t.transform) } : null;
  };
  return {
    ...m, baseColorTexture: map(m.baseColorTexture), metallicRoughnessTexture: map(m.metallicRoughnessTexture),
    normalTexture: map(m.normalTexture), occlusionTexture: map(m.occlusionTexture), emissiveTexture: map(m.emissiveTexture),
  };
}

/**
 * The Blinn-Phong stand-in a glTF material is drawn with until PBR shading (docs/gltf.md#drawing):
 * base colour as Ka and Kd, its alpha as the opacity when blended, a highlight from the
 * specular colour at normal incidence (0.04 for a dielectric, the base colour for a metal) fading
 * with roughness, its exponent 2/α² − 2 (α = roughness²), the base colour texture on TEXCOORD_0,
 * and its emissive factor times its strength as light given off.
 */
export function standIn(m: PbrMaterial): MtlValues {
  const [r, g, b, a] = m.baseColor;
  const base = [r, g, b] as const;
  const f0 = base.map((c) => 0.04 + (c - 0.04) * m.metallic);
  const fade = 1 - m.roughness;
  const alpha = Math.max(m.roughness * m.roughness, 0.05);
  const shininess = Math.min(Math.max(2 / (alpha * alpha) - 2, 1), 800);
  const texture = m.baseColorTexture && m.baseColorTexture.texCoord === 0 ? m.baseColorTexture.source.url : undefined;
  const [er, eg, eb] = m.emissive.map((c) => c * m.emissiveStrength);
  return {
    ambient: base, diffuse: base, specular: [f0[0] * fade, f0[1] * fade, f0[2] * fade], shininess,
    opacity: m.alphaMode === 'blend' ? a : 1, texture, pbr: m,
    // KHR_materials_unlit: the base colour alone (docs/pbr.md#the-scenes-lights).
    ...(!m.unlit && (er > 0 || eg > 0 || eb > 0) ? { emissive: [er, eg, eb] as const } : {}),
  };
}

async function readHere(open: OpenGltf, external: Map<number, Uint8Array>): Promise<GltfResult> {
  await decompressGltf(open, external);
  return readGltf(open, external);
}

let nextId = 1;

/** Resolves null when no worker could run the job (the caller reads on the main thread). */
function readInWorker(bytes: Uint8Array, url: string, external: Map<number, Uint8Array>): Promise<GltfResult | null> {
  return new Promise((resolve, reject) => {
    let worker: Worker;
    try {
      worker = new Worker(new URL('../../loaders/gltf-worker.ts', import.meta.url), { type: 'module' });
    } catch {
      resolve(null);
      return;
    }
    worker.onmessage = (e: MessageEvent<GltfJobResponse>) => {
      worker.terminate();
      const r = e.data;
      if (r.ok) resolve(r.result);
      else reject(new LoadError(r.error.url, r.error.message, r.error.line ?? r.error.path));
    };
    worker.onerror = (e) => {
      e.preventDefault();
      worker.terminate();
      resolve(null);
    };
    // Copied, not transferred: the bytes stay usable for the main-thread fallback.
    const request: GltfJobRequest = {
      id: nextId++, url, bytes: bytes.slice().buffer as ArrayBuffer,
      external: [...external].map(([i, b]) => [i, b.slice().buffer as ArrayBuffer]),
    };
    worker.postMessage(request, [request.bytes, ...request.external.map(([, b]) => b)]);
  });
}
