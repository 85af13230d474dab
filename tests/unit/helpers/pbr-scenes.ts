// Scenes of glTF materials (docs/pbr.md#the-scenes-lights) that the renderers and the reference draw alike: a grid of
// spheres, metallic 0, ½, 1 by rows and roughness 0.05 … 1 by columns, over a glass floor, lit by a
// directional and a point light. Used by the software renderer's and WebGL's comparisons with the reference.
import type { PbrMaterial } from '../../../src/scene/pbr-material';
import type { Environment, Light, Material, Scene, SceneObject, Vec3 } from '../../../src/scene/scene';
import { defaultFrameState } from './frame-state';
import { imageDirection, type EnvironmentImage } from '../../../src/math/environment-image';

export const METALLIC = [0, 0.5, 1] as const;
export const ROUGHNESS = [0.05, 0.3, 0.6, 1] as const;

/** A glTF material as the loader gives it, with the fields the tests set. */
export function pbrMaterial(over: Partial<PbrMaterial> = {}): PbrMaterial {
  return {
    name: 'test', baseColor: [1, 1, 1, 1], baseColorTexture: null, metallic: 1, roughness: 1,
    metallicRoughnessTexture: null, normalTexture: null, normalScale: 1, occlusionTexture: null, occlusionStrength: 1,
    emissive: [0, 0, 0], emissiveTexture: null, emissiveStrength: 1, alphaMode: 'opaque', alphaCutoff: 0.5,
    doubleSided: false, unlit: false, ...over,
  };
}

/**
 * The scene's Material for a glTF material: `pbr` as given, the Blinn-Phong fields a stand-in
 * (no renderer reads them for a glTF material), the texture none unless given.
 */
export function withPbr(pbr: PbrMaterial, texture: Material['texture'] = { kind: 'none' }): Material {
  const [r, g, b] = pbr.baseColor;
  return { ambient: [r, g, b], diffuse: [r, g, b], specular: [0, 0, 0], shininess: 1, opacity: 1, texture, mapping: 'uv', pbr };
}

const sphere = (position: Vec3, material: Material): SceneObject => ({
  geometry: { kind: 'sphere', radius: 0.4 }, transform: { position, rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0 },
  material, bounds: { center: [0, 0, 0], radius: 0.4 },
});

export const PBR_LIGHTS: readonly Light[] = [
  { kind: 'directional', vector: [-0.4, 0.8, 0.6], ambient: [0.04, 0.04, 0.04], diffuse: [0.9, 0.85, 0.8], specular: [1, 1, 1] },
  { kind: 'point', vector: [2.5, 2, 3], ambient: [0, 0, 0], diffuse: [0.3, 0.35, 0.5], specular: [1, 1, 1] },
];

/** Twelve spheres, a coloured base (gold-ish), over a glass floor at y = 0. */
export function sphereGrid(): Scene {
  const objects: SceneObject[] = [];
  METALLIC.forEach((metallic, row) => ROUGHNESS.forEach((roughness, col) => {
    const material = withPbr(pbrMaterial({ baseColor: [0.95, 0.64, 0.37, 1], metallic, roughness }));
    objects.push(sphere([-1.5 + col, 0.45 + 1 * row, -0.4 * row], material));
  }));
  return {
    glass: { center: [0, 0, 0], normal: [0, 1, 0], size: [6, 4] },
    objects, lights: PBR_LIGHTS, background: [0.12, 0.12, 0.14],
  };
}

// A unit box, its +Z face head-on to the camera and to a directional light (Ia IA, Id ID; its specular
// colour is not a glTF material's: 7, to show it is not read).
export const IA = 0.1, ID = 0.2;

export function boxScene(pbr: PbrMaterial, emissive?: Vec3, light: Light = HEAD_ON): Scene {
  const material = { ...withPbr(pbr), ...(emissive ? { emissive } : {}) };
  return {
    glass: null, background: [0, 0, 0],
    objects: [{ geometry: { kind: 'box', size: 1 }, transform: { position: [0, 0, 0], rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0 }, material, bounds: { center: [0, 0, 0], radius: 0.9 } }],
    lights: [light],
  };
}

const HEAD_ON: Light = { kind: 'directional', vector: [0, 0, 1], ambient: [IA, IA, IA], diffuse: [ID, ID, ID], specular: [7, 7, 7] };

/**
 * A light of 100 at 85° from the face's normal (and from the view), no ambient: v·h = cos 42.5°, so Schlick's F is
 * F0 + (1 − F0)(1 − cos 42.5°)⁵, not F0. A dark metal (F0 0.02) at roughness 1 (D = 1/π, Vis = ½/(cos 85° + 1)):
 * 100·cos 85°·F·Vis (π·D = 1).
 */
export const GRAZING: Light = { kind: 'directional', vector: [Math.sin(85 * Math.PI / 180), 0, Math.cos(85 * Math.PI / 180)], ambient: [0, 0, 0], diffuse: [100, 100, 100], specular: [7, 7, 7] };
const GRAZING_WANT = (() => {
  const nl = Math.cos((85 * Math.PI) / 180), vh = Math.cos((42.5 * Math.PI) / 180);
  const f = 0.02 + 0.98 * (1 - vh) ** 5;
  return 100 * nl * f * (0.5 / (nl + 1));
})();

/** 33×33, the camera 4 from the box's +Z face, head-on; colour space none (the values as they are). */
export const BOX_STATE = defaultFrameState({ width: 33, height: 33, cameraPosition: [0, 0, 4], yaw: -90, pitch: 0, colorSpace: 'none', time: 0, spin: 0, samples: 0 });

/**
 * The centre pixel, by hand: Ia·c_diff + π·Id·((1 − F0)·c_diff/π + F0/(4πα²)) = Ia·c_diff + Id·((1 − F0)·c_diff + F0/(4α²)),
 * c_diff = base·(1 − m), F0 = 0.04·(1 − m) + base·m, α = roughness² (at least 0.002).
 */
export const HAND_CASES: { name: string; pbr: Partial<PbrMaterial>; emissive?: Vec3; light?: Light; want: number[] }[] = [
  // GRAZING: Fresnel away from normal incidence (0.0851 here; with (1 − v·h)³ it would be 0.1514).
  { name: 'a dark metal under a light at 85°', pbr: { baseColor: [0.02, 0.02, 0.02, 1], metallic: 1, roughness: 1 }, light: GRAZING, want: [GRAZING_WANT, GRAZING_WANT, GRAZING_WANT] },
  // m 0, roughness 1 (α 1), base 0.5: 0.1·0.5 + 0.2·(0.96·0.5 + 0.04/4) = 0.05 + 0.2·0.49 = 0.148.
  { name: 'a rough dielectric', pbr: { baseColor: [0.5, 0.5, 0.5, 1], metallic: 0, roughness: 1 }, want: [0.148, 0.148, 0.148] },
  // m 1, roughness 1, base (0.5, 0.8, 0.2): c_diff 0, F0 = base: 0.2·base/4 = 0.05·base.
  { name: 'a rough metal', pbr: { baseColor: [0.5, 0.8, 0.2, 1], metallic: 1, roughness: 1 }, want: [0.025, 0.04, 0.01] },
  // m 1, roughness 0.5 (α 0.25, 4α² = 0.25), base 0.5: 0.2·0.5/0.25 = 0.4.
  { name: 'a metal of roughness ½', pbr: { baseColor: [0.5, 0.5, 0.5, 1], metallic: 1, roughness: 0.5 }, want: [0.4, 0.4, 0.4] },
  // m ½, roughness 1, base (1, 0, 0): c_diff (0.5, 0, 0), F0 (0.52, 0.02, 0.02):
  // r = 0.1·0.5 + 0.2·(0.48·0.5 + 0.52/4) = 0.05 + 0.2·0.37 = 0.124; g = b = 0.2·0.02/4 = 0.001.
  { name: 'half metal', pbr: { baseColor: [1, 0, 0, 1], metallic: 0.5, roughness: 1 }, want: [0.124, 0.001, 0.001] },
  // Emissive adds: the rough dielectric + (0.3, 0.2, 0.1).
  { name: 'emissive', pbr: { baseColor: [0.5, 0.5, 0.5, 1], metallic: 0, roughness: 1 }, emissive: [0.3, 0.2, 0.1], want: [0.448, 0.348, 0.248] },
  // Unlit: the base colour, nothing else (the light and emissive are not its).
  { name: 'unlit', pbr: { baseColor: [0.2, 0.6, 0.8, 1], metallic: 1, roughness: 0, unlit: true }, want: [0.2, 0.6, 0.8] },
  // Roughness 0 is seen as α 0.002 by a directional light: 0.2·0.5/(4·0.002²) clips to 1.
  { name: 'a mirror metal', pbr: { baseColor: [0.5, 0.5, 0.5, 1], metallic: 1, roughness: 0 }, want: [1, 1, 1] },
];

/** The studio at intensity 1 (docs/pbr.md#the-environment). */
export const STUDIO: Environment = { kind: 'studio', intensity: 1 };

/** The grid of spheres with its two lights, in the studio. */
export const studioGrid = (): Scene => ({ ...sphereGrid(), environment: STUDIO });

const DEG = 180 / Math.PI;

/**
 * A box whose +Z face has the normal n halfway between the view (+z, the camera 4 in front of it) and the key panel's centre
 * (φ −45°, e 45°: d = (−½, √½, ½)): n = (v + d)/|v + d|. The box turned about X by −asin(n_y), then about Y by atan2(n_x, n_z).
 */
export function mirrorToKey(pbr = pbrMaterial({ baseColor: [0.1, 0.1, 0.1, 1], metallic: 1, roughness: 0 }), environment: Environment | null = STUDIO): Scene {
  const d = [-0.5, Math.SQRT1_2, 0.5], h = [d[0], d[1], d[2] + 1], len = Math.hypot(h[0], h[1], h[2]);
  const n = h.map((x) => x / len);
  const s = boxScene(pbr);
  const o = s.objects[0];
  return {
    ...s, lights: [], environment,
    objects: [{ ...o, transform: { ...o.transform, rotation: [-Math.asin(n[1]) * DEG, Math.atan2(n[0], n[2]) * DEG, 0] } }],
  };
}

/**
 * A sky of `width` × `width`/2 texels (docs/pbr.md#an-image), as an equirectangular .hdr would hold it: blue above the horizon,
 * lighter toward it; a warm ground below; a sun of radiance 40 and 6° across, high toward −z and +x (where the grid's camera
 * looks into it); linear light.
 */
export function skyImage(width = 128): EnvironmentImage {
  const height = width / 2, rgb = new Float32Array(width * height * 3), d = new Float64Array(3);
  const sun = [0.45, 0.6, -0.66], len = Math.hypot(...sun), cosSun = Math.cos((3 * Math.PI) / 180);
  for (let j = 0; j < height; j++) {
    for (let i = 0; i < width; i++) {
      imageDirection(d, (i + 0.5) / width, (j + 0.5) / height);
      const up = d[1], o = 3 * (j * width + i);
      if ((d[0] * sun[0] + d[1] * sun[1] + d[2] * sun[2]) / len > cosSun) rgb.set([40, 38, 34], o);
      else if (up >= 0) rgb.set([0.25 + 0.35 * (1 - up), 0.4 + 0.3 * (1 - up), 0.9], o);
      else rgb.set([0.3, 0.22, 0.15], o);
    }
  }
  return { width, height, rgb };
}

/** `image` as a scene's environment, at `intensity`. */
export const imageEnvironment = (image: EnvironmentImage, intensity = 1, url = 'https://example.test/sky.hdr'): Environment => ({ kind: 'image', intensity, url, image });
