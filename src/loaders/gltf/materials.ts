// glTF's metallic-roughness materials as plain data (docs/gltf.md#materials): every field of the
// core material and of KHR_materials_emissive_strength, KHR_materials_unlit and
// KHR_texture_transform, defaults as the specification states them. Textures name their image
// by index; the element turns images into URLs.
import { fieldPath, GltfFile, int, num, numbers, object, optionalObject, str, type Obj } from './fields';
import type { AlphaMode, PbrMaterialOf, PbrSampler, PbrTextureOf } from '../../scene/pbr-material';

export type GltfSampler = PbrSampler;
/** A texture as the file has it: images[image]. */
export type GltfTextureRef = PbrTextureOf<{ image: number }>;
export type GltfMaterial = PbrMaterialOf<{ image: number }>;
export type { AlphaMode };

const REPEAT = 10497;
const WRAPS = new Set([33071, 33648, REPEAT]);
const MAG = new Set([9728, 9729]);
const MIN = new Set([9728, 9729, 9984, 9985, 9986, 9987]);

/** The default material of a primitive without one (the specification's). */
export const DEFAULT_MATERIAL: GltfMaterial = {
  name: '', baseColor: [1, 1, 1, 1], baseColorTexture: null, metallic: 1, roughness: 1, metallicRoughnessTexture: null,
  normalTexture: null, normalScale: 1, occlusionTexture: null, occlusionStrength: 1, emissive: [0, 0, 0], emissiveTexture: null,
  emissiveStrength: 1, alphaMode: 'opaque', alphaCutoff: 0.5, doubleSided: false, unlit: false,
};

export function readMaterials(file: GltfFile): GltfMaterial[] {
  return file.list('materials').map((m, i) => readMaterial(file, object(file, m, `materials[${i}]`), `materials[${i}]`));
}

function readMaterial(file: GltfFile, m: Obj, path: string): GltfMaterial {
  const pbrPath = `${path}.pbrMetallicRoughness`;
  const pbr = optionalObject(file, m, 'pbrMetallicRoughness', path) ?? {};
  const ext = optionalObject(file, m, 'extensions', path) ?? {};
  const strength = optionalObject(file, ext, 'KHR_materials_emissive_strength', `${path}.extensions`);
  const mode = str(file, m, 'alphaMode', path, 'OPAQUE');
  if (mode !== 'OPAQUE' && mode !== 'MASK' && mode !== 'BLEND') file.fail(`${path}.alphaMode`, `${path}.alphaMode is ${JSON.stringify(mode).slice(0, 40)}, not OPAQUE, MASK or BLEND`);
  const normal = optionalObject(file, m, 'normalTexture', path);
  const occlusion = optionalObject(file, m, 'occlusionTexture', path);
  const color = numbers(file, pbr, 'baseColorFactor', pbrPath, 4, [1, 1, 1, 1]);
  const emissive = numbers(file, m, 'emissiveFactor', path, 3, [0, 0, 0]);
  return {
    name: m.name === undefined ? '' : str(file, m, 'name', path),
    baseColor: [clamp01(color[0]), clamp01(color[1]), clamp01(color[2]), clamp01(color[3])],
    baseColorTexture: textureRef(file, pbr, 'baseColorTexture', pbrPath),
    metallic: num(file, pbr, 'metallicFactor', pbrPath, 1, 0, 1),
    roughness: num(file, pbr, 'roughnessFactor', pbrPath, 1, 0, 1),
    metallicRoughnessTexture: textureRef(file, pbr, 'metallicRoughnessTexture', pbrPath),
    normalTexture: textureRef(file, m, 'normalTexture', path),
    normalScale: normal ? num(file, normal, 'scale', `${path}.normalTexture`, 1) : 1,
    occlusionTexture: textureRef(file, m, 'occlusionTexture', path),
    occlusionStrength: occlusion ? num(file, occlusion, 'strength', `${path}.occlusionTexture`, 1, 0, 1) : 1,
    emissive: [Math.max(0, emissive[0]), Math.max(0, emissive[1]), Math.max(0, emissive[2])],
    emissiveTexture: textureRef(file, m, 'emissiveTexture', path),
    emissiveStrength: strength ? num(file, strength, 'emissiveStrength', `${path}.extensions.KHR_materials_emissive_strength`, 1, 0) : 1,
    alphaMode: mode === 'OPAQUE' ? 'opaque' : mode === 'MASK' ? 'mask' : 'blend',
    alphaCutoff: num(file, m, 'alphaCutoff', path, 0.5, 0),
    doubleSided: m.doubleSided === true,
    unlit: ext.KHR_materials_unlit !== undefined,
  };
}

function clamp01(x: number): number {
  // Stryker disable next-line EqualityOperator: at x = 0 or 1 exactly, either branch returns that same value
  return x < 0 ? 0 : x > 1 ? 1 : x;
}

/** A textureInfo field of `o`, with its texture's sampler and source resolved (null when absent or without an image). */
function textureRef(file: GltfFile, o: Obj, key: string, path: string): GltfTextureRef | null {
  const info = optionalObject(file, o, key, path);
  if (!info) return null;
  const at = fieldPath(path, key);
  const index = int(file, info, 'index', at);
  const texturePath = `textures[${index}]`;
  const texture = file.item('textures', index, `${at}.index`);
  const image = textureImage(file, texture, texturePath);
  if (image === null) return null;
  const samplerIndex = texture.sampler === undefined ? null : int(file, texture, 'sampler', texturePath);
  const sampler = samplerIndex === null ? { magFilter: undefined, minFilter: undefined, wrapS: REPEAT, wrapT: REPEAT }
    : readSampler(file, file.item('samplers', samplerIndex, `${texturePath}.sampler`), `samplers[${samplerIndex}]`);
  let texCoord = int(file, info, 'texCoord', at, 0);
  const ext = optionalObject(file, info, 'extensions', at);
  const tt = ext && optionalObject(file, ext, 'KHR_texture_transform', `${at}.extensions`);
  let transform: number[] | null = null;
  if (tt) {
    const where = `${at}.extensions.KHR_texture_transform`;
    const [ox, oy] = numbers(file, tt, 'offset', where, 2, [0, 0]);
    const [sx, sy] = numbers(file, tt, 'scale', where, 2, [1, 1]);
    const r = num(file, tt, 'rotation', where, 0);
    // The extension's T · R · S: rotation counter-clockwise in UV space, whose v points down.
    const c = Math.cos(r), s = Math.sin(r);
    transform = [c * sx, s * sy, ox, -s * sx, c * sy, oy];
    if (tt.texCoord !== undefined) texCoord = int(file, tt, 'texCoord', where);
  }
  if (texCoord > 1) {
    file.warn(`${at}.texCoord`, `${at} reads TEXCOORD_${texCoord}: only TEXCOORD_0 and TEXCOORD_1 are read; drawn without it`);
    return null;
  }
  return { source: { image }, texCoord, sampler, transform };
}

/** The image a texture draws: its source, or a supported extension's (EXT_texture_webp); null for KTX2 alone. */
function textureImage(file: GltfFile, texture: Obj, path: string): number | null {
  const ext = optionalObject(file, texture, 'extensions', path);
  const webp = ext && optionalObject(file, ext, 'EXT_texture_webp', `${path}.extensions`);
  if (webp) return imageIndex(file, webp, `${path}.extensions.EXT_texture_webp`);
  if (texture.source !== undefined) return imageIndex(file, texture, path);
  if (ext && ext.KHR_texture_basisu !== undefined) {
    file.warn(`${path}.extensions.KHR_texture_basisu`, `${path} is a KTX2 (Basis) image only: drawn with its material's factor instead`);
  }
  return null;
}

function imageIndex(file: GltfFile, o: Obj, path: string): number {
  const i = int(file, o, 'source', path);
  file.item('images', i, `${path}.source`);
  return i;
}

function readSampler(file: GltfFile, s: Obj, path: string): GltfSampler {
  const pick = (key: string, allowed: Set<number>, fallback: number | undefined) => {
    if (s[key] === undefined) return fallback;
    const v = int(file, s, key, path);
    if (allowed.has(v)) return v;
    file.warn(fieldPath(path, key), `${fieldPath(path, key)} is ${v}, not a value glTF allows: the default is used`);
    return fallback;
  };
  return { magFilter: pick('magFilter', MAG, undefined), minFilter: pick('minFilter', MIN, undefined), wrapS: pick('wrapS', WRAPS, REPEAT)!, wrapT: pick('wrapT', WRAPS, REPEAT)! };
}
