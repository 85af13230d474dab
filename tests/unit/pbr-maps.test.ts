// A glTF material's metallic-roughness, occlusion and emissive maps (docs/gltf.md#drawing) in the float64 reference and the
// software renderer: the box face head-on to the camera and to a directional light of tests/unit/pbr-shading.test.ts, each
// map a 1×1 image, the centre pixel worked out by hand (the reference to 1e-12, the software renderer to the 8-bit level);
// a map whose image is missing, on TEXCOORD_1, or under another mapping is not read (the factor alone); occlusion dims the
// environment's light (the mirror metal reflecting the key panel) and the ambient term, not the lights' direct light.
import { describe, expect, it } from 'vitest';
import { compareImages, renderScene } from '../../src/reference';
import { SoftwareRenderer } from '../../src/software';
import { Lights } from '../../src/software/lighting';
import { pbrFragment } from '../../src/software/pbr-fragment';
import type { MipTexture } from '../../src/software/mip-texture';
import { pbrMaterial } from './helpers/pbr-scenes';
import { prepareEnvironment } from '../../src/frame/environment-light';
import { srgbToLinear, linearToSrgb } from '../../src/math/srgb';
import type { Scene } from '../../src/scene/scene';
import type { DecodedImage } from '../../src/scene/decoded-image';
import { BOX_STATE as STATE, ID, STUDIO, mirrorToKey } from './helpers/pbr-scenes';
import { AO, COLOURED, EM, IMAGES, MAP_CASES, NORMAL_CASES, QUADRANTS, QUADRANTS_MOVED, SLANTED_STRIPES, TILTED_NORMAL_MAP, box, map, quadrantsUnder } from './helpers/pbr-map-cases';

const CENTRE = 16 * 33 + 16;
/** The centre pixel of `scene` by the reference (linear, unclamped) and the software renderer (8-bit). */
function centre(scene: Scene, images: Map<string, DecodedImage> | null = IMAGES, state = STATE): { ref: number[]; soft: number[] } {
  const ref = renderScene(scene, state, images, { samplesPerAxis: 1 }).rgb;
  const soft = new SoftwareRenderer({ samplesPerAxis: 1 }).render(scene, state, images);
  return { ref: [0, 1, 2].map((k) => ref[3 * CENTRE + k]), soft: [0, 1, 2].map((k) => soft[4 * CENTRE + k]) };
}

function expectCentre(scene: Scene, want: readonly number[], label: string, images: Map<string, DecodedImage> | null = IMAGES): void {
  const { ref, soft } = centre(scene, images);
  want.forEach((w, k) => {
    expect(ref[k], `${label}: reference channel ${k}`).toBeCloseTo(w, 12);
    expect(soft[k], `${label}: software channel ${k}`).toBe(Math.round(Math.min(w, 1) * 255));
  });
}

describe('each map on the box, worked by hand: the reference to 1e-12, the software renderer to the 8-bit level', () => {
  for (const c of MAP_CASES) it(c.name, () => expectCentre(c.scene, c.want, c.name, c.images));
});

describe('the occlusion map', () => {
  it('dims the environment: the mirror metal reflecting the key panel, times 64/255 (the reference\'s own stream, the same directions)', () => {
    prepareEnvironment(STUDIO);
    const plain = mirrorToKey();
    const o = plain.objects[0], pbr = { ...o.material.pbr!, occlusionTexture: map(AO) };
    const dimmed: Scene = { ...plain, objects: [{ ...o, material: { ...o.material, pbr } }] };
    const a = centre(plain), b = centre(dimmed);
    const k = 64 / 255;
    const hand = 6 * (0.1 + 0.9 * (1 - 1.5 / Math.sqrt(3)) ** 5);
    for (let c = 0; c < 3; c++) {
      // Not dimmed: the reference's Monte Carlo within its stratification of the hand value (1/76.8 of it at 1 sample a pixel:
      // tests/unit/environment-light.test.ts), so the ratio below is of light, not of two zeros.
      expect(Math.abs(a.ref[c] - hand), `reference channel ${c} undimmed`).toBeLessThan(hand / 76.8);
      expect(b.ref[c], `reference channel ${c}`).toBeCloseTo(a.ref[c] * k, 12);
      // 6·F(n·v) = 0.60023 (tests/unit/environment-light.test.ts) times 64/255: 38.4.
      expect(b.soft[c], `software channel ${c}`).toBe(Math.round(6 * (0.1 + 0.9 * (1 - 1.5 / Math.sqrt(3)) ** 5) * k * 255));
    }
  });
});

describe('the emissive map', () => {
  it('is colour: decoded to linear light in srgb (128 → 0.2158), the frame encoded once', () => {
    const state = { ...STATE, colorSpace: 'srgb' as const };
    const scene = box({ baseColor: [0, 0, 0, 1], metallic: 0, roughness: 1, emissiveTexture: map(EM) }, [0.5, 0.5, 0.5]);
    const { ref, soft } = centre(scene, IMAGES, state);
    const want = [1, srgbToLinear(128 / 255), 0].map((t) => 0.5 * t + ID * 0.04 / 4);
    want.forEach((w, k) => {
      // The reference's rgb is the frame's value, encoded.
      expect(ref[k], `reference channel ${k}`).toBeCloseTo(linearToSrgb(w), 12);
      expect(Math.abs(soft[k] - linearToSrgb(w) * 255), `software channel ${k}`).toBeLessThanOrEqual(0.5);
    });
  });
});

describe('which way up', () => {
  it('2×2 maps over the face: the software renderer against the reference (each reads images its own way)', () => {
    const state = { ...STATE, width: 65, height: 65 };
    const ref = renderScene(QUADRANTS.scene, state, QUADRANTS.images, { samplesPerAxis: 4 });
    const soft = new SoftwareRenderer({ samplesPerAxis: 4 }).render(QUADRANTS.scene, state, QUADRANTS.images);
    const psnr = compareImages(ref, soft).psnr;
    // The same maps flipped top to bottom: what reading them the wrong way up would give.
    const flip = (im: DecodedImage): DecodedImage => ({ ...im, data: new Uint8ClampedArray([...im.data.slice(8), ...im.data.slice(0, 8)]) });
    const flipped = new Map([...QUADRANTS.images].map(([u, im]) => [u, flip(im)]));
    const wrong = compareImages(ref, new SoftwareRenderer({ samplesPerAxis: 4 }).render(QUADRANTS.scene, state, flipped)).psnr;
    // Measured: objects 59.2 dB (flipped: 9.2); the bound 2 dB under.
    expect(psnr.objects, `objects ${psnr.objects.toFixed(1)} dB`).toBeGreaterThan(57.2);
    expect(wrong.objects, `flipped: objects ${wrong.objects.toFixed(1)} dB`).toBeLessThan(20);
  });

  it('2×2 maps and a base colour texture under one KHR_texture_transform: the software renderer against the reference', () => {
    // In srgb: the base colour and the emission decoded as colour, the metallic-roughness and occlusion maps not.
    const state = { ...STATE, width: 65, height: 65, colorSpace: 'srgb' as const };
    const ref = renderScene(QUADRANTS_MOVED.scene, state, QUADRANTS_MOVED.images, { samplesPerAxis: 4 });
    const soft = new SoftwareRenderer({ samplesPerAxis: 4 }).render(QUADRANTS_MOVED.scene, state, QUADRANTS_MOVED.images);
    const psnr = compareImages(ref, soft).psnr;
    // Untransformed, the same scene: what ignoring the transforms would score.
    const still = (m: NonNullable<Scene['objects'][0]['material']['pbr']>) => ({ ...m, baseColorTexture: m.baseColorTexture && { ...m.baseColorTexture, transform: null },
      metallicRoughnessTexture: { ...m.metallicRoughnessTexture!, transform: null }, occlusionTexture: { ...m.occlusionTexture!, transform: null }, emissiveTexture: { ...m.emissiveTexture!, transform: null } });
    const o = QUADRANTS_MOVED.scene.objects[0];
    const plain: Scene = { ...QUADRANTS_MOVED.scene, objects: [{ ...o, material: { ...o.material, pbr: still(o.material.pbr!) } }] };
    const wrong = compareImages(ref, new SoftwareRenderer({ samplesPerAxis: 4 }).render(plain, state, QUADRANTS_MOVED.images)).psnr;
    // Measured: objects 58.6 dB (the transforms ignored: 11.1); the bound 2 dB under.
    expect(psnr.objects, `objects ${psnr.objects.toFixed(1)} dB`).toBeGreaterThan(56.6);
    expect(wrong.objects, `untransformed: objects ${wrong.objects.toFixed(1)} dB`).toBeLessThan(20);
  });
});

describe('the normal map, on a quad with tangents, worked by hand: the reference to 1e-12, the software renderer to the 8-bit level', () => {
  for (const c of NORMAL_CASES) it(c.name, () => expectCentre(c.scene, c.want, c.name, c.images));
});

describe('a transform that shrinks the maps many times over (every pixel a footprint of many texels)', () => {
  it('the software renderer\'s mip levels and the reference\'s footprints follow the transform\'s linear part', () => {
    // One sample a pixel both: the software renderer's derivatives and the reference's ray differentials span a pixel.
    const state = { ...STATE, width: 65, height: 65, colorSpace: 'srgb' as const };
    const scene = quadrantsUnder(0.5, [21, 3.5], [0.3, 0.1]);
    const soft = new SoftwareRenderer({ samplesPerAxis: 1 }).render(scene, state, QUADRANTS_MOVED.images);
    const box = compareImages(renderScene(scene, state, QUADRANTS_MOVED.images, { samplesPerAxis: 1, textureFilter: 'box' }), soft).psnr;
    const point = compareImages(renderScene(scene, state, QUADRANTS_MOVED.images, { samplesPerAxis: 1, textureFilter: 'point' }), soft).psnr;
    // Measured: 34.1 dB against the reference's exact mean over each pixel's footprint (mip levels and 16 anisotropic taps
    // approximate it); 13.9 against its point samples, what a footprint left untransformed comes near.
    expect(box.objects, `objects ${box.objects.toFixed(1)} dB`).toBeGreaterThan(32.1);
    expect(point.objects, `point-sampled: objects ${point.objects.toFixed(1)} dB`).toBeLessThan(20);
  });
});

describe('where the maps are not read', () => {
  it('without images at all, a glTF material with maps draws its factors (the software renderer)', () => {
    const scene = box({ baseColor: [0.5, 0.5, 0.5, 1], metallic: 1, roughness: 1, metallicRoughnessTexture: map(AO), emissiveTexture: map(EM) });
    const none = new SoftwareRenderer({ samplesPerAxis: 1 }).render(scene, STATE);
    const factors = new SoftwareRenderer({ samplesPerAxis: 1 }).render(box({ baseColor: [0.5, 0.5, 0.5, 1], metallic: 1, roughness: 1 }), STATE);
    expect(Buffer.from(none).equals(Buffer.from(factors))).toBe(true);
  });

  it('under another mapping, the base colour texture follows it without its transform (both CPU renderers)', () => {
    const base = 'https://example.com/base under triplanar.png';
    const images = new Map([[base, QUADRANTS_MOVED.images.get('https://example.com/base 2×2.png')!]]);
    const draw = (transform: number[] | null) => {
      const s = box({ baseColor: [1, 1, 1, 1], metallic: 0, roughness: 1, baseColorTexture: map(base, 0, transform) });
      const o = s.objects[0];
      const scene: Scene = { ...s, objects: [{ ...o, material: { ...o.material, texture: { kind: 'image', url: base }, mapping: 'triplanar' } }] };
      const state = { ...STATE, width: 65, height: 65 };
      return { ref: renderScene(scene, state, images, { samplesPerAxis: 1 }).rgba, soft: new SoftwareRenderer({ samplesPerAxis: 1 }).render(scene, state, images) };
    };
    const moved = draw([3, 1, 0.2, -1, 2, 0.4]), plain = draw(null);
    expect(Buffer.from(moved.ref).equals(Buffer.from(plain.ref)), 'reference').toBe(true);
    expect(Buffer.from(moved.soft).equals(Buffer.from(plain.soft)), 'software').toBe(true);
  });
});

describe('vertex colours', () => {
  it('multiply the base colour, interpolated across the triangle: half red, half blue on the quad\'s diagonal (by hand)', () => {
    expectCentre(COLOURED.scene, COLOURED.want, COLOURED.name, COLOURED.images);
  });

  it('are not read for a material that is not glTF\'s (an OBJ\'s `v x y z r g b` stays as it was drawn)', () => {
    const o = COLOURED.scene.objects[0];
    const obj: Scene = { ...COLOURED.scene, objects: [{ ...o, material: { ...o.material, pbr: undefined } }] };
    const plain = (o.geometry as { data: object }).data;
    const without: Scene = { ...obj, objects: [{ ...obj.objects[0], geometry: { kind: 'mesh', key: 'plain', data: { ...plain, colors: undefined } as never } }] };
    const draw = (s: Scene) => Buffer.from(new SoftwareRenderer({ samplesPerAxis: 1 }).render(s, STATE));
    expect(draw(obj).equals(draw(without))).toBe(true);
    expect(Buffer.from(renderScene(obj, STATE, null).rgba).equals(Buffer.from(renderScene(without, STATE, null).rgba))).toBe(true);
  });
});

describe('the normal map in no special pose', () => {
  it('the software renderer against the reference (each turns the normal its own way)', () => {
    const state = { ...STATE, width: 65, height: 65, colorSpace: 'srgb' as const };
    const c = TILTED_NORMAL_MAP;
    const ref = renderScene(c.scene, state, c.images, { samplesPerAxis: 4 });
    const soft = new SoftwareRenderer({ samplesPerAxis: 4 }).render(c.scene, state, c.images);
    const flat = new SoftwareRenderer({ samplesPerAxis: 4 }).render(c.scene, state, new Map());
    const psnr = compareImages(ref, soft).psnr, without = compareImages(ref, flat).psnr;
    // Measured: 60.0 dB; the map left out, 26.5.
    expect(psnr.objects, `objects ${psnr.objects.toFixed(1)} dB`).toBeGreaterThan(58);
    expect(without.objects, `without the map: objects ${without.objects.toFixed(1)} dB`).toBeLessThan(35);
  });
});

describe('a transform\'s cross terms in the footprint', () => {
  it('slanted stripes under a turned, shrunk transform: the CPU renderer against the reference\'s exact footprints, within 0.3 dB of the figure', () => {
    // The texture's axes fall skewed on the screen, so each footprint's shape depends on the transform's cross terms. Both
    // images are deterministic (one sample a pixel, no random stream): the margin is the figure's rounding, not noise. The
    // CPU renderer's anisotropic read approximates a footprint (SwiftShader's rule: taps along one derivative), so a flipped
    // cross term can move its agreement either way (38.3, 45.8, 33.2, 38.3 dB measured); the lookup itself is tied by hand below.
    const state = { ...STATE, width: 65, height: 65, colorSpace: 'srgb' as const };
    const c = SLANTED_STRIPES;
    const soft = new SoftwareRenderer({ samplesPerAxis: 1 }).render(c.scene, state, c.images);
    const p = compareImages(renderScene(c.scene, state, c.images, { samplesPerAxis: 1, textureFilter: 'box' }), soft).psnr;
    // Measured: objects 37.8 dB.
    expect(p.objects, `objects ${p.objects.toFixed(2)} dB`).toBeGreaterThan(37.5);
  });
});

describe('a transform moves a lookup and its derivatives (the CPU renderer), by hand', () => {
  it('u\' = a·u + b·v + c, v\' = d·u + e·v + f, each derivative through the linear part: the lookup every map is read at', () => {
    // A texture that records what it is asked for, as each of the four maps and the base colour texture.
    const asked: number[][] = [];
    const recorder = { sample: (l: Float64Array, out: Float64Array) => { asked.push([...l]); out.fill(1); } } as unknown as MipTexture;
    const m = [2, 3, 0.5, -1, 4, 0.25];
    const pbr = pbrMaterial({
      baseColorTexture: map('base', 0, m), metallicRoughnessTexture: map('mr', 0, m), occlusionTexture: map('ao', 0, m), emissiveTexture: map('em', 0, m),
    });
    const lights = new Lights();
    lights.set(box(pbr), [0, 0, 1], [0, 0, 4]);
    const lookup = new Float64Array([0.1, 0.2, 0.01, 0.02, 0.03, 0.05]);
    const g = new Float64Array([0, 0, -4, 0, 0, 1, 0, 0, 1]);
    pbrFragment(lights, { ...box(pbr).objects[0].material, emissive: [1, 1, 1] }, false, g, recorder, [1, 1, 1], [1, 1, 1],
      { metalRough: recorder, occlusion: recorder, emissive: recorder, normal: null, alpha: null }, new Float64Array(4), lookup, new Float64Array(3));
    // (0.1, 0.2) → (2·0.1 + 3·0.2 + 0.5, −0.1 + 4·0.2 + 0.25) = (1.3, 0.95); ∂/∂x (0.01, 0.02) → (0.08, 0.07); ∂/∂y (0.03, 0.05) → (0.21, 0.17).
    const want = [1.3, 0.95, 0.08, 0.07, 0.21, 0.17];
    expect(asked.length, 'the base colour texture and three maps').toBe(4);
    for (const l of asked) l.forEach((x, k) => expect(x, `component ${k}`).toBeCloseTo(want[k], 12));
  });
});

describe('the reference\'s footprint under a transform', () => {
  it('one exact box footprint a pixel agrees with 64 point samples where the shading is linear in the map (slanted stripes given off)', () => {
    // Emission is linear in its map: the mean of the light over a pixel is the light of the map's mean over its footprint, so
    // the footprint (the hit's UV gradients moved through the transform's linear part) must cover what the samples cover.
    const state = { ...STATE, width: 65, height: 65, colorSpace: 'srgb' as const };
    const c = SLANTED_STRIPES;
    const truth = renderScene(c.scene, state, c.images, { samplesPerAxis: 8, textureFilter: 'point' });
    const p = compareImages(truth, renderScene(c.scene, state, c.images, { samplesPerAxis: 1, textureFilter: 'box' }).rgba).psnr;
    // Measured: objects 58.2 dB (a cross term's sign flipped: 41.7, 40.8).
    expect(p.objects, `objects ${p.objects.toFixed(1)} dB`).toBeGreaterThan(56.2);
  });
});
