// The scene model of docs/scene-model.md#one-scene-value: one plain value (no DOM, no GL) that every renderer and the
// float64 reference read. The element builds it from its attributes and children; nothing
// downstream knows what an object is called, only its geometry, transform and material.
import type { MeshData } from './geometry/mesh-data';
import { readMap, type PbrMaterial } from './pbr-material';
import type { EnvironmentImage } from '../math/environment-image';

export type Vec3 = readonly [number, number, number];

/** How texture coordinates are made (docs/scene-model.md#texture-mappings). */
export type Mapping = 'uv' | 'triplanar' | 'cylindrical' | 'spherical';
export const MAPPINGS: readonly Mapping[] = ['uv', 'triplanar', 'cylindrical', 'spherical'];

/**
 * The seeded checker of docs/default-scene.md#the-procedural-texture, an image (by URL, decoded by whoever draws it), or none: a
 * plain material, tex = 1 (the course's `.byu` objects, docs/course-files.md#mesh-byu).
 */
export type TextureSource =
  | { kind: 'procedural' }
  /** `fallback: 'none'`: drawn plain (white) while the image is missing or if it failed, not with the checker (a glTF's or a course file's). */
  | { kind: 'image'; url: string; fallback?: 'none' }
  | { kind: 'none' };

/** Blinn-Phong with the names Ka, Kd, Ks and shininess; the texture multiplies Ka and Kd. */
export interface Material {
  ambient: Vec3;
  diffuse: Vec3;
  specular: Vec3;
  shininess: number;
  /** 1 − kt; below 1 the object is blended over what lies behind it (docs/scene-model.md#glass-object, docs/software-renderer.md#transparency). */
  opacity: number;
  texture: TextureSource;
  mapping: Mapping;
  /** Light the surface gives off, linear RGB added to its lit colour (a glTF material's emissive; absent: none). */
  emissive?: Vec3;
  /**
   * A glTF model's material as the file has it (docs/gltf.md#materials); the fields above are its
   * Blinn-Phong stand-in until PBR shading. Absent for everything else.
   */
  pbr?: PbrMaterial;
}

/** Built-ins are centred on the origin before the transform. */
export type Geometry =
  /** Axis-aligned cube of edge `size`, each face UV-mapped over [0, 1]². */
  | { kind: 'box'; size: number }
  /** Sphere of `radius`, tessellated by whoever draws it (the GPU by its size on screen). */
  | { kind: 'sphere'; radius: number }
  /** The Gaussian y = e^(−x²)·e^(−z²) on x, z ∈ [−2, 2], `resolution` × `resolution` vertices. */
  | { kind: 'gaussian'; resolution: number }
  /** A loaded triangle mesh; `key` names its content (URL + options) for sharing. */
  | { kind: 'mesh'; key: string; data: MeshData };

export interface Transform {
  position: Vec3;
  /** Degrees, applied X, then Y, then Z. */
  rotation: Vec3;
  scale: Vec3;
  /** Turning about the object's own Y axis, rad/s, applied before `rotation` (0: still). */
  spin: number;
}

/** A sphere containing the geometry in its own (untransformed) frame: culling and LOD. */
export interface Bounds {
  center: Vec3;
  radius: number;
}

export interface SceneObject {
  geometry: Geometry;
  transform: Transform;
  material: Material;
  bounds: Bounds;
  /** False: kept out of the glass's reflection, drawn everywhere else (docs/scene-model.md#glass-object). Absent: reflected. */
  reflected?: boolean;
}

export interface Light {
  /** 'directional': `vector` points towards the light; 'point': `vector` is its position. */
  kind: 'directional' | 'point';
  vector: Vec3;
  /** Ia, Id, Is (numbers above 1 allowed). */
  ambient: Vec3;
  diffuse: Vec3;
  specular: Vec3;
}

/** Lights a scene is drawn with: its first MAX_LIGHTS, by every renderer and the reference (docs/scene-model.md#lights). */
export const MAX_LIGHTS = 4;

export interface Glass {
  center: Vec3;
  /** Unit normal: the side it points to is "+". */
  normal: Vec3;
  /** Width along a = normalize(+Y × n) (+X when n ∥ Y), height along n × a. */
  size: readonly [number, number];
}

/**
 * Light from every direction (docs/pbr.md#the-environment), which lights glTF materials only, its radiance times `intensity`:
 * `studio` is the neutral studio of math/studio.ts; `image` an equirectangular image of linear light (docs/pbr.md#an-image),
 * reduced to at most 512 × 256 texels (math/environment-image.ts), named by its URL.
 */
export type Environment =
  | { kind: 'studio'; intensity: number }
  | { kind: 'image'; intensity: number; url: string; image: EnvironmentImage };

/**
 * The name an environment's prepared maps are kept under (frame/environment-cache.ts): `studio`, or an image's URL (absolute, so
 * never the word). Made of nothing new: the frame loop may ask.
 */
export const environmentKey = (e: Environment): string => (e.kind === 'image' ? e.url : e.kind);

export interface Scene {
  /** Null: no glass, hence no glass pass and no reflection pass (a plain model viewer). */
  glass: Glass | null;
  objects: readonly SceneObject[];
  /** Its lights; the first MAX_LIGHTS light it. */
  lights: readonly Light[];
  /** Clear colour, also of the reflection. */
  background: Vec3;
  /** Absent or null: none; glTF materials see only the lights. */
  environment?: Environment | null;
}

/** The images `m` draws with, by URL: its texture's, and a glTF material's maps' (docs/gltf.md#drawing). Asked when a scene is new. */
export function materialImages(m: Material): string[] {
  const urls = m.texture.kind === 'image' ? [m.texture.url] : [];
  const p = m.pbr;
  if (p) for (const t of [p.metallicRoughnessTexture, p.occlusionTexture, p.emissiveTexture, p.normalTexture]) {
    const read = readMap(t);
    if (read) urls.push(read.source.url);
  }
  return urls;
}

/** Whether a scene has a glTF material (docs/pbr.md#the-scenes-lights). Reads; allocates nothing (asked every frame). */
export function hasPbrMaterial(scene: Scene): boolean {
  for (const o of scene.objects) if (o.material.pbr !== undefined) return true;
  return false;
}

/**
 * `value` and everything in it frozen, but typed arrays (which cannot be): the scene value the
 * element hands over. A page that changed it in place would otherwise see some renderers follow
 * and others not — the software renderer's caches know a value by identity (docs/scene-model.md#one-scene-value).
 */
export function deepFreeze<T>(value: T): T {
  if (value !== null && typeof value === 'object' && !ArrayBuffer.isView(value) && !Object.isFrozen(value)) {
    Object.freeze(value);
    for (const v of Object.values(value)) deepFreeze(v);
  }
  return value;
}
