// A glTF material's maps on the box face head-on to the camera and to a directional light (tests/unit/helpers/pbr-scenes.ts
// boxScene), each map a 1×1 image, the centre pixel worked out by hand in colour space none: shared by the CPU renderers'
// test (tests/unit/pbr-maps.test.ts) and the GLSL's (tests/e2e/pbr-maps.spec.ts).
import type { PbrMaterial, PbrTexture } from '../../../src/scene/pbr-material';
import type { Scene, Vec3 } from '../../../src/scene/scene';
import type { DecodedImage } from '../../../src/scene/decoded-image';
import { IA, ID, boxScene, pbrMaterial } from './pbr-scenes';
import { transformAsObj } from '../../../src/loaders/gltf/as-obj';

export const MR = 'https://example.com/metal rough.png', AO = 'https://example.com/occlusion.png', EM = 'https://example.com/emissive.png';

export const image = (r: number, g: number, b: number): DecodedImage => ({ width: 1, height: 1, data: new Uint8ClampedArray([r, g, b, 255]) });
export const IMAGES = new Map<string, DecodedImage>([[MR, image(0, 191, 255)], [AO, image(64, 0, 0)], [EM, image(255, 128, 0)]]);

/** A map of the scene value: `transform` in the scene's UV (the OBJ way up, as the element turns a file's: transformAsObj). */
export const map = (url: string, texCoord = 0, transform: readonly number[] | null = null): PbrTexture => ({
  source: { url }, texCoord, sampler: { magFilter: undefined, minFilter: undefined, wrapS: 10497, wrapT: 10497 }, transform,
});

/** A box of `pbr` with `emissive` (the element's Material.emissive: the factor times its strength). */
export const box = (over: Partial<PbrMaterial>, emissive?: Vec3): Scene => boxScene(pbrMaterial(over), emissive);

/** Head-on (N = V = L = H): Ia·c_diff·occlusion + Id·((1 − F0)·c_diff + F0/(4α²)), α = roughness², F0 = 0.04(1 − m) + base·m. */
export const lit = (base: number, metallic: number, roughness: number, occlusion = 1): number => {
  const cdiff = base * (1 - metallic), f0 = 0.04 * (1 - metallic) + base * metallic, a = roughness * roughness;
  return IA * cdiff * occlusion + ID * ((1 - f0) * cdiff + f0 / (4 * a * a));
};

/** 2×2 RGBA8, rows top first: (top left, top right, bottom left, bottom right). */
const quad = (...texels: [number, number, number][]): DecodedImage => ({ width: 2, height: 2, data: new Uint8ClampedArray(texels.flatMap((t) => [...t, 255])) });

const MR2 = 'https://example.com/metal rough 2×2.png', BASE2 = 'https://example.com/base 2×2.png';
/** glTF's scale (0, 0), offset (0.75, 0.25): every UV onto the top right texel's centre (v down), in the scene's UV. */
export const ONTO_TOP_RIGHT = transformAsObj([0, 0, 0.75, 0, 0, 0.25]);

const grey = (x: number): number[] => [x, x, x];
const GREY = [0.5, 0.5, 0.5, 1] as const;
const factorOnly = grey(lit(0.5, 1, 1));

export interface MapCase {
  name: string;
  scene: Scene;
  images: Map<string, DecodedImage>;
  /** The centre pixel, linear, in colour space none. */
  want: number[];
}

export const MAP_CASES: MapCase[] = [
  // G roughness, B metallic: (·, 191, 255) on factors 1, 1 is a metal of roughness 191/255.
  { name: 'metallic-roughness (·, 191, 255) on factors 1, 1', scene: box({ baseColor: GREY, metallic: 1, roughness: 1, metallicRoughnessTexture: map(MR) }), images: IMAGES, want: grey(lit(0.5, 1, 191 / 255)) },
  // The factors scale what the map gives: metallic ½ × 1, roughness 0.8 × 191/255.
  { name: 'metallic-roughness on factors ½, 0.8', scene: box({ baseColor: GREY, metallic: 0.5, roughness: 0.8, metallicRoughnessTexture: map(MR) }), images: IMAGES, want: grey(lit(0.5, 0.5, 0.8 * 191 / 255)) },
  // B is metallic, not R: (0, 191, 0) makes a metal a dielectric.
  { name: 'metallic-roughness (0, 191, 0): B is metallic', scene: box({ baseColor: GREY, metallic: 1, roughness: 1, metallicRoughnessTexture: map(MR) }), images: new Map([[MR, image(0, 191, 0)]]), want: grey(lit(0.5, 0, 191 / 255)) },
  // 1 + strength·(R − 1) dims the ambient term, not the direct light.
  ...[0.5, 1].map((strength) => ({
    name: `occlusion R 64 at strength ${strength}`, images: IMAGES,
    scene: box({ baseColor: GREY, metallic: 0, roughness: 1, occlusionTexture: map(AO), occlusionStrength: strength }),
    want: grey(lit(0.5, 0, 1, 1 + strength * (64 / 255 - 1))),
  })),
  // The emission times the map: (255, 128, 0) on (0.3, 0.2, 0.1).
  { name: 'emissive (255, 128, 0) on (0.3, 0.2, 0.1)', scene: box({ baseColor: GREY, metallic: 0, roughness: 1, emissiveTexture: map(EM) }, [0.3, 0.2, 0.1]), images: IMAGES, want: [1, 128 / 255, 0].map((t, k) => lit(0.5, 0, 1) + [0.3, 0.2, 0.1][k] * t) },
  // KHR_texture_transform: scale 0 and offset (0.75, 0.25) in glTF's UV read the top right texel's centre everywhere, exactly.
  {
    name: 'a transform onto one texel: the metallic-roughness map\'s top right (·, 191, 255) among (·, 40, 0)', want: grey(lit(0.5, 1, 191 / 255)),
    images: new Map([[MR2, quad([0, 40, 0], [0, 191, 255], [0, 40, 0], [0, 40, 0])]]),
    scene: box({ baseColor: GREY, metallic: 1, roughness: 1, metallicRoughnessTexture: map(MR2, 0, ONTO_TOP_RIGHT) }),
  },
  {
    name: 'a transform onto one texel: the base colour texture\'s top right (128) among (255)', want: grey(lit(128 / 255, 0, 1)),
    images: new Map([[BASE2, quad([255, 255, 255], [128, 128, 128], [255, 255, 255], [255, 255, 255])]]),
    scene: ((s: Scene) => ({ ...s, objects: [{ ...s.objects[0], material: { ...s.objects[0].material, texture: { kind: 'image' as const, url: BASE2 } } }] }))(
      box({ baseColor: [1, 1, 1, 1], metallic: 0, roughness: 1, baseColorTexture: map(BASE2, 0, ONTO_TOP_RIGHT) })),
  },
  // An emission without its map beside a metallic-roughness map: the factor alone, whatever that map's texel.
  { name: 'an emissive factor without a map, beside a metallic-roughness map', scene: box({ baseColor: GREY, metallic: 1, roughness: 1, metallicRoughnessTexture: map(MR) }, [0.3, 0.2, 0.1]), images: IMAGES, want: [0.3, 0.2, 0.1].map((e) => lit(0.5, 1, 191 / 255) + e) },
  // An emissive map whose image is missing, beside a metallic-roughness map: the factor alone, not times that map's texel.
  { name: 'an emissive map whose image is missing, beside a metallic-roughness map', scene: box({ baseColor: GREY, metallic: 1, roughness: 1, metallicRoughnessTexture: map(MR), emissiveTexture: map('https://example.com/no emission.png') }, [0.3, 0.2, 0.1]), images: IMAGES, want: [0.3, 0.2, 0.1].map((e) => lit(0.5, 1, 191 / 255) + e) },
  // An emissive map on a black emissive factor (the element gives such a material no Material.emissive): nothing given off.
  { name: 'an emissive map on a black factor: nothing given off', scene: box({ baseColor: GREY, metallic: 0, roughness: 1, emissiveTexture: map(EM) }), images: IMAGES, want: grey(lit(0.5, 0, 1)) },
  // Under another mapping the emissive map is not read either: the factor alone.
  {
    name: 'an emissive map under the triplanar mapping: the factor alone', images: IMAGES, want: [0.3, 0.2, 0.1].map((e) => lit(0.5, 0, 1) + e),
    scene: ((sc: Scene) => ({ ...sc, objects: [{ ...sc.objects[0], material: { ...sc.objects[0].material, mapping: 'triplanar' as const } }] }))(
      box({ baseColor: GREY, metallic: 0, roughness: 1, emissiveTexture: map(EM) }, [0.3, 0.2, 0.1])),
  },
  // Not read, the factor alone: the image missing; on TEXCOORD_1; under a mapping other than uv (the maps follow the mesh's UV).
  // (A URL no case gives an image for: the GLSL's page keeps the images of the draws before.)
  { name: 'a map whose image is missing', scene: box({ baseColor: GREY, metallic: 1, roughness: 1, metallicRoughnessTexture: map('https://example.com/gone.png') }), images: new Map(), want: factorOnly },
  { name: 'a map on TEXCOORD_1', scene: box({ baseColor: GREY, metallic: 1, roughness: 1, metallicRoughnessTexture: map(MR, 1) }), images: IMAGES, want: factorOnly },
  {
    name: 'maps under the triplanar mapping', images: IMAGES, want: factorOnly,
    scene: ((s: Scene) => ({ ...s, objects: [{ ...s.objects[0], material: { ...s.objects[0].material, mapping: 'triplanar' as const } }] }))(
      box({ baseColor: GREY, metallic: 1, roughness: 1, metallicRoughnessTexture: map(MR), occlusionTexture: map(AO) })),
  },
];


/**
 * Which way up a map is read: each map 2×2 with a texel of its own per quadrant, magnified over the face (filtered between
 * them), the whole face compared between renderers — a map read at (u, v) for (u, 1 − v), or with its channels swapped,
 * moves the quadrants.
 */
export const QUADRANTS: MapCase = {
  name: 'three 2×2 maps on the face', want: [],
  images: new Map([
    [MR, quad([0, 40, 255], [0, 230, 255], [0, 120, 0], [0, 255, 128])],
    [AO, quad([255, 0, 0], [30, 0, 0], [160, 0, 0], [90, 0, 0])],
    [EM, quad([0, 0, 0], [255, 0, 0], [0, 80, 255], [200, 200, 0])],
  ]),
  scene: box({
    baseColor: [0.6, 0.5, 0.4, 1], metallic: 1, roughness: 1, metallicRoughnessTexture: map(MR), occlusionTexture: map(AO), emissiveTexture: map(EM),
  }, [0.3, 0.3, 0.3]),
};

/** KHR_texture_transform's T·R·S in glTF's UV (loaders/gltf/materials.ts), then in the scene's. */
const gltfTransform = (r: number, [sx, sy]: [number, number], [ox, oy]: [number, number]): number[] => {
  const c = Math.cos(r), s = Math.sin(r);
  return transformAsObj([c * sx, s * sy, ox, -s * sx, c * sy, oy]);
};
const MOVED = gltfTransform(0.4, [1.7, 0.8], [0.15, -0.2]);

/** QUADRANTS with every map, and a base colour texture, moved by one transform (rotated, scaled, offset): the renderers compared. */
export const QUADRANTS_MOVED: MapCase = {
  name: 'three 2×2 maps and a base colour texture on the face, transformed', want: [],
  images: new Map([...QUADRANTS.images, [BASE2, quad([255, 255, 255], [128, 128, 128], [60, 200, 90], [255, 255, 255])]]),
  scene: ((s: Scene) => ({ ...s, objects: [{ ...s.objects[0], material: { ...s.objects[0].material, texture: { kind: 'image' as const, url: BASE2 } } }] }))(box({
    baseColor: [0.6, 0.5, 0.4, 1], metallic: 1, roughness: 1, baseColorTexture: map(BASE2, 0, MOVED), metallicRoughnessTexture: map(MR, 0, MOVED),
    occlusionTexture: map(AO, 0, MOVED), emissiveTexture: map(EM, 0, MOVED),
  }, [0.3, 0.3, 0.3])),
};

// ---- the normal map (docs/gltf.md#the-normal-map) ----

export const NM = 'https://example.com/normal.png';
/** A texel's tangent-space vector, 2·byte/255 − 1 each. */
const unpack = (r: number, g: number, b: number): number[] => [r, g, b].map((c) => (2 * c) / 255 - 1);

/**
 * The glTF BRDF of a rough dielectric (roughness 1: D = 1/π, Vis = ½/(n·l + n·v)) of base 0.5 at the normal `n` (unit),
 * lit by a directional light towards `l` (Ia IA, Id ID), seen along v = +z: Ia·c_diff + π·f·Id·(n·l).
 */
function roughDielectric(n: number[], l: number[]): number {
  const v = [0, 0, 1], dot = (a: number[], b: number[]) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const hl = Math.hypot(l[0] + v[0], l[1] + v[1], l[2] + v[2]), h = [0, 1, 2].map((k) => (l[k] + v[k]) / hl);
  const nl = dot(n, l), nv = dot(n, v), f = 0.04 + 0.96 * (1 - dot(v, h)) ** 5;
  const brdf = ((1 - f) * 0.5) / Math.PI + (f * (1 / Math.PI) * 0.5) / (nl + nv);
  return IA * 0.5 + Math.PI * brdf * ID * nl;
}

/** The unit quad of z = 0, counter-clockwise from +z, its UVs the OBJ way up, its tangents +x with w = +1: B = N × T = +y. */
const MAPPED_QUAD = {
  positions: new Float32Array([-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0]),
  normals: new Float32Array([0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1]),
  uvs: new Float32Array([0, 0, 1, 0, 1, 1, 0, 1]),
  indices: new Uint16Array([0, 1, 2, 0, 2, 3]),
  tangents: new Float32Array([1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1]),
};

/** The quad with a normal map (NM) of `scale`, turned `turn`° about Y, double-sided or not, under the light towards `l`. */
function normalMapped(scale: number, l: number[], turn = 0, doubleSided = false, url = NM): Scene {
  const s = box({ baseColor: [0.5, 0.5, 0.5, 1], metallic: 0, roughness: 1, normalTexture: map(url), normalScale: scale, doubleSided });
  const o = s.objects[0];
  return {
    ...s, lights: [{ ...s.lights[0], vector: l as [number, number, number] }],
    objects: [{ ...o, geometry: { kind: 'mesh', key: 'mapped quad', data: MAPPED_QUAD }, bounds: { center: [0, 0, 0], radius: Math.SQRT2 }, transform: { ...o.transform, rotation: [0, turn, 0] } }],
  };
}

const HEAD_ON = [0, 0, 1], FROM_ABOVE = [0, Math.sin(Math.PI / 6), Math.cos(Math.PI / 6)], FROM_THE_SIDE = [Math.sin(Math.PI / 6), 0, Math.cos(Math.PI / 6)];

/** `s` with its quad's tangents replaced by `t` (xyzw at every vertex). */
const withTangents = (s: Scene, t: number[], key: string): Scene => {
  const o = s.objects[0], g = o.geometry as { kind: 'mesh'; key: string; data: typeof MAPPED_QUAD };
  return { ...s, objects: [{ ...o, geometry: { ...g, key, data: { ...g.data, tangents: new Float32Array([0, 1, 2, 3].flatMap(() => t)) } } }] };
};
const unit = (a: number[]) => a.map((x) => x / Math.hypot(...a));

export const NORMAL_CASES: MapCase[] = [
  // (218, 128, 218): tilted ~45° towards the tangent (+x).
  { name: 'a texel tilting the normal towards T', scene: normalMapped(1, HEAD_ON), images: new Map([[NM, image(218, 128, 218)]]), want: grey(roughDielectric(unit(unpack(218, 128, 218)), HEAD_ON)) },
  // (128, 218, 218): tilted towards the bitangent N × T = +y, the image's top: towards a light from above, brighter.
  { name: 'a texel tilting the normal towards B, the image\'s top, under a light from above', scene: normalMapped(1, FROM_ABOVE), images: new Map([[NM, image(128, 218, 218)]]), want: grey(roughDielectric(unit(unpack(128, 218, 218)), FROM_ABOVE)) },
  // The scale multiplies x and y: ½.
  { name: 'normalScale ½', scene: normalMapped(0.5, HEAD_ON), images: new Map([[NM, image(218, 128, 218)]]), want: grey(roughDielectric(unit(unpack(218, 128, 218).map((c, k) => (k < 2 ? c / 2 : c))), HEAD_ON)) },
  // Double-sided, seen from its front: as single-sided (nothing turned).
  { name: 'double-sided, seen from its front', scene: normalMapped(1, HEAD_ON, 0, true), images: new Map([[NM, image(218, 128, 218)]]), want: grey(roughDielectric(unit(unpack(218, 128, 218)), HEAD_ON)) },
  // Seen from behind, double-sided: the perturbed normal turned to the viewer whole (its z as from the front).
  { name: 'double-sided, seen from behind', scene: normalMapped(1, HEAD_ON, 180, true), images: new Map([[NM, image(218, 128, 218)]]), want: grey(roughDielectric(unit(unpack(218, 128, 218)).map((c, k) => (k === 2 ? c : -c)), HEAD_ON)) },
  // Turned a quarter about its normal (Z): the tangent goes through the model matrix to +y, B = N × T to −x; the tilt towards T
  // now faces the light from above.
  {
    name: 'the quad turned a quarter about its normal: the tangent through the model matrix', images: new Map([[NM, image(218, 128, 218)]]),
    scene: ((s: Scene) => ({ ...s, objects: [{ ...s.objects[0], transform: { ...s.objects[0].transform, rotation: [0, 0, 90] as [number, number, number] } }] }))(normalMapped(1, FROM_ABOVE)),
    want: grey(roughDielectric(unit(((t) => [-t[1], t[0], t[2]])(unpack(218, 128, 218))), FROM_ABOVE)),
  },
  // Single-sided, its normals against its winding (a file's fault): seen from its front, the normal faces away and is not
  // turned: no direct light, the ambient term alone (0.1 · 0.5).
  {
    name: 'single-sided, its normals against its winding: not turned to the viewer', images: new Map([[NM, image(218, 128, 218)]]), want: grey(IA * 0.5),
    scene: ((s: Scene) => {
      const o = s.objects[0], g = o.geometry as { kind: 'mesh'; key: string; data: typeof MAPPED_QUAD };
      const data = { ...g.data, normals: g.data.normals.map((x) => -x) };
      return { ...s, objects: [{ ...o, geometry: { ...g, key: 'inside-out quad', data } }] };
    })(normalMapped(1, HEAD_ON)),
  },
  // Seen from behind under a light from the side: the perturbed normal turned whole, its tilt along T kept (x, −y, z in the
  // world, T turned to −x, B = w·(N × T) = +y): a frame turned before the perturbation would tilt it the other way.
  {
    name: 'double-sided, seen from behind, under a light from the side', scene: normalMapped(1, FROM_THE_SIDE, 180, true), images: new Map([[NM, image(218, 128, 218)]]),
    want: grey(roughDielectric(unit(((t) => [t[0], -t[1], t[2]])(unpack(218, 128, 218))), FROM_THE_SIDE)),
  },
  // normalScale ½ on a texel tilting towards B, under a light from above: x and y halved.
  { name: 'normalScale ½ towards B, under a light from above', scene: normalMapped(0.5, FROM_ABOVE), images: new Map([[NM, image(128, 218, 218)]]), want: grey(roughDielectric(unit(unpack(128, 218, 218).map((c, k) => (k < 2 ? c / 2 : c))), FROM_ABOVE)) },
  // A tangent three times as long: made unit before the frame is built (as it is after a scaling transform, or interpolated).
  { name: 'a tangent three times as long', scene: withTangents(normalMapped(1, FROM_ABOVE), [3, 0, 0, 1], 'long tangents'), images: new Map([[NM, image(128, 218, 218)]]), want: grey(roughDielectric(unit(unpack(128, 218, 218)), FROM_ABOVE)) },
  // A zero tangent (a file's, kept zero): no frame to turn in, the interpolated normal.
  { name: 'a zero tangent: the interpolated normal', scene: withTangents(normalMapped(1, HEAD_ON), [0, 0, 0, 1], 'zero tangents'), images: new Map([[NM, image(218, 128, 218)]]), want: grey(0.148) },
  // Under a mapping other than uv the normal map is not read, as the other maps are not.
  {
    name: 'the normal map under the triplanar mapping: not read', images: new Map([[NM, image(218, 128, 218)]]), want: grey(0.148),
    scene: ((s: Scene) => ({ ...s, objects: [{ ...s.objects[0], material: { ...s.objects[0].material, mapping: 'triplanar' as const } }] }))(normalMapped(1, HEAD_ON)),
  },
  // The image missing (a URL no case gives one for): the interpolated normal (0.148, tests/unit/helpers/double-sided.ts).
  { name: 'a normal map whose image is missing', scene: normalMapped(1, HEAD_ON, 0, false, 'https://example.com/no normal.png'), images: new Map(), want: grey(0.148) },
];

/** QUADRANTS_MOVED's box with every texture under the glTF transform rotation `r`, scale, offset (its images: QUADRANTS_MOVED's). */
export function quadrantsUnder(r: number, scale: [number, number], offset: [number, number]): Scene {
  const t = gltfTransform(r, scale, offset), o = QUADRANTS_MOVED.scene.objects[0], p = o.material.pbr!;
  const pbr = {
    ...p, baseColorTexture: map(BASE2, 0, t), metallicRoughnessTexture: map(MR, 0, t), occlusionTexture: map(AO, 0, t), emissiveTexture: map(EM, 0, t),
  };
  return { ...QUADRANTS_MOVED.scene, objects: [{ ...o, material: { ...o.material, pbr } }] };
}

// ---- vertex colours (docs/gltf.md#vertex-colours) ----

/**
 * MAPPED_QUAD with COLOR_0 red, green, blue, white at its corners (0, 1, 2, 3): its centre lies on the diagonal 0–2 the two
 * triangles share, where the colour is half red, half blue. A rough dielectric of base 0.5 head-on: per channel
 * Ia·b + Id·(0.96·b + 0.01), b = 0.5·colour.
 */
export const COLOURED: MapCase = (() => {
  const s = normalMapped(1, HEAD_ON, 0, false, 'https://example.com/no normal.png');
  const o = s.objects[0], g = o.geometry as { kind: 'mesh'; key: string; data: typeof MAPPED_QUAD };
  const data = { ...g.data, colors: new Float32Array([1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1]) };
  const want = [0.5, 0, 0.5].map((c) => IA * 0.5 * c + ID * (0.96 * 0.5 * c + 0.01));
  return { name: 'vertex colours', images: new Map(), want, scene: { ...s, objects: [{ ...o, geometry: { ...g, key: 'coloured quad', data } }] } };
})();

/**
 * A normal-mapped quad in no special pose: turned about all three axes, its vertex normals leaning off its face and its tangents
 * off the normals (so that every term of the frame's making counts), a 2×2 normal map, under both lights: the renderers compared.
 */
export const TILTED_NORMAL_MAP: MapCase = (() => {
  const s = normalMapped(1, [-0.4, 0.8, 0.6], 0, true);
  const o = s.objects[0], g = o.geometry as { kind: 'mesh'; key: string; data: typeof MAPPED_QUAD };
  // Tangents three times unit length (made unit before use), the quad double-sided (seen from its front: nothing turned).
  const n = unit([0.2, -0.15, 1]), t = [3, 0.9, 1.2, -1];
  const data = { ...g.data, normals: new Float32Array([0, 1, 2, 3].flatMap(() => n)), tangents: new Float32Array([0, 1, 2, 3].flatMap(() => t)) };
  return {
    name: 'a tilted normal-mapped quad', want: [],
    images: new Map([[NM, quad([218, 128, 218], [128, 60, 230], [40, 200, 200], [160, 170, 240])]]),
    scene: { ...s, objects: [{ ...o, transform: { ...o.transform, rotation: [25, -35, 15] as [number, number, number] }, geometry: { ...g, key: 'tilted quad', data } }] },
  };
})();

/**
 * A checker map (2×2, white and black) as the emission of a quad seen at a slant, under a transform that turns and shrinks it: the
 * texture's axes fall skewed on the screen, so a footprint's size along the stripes hangs on the transform's cross terms.
 */
export const SLANTED_STRIPES: MapCase = (() => {
  const stripes = 'https://example.com/stripes.png';
  const s = normalMapped(1, HEAD_ON, 0, false, 'https://example.com/no normal.png');
  const o = s.objects[0];
  const pbr = { ...o.material.pbr!, baseColor: [0.2, 0.2, 0.2, 1] as [number, number, number, number], emissiveTexture: map(stripes, 0, gltfTransform(0.7, [9, 2], [0.1, 0.3])) };
  return {
    name: 'slanted stripes', want: [], images: new Map([[stripes, quad([255, 255, 255], [0, 0, 0], [0, 0, 0], [255, 255, 255])]]),
    scene: { ...s, objects: [{ ...o, transform: { ...o.transform, rotation: [-55, 40, 10] as [number, number, number] }, material: { ...o.material, emissive: [0.8, 0.8, 0.8] as [number, number, number], pbr } }] },
  };
})();
