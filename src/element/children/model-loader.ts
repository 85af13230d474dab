// One model's whole load: fetch (with progress), sniff and parse, then its MTL files resolved
// against the model's URL (and their textures against each MTL's own). A missing or broken MTL
// is a warning, not an error: the model still shows, with attribute and default materials.
import { LoadError, warningText } from '../../loaders/load-error';
import { parseMtlBytes } from '../../loaders/mtl';
import type { ObjResult } from '../../loaders/obj';
import { fetchBytes, type Progress } from './model-fetch';
import { parseModelBytes } from './model-parse';
import { sniffModel } from '../../loaders/sniff';
import type { MtlValues } from './object-material';
import { bezierObj, type ByuBezierInfo } from '../../loaders/course/byu-model';
import { absoluteUrl } from '../absolute-url';

export interface LoadedModel {
  url: string;
  obj: ObjResult;
  /** A Bézier `.byu` (docs/course-files.md#bezier-byu): re-evaluated at the object's `resolution` when it sets one. */
  bezier: ByuBezierInfo | null;
  /** The Bézier patch on an E×E grid (here, so that the evaluator stays in this lazy chunk). */
  bezierAt: ((resolution: number) => ObjResult) | null;
  /** A course `.byu`: no texture unless the object's `texture` sets one (docs/course-files.md#mesh-byu). */
  byu: boolean;
  /** A glTF model: its materials name their own textures, so none gets the procedural checker (docs/gltf.md#in-the-scene). */
  gltf: boolean;
  /** By material name; the first MTL file that defines a name gives it. */
  materials: Map<string, MtlValues>;
  /** Console-ready text (prefix, URL and line), as in the `load` event's detail. */
  warnings: string[];
}

export async function loadModel(url: string, signal: AbortSignal, onProgress: (p: Progress) => void): Promise<LoadedModel> {
  const bytes = await fetchBytes(url, signal, onProgress);
  // glTF's reader is a chunk of its own, fetched by the first glTF model (docs/gltf.md#loading).
  const sniffed = sniffModel(bytes);
  if (sniffed === 'gltf') return import('./gltf-model').then(({ loadGltfModel }) => loadGltfModel(bytes, url, signal));
  const { obj, bezier, byu } = await parseModelBytes(bytes, url, sniffed);
  signal.throwIfAborted();
  const warnings = obj.warnings.map((w) => warningText(url, w));
  const materials = new Map<string, MtlValues>();
  for (const name of obj.mtllibs) {
    const mtlUrl = absoluteUrl(name.replace(/\\/g, '/'), url);
    if (mtlUrl === null) {
      warnings.push(`glass-plane-scene: ${url}: mtllib ${JSON.stringify(name)} is not a usable URL; ignored`);
      continue;
    }
    try {
      const mtl = parseMtlBytes(await fetchBytes(mtlUrl, signal), { url: mtlUrl });
      for (const w of mtl.warnings) warnings.push(warningText(mtlUrl, w));
      for (const [key, m] of mtl.materials) {
        if (materials.has(key)) continue;
        const map = m.diffuseMap ?? m.ambientMap;
        materials.set(key, {
          ambient: m.ambient, diffuse: m.diffuse, specular: m.specular, shininess: m.shininess, opacity: m.opacity,
          texture: map?.url,
        });
      }
    } catch (e) {
      if (signal.aborted) throw e;
      const why = e instanceof LoadError ? e.detail.message : e instanceof Error ? e.message : String(e);
      warnings.push(`glass-plane-scene: ${mtlUrl}: material library not loaded (${why}); using attributes and defaults`);
    }
  }
  const bezierAt = bezier ? (resolution: number) => bezierObj(bezier, resolution) : null;
  return { url, obj, bezier, bezierAt, byu, gltf: false, materials, warnings };
}
