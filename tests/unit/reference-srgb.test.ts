// The reference in linear light (docs/colour.md#srgb, colour-space 'srgb'): colour data decoded, light summed,
// one encode per pixel; 'none' as stored. Expected values are written out here: the curve in its
// two IEC 61966-2-1 segments by hand, and the figures it gives (to 7 digits, as published).
import { describe, expect, it } from 'vitest';
import { renderReference, renderScene, type ReferenceImage, type ReferenceOptions, type ReferenceState, type ViewState } from '../../src/reference';
import { DEFAULT_GLASS, defaultScene } from '../../src/scene/default-scene';
import { texel } from '../../src/scene/procedural-texture';
import type { Geometry, Light, Material, Scene, SceneObject, Vec3 } from '../../src/scene/scene';
import type { DecodedImage, SceneImages } from '../../src/scene/decoded-image';
import { defaultFrameState } from './helpers/frame-state';

/** sRGB → linear, the piecewise curve written out (not src/math/srgb.ts). */
const decode = (c: number): number => (c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4);
/** linear → sRGB, clipped to 0..1, written out. */
const encode = (l: number): number => (l <= 0 ? 0 : l >= 1 ? 1 : l <= 0.0031308 ? 12.92 * l : 1.055 * l ** (1 / 2.4) - 0.055);

/** 9×9 looking down −Z from (0, 0, 10): pixel (4, 4) is centred on the axis. */
const FRONT: ViewState = defaultFrameState({ width: 9, height: 9, fov: 40, cameraPosition: [0, 0, 10], yaw: -90, pitch: 0 });
/** Ambient light only: a surface shows Ka ⊙ tex, nothing else. */
const AMBIENT: Light = { kind: 'directional', vector: [0, 0, 1], ambient: [1, 1, 1], diffuse: [0, 0, 0], specular: [0, 0, 0] };
const image = (width: number, height: number, levels: number[]): DecodedImage => ({
  width, height, data: new Uint8Array(levels.flatMap((v) => [v, v, v, 255])),
});
const WHITE = image(1, 1, [255]);

/** Ka = `ambient`, Kd = Ks = 0, textured with `texture` (an image URL, or the procedural texture). */
function plain(ambient: number | Vec3, texture = 'white.png'): Material {
  const ka: Vec3 = typeof ambient === 'number' ? [ambient, ambient, ambient] : ambient;
  return {
    ambient: ka, diffuse: [0, 0, 0], specular: [0, 0, 0], shininess: 32, opacity: 1, mapping: 'uv',
    texture: texture === 'procedural' ? { kind: 'procedural' } : { kind: 'image', url: texture },
  };
}
/** A w×h quad in the plane z = 0 facing +Z, UV (0, 0) at its lower left corner. */
function quad(w: number, h: number): Geometry {
  return {
    kind: 'mesh', key: `quad ${w}×${h}`,
    data: {
      positions: new Float32Array([-w / 2, -h / 2, 0, w / 2, -h / 2, 0, w / 2, h / 2, 0, -w / 2, h / 2, 0]),
      normals: new Float32Array([0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1]),
      uvs: new Float32Array([0, 0, 1, 0, 1, 1, 0, 1]),
      indices: new Uint16Array([0, 1, 2, 0, 2, 3]),
    },
  };
}
function object(geometry: Geometry, material: Material, position: Vec3 = [0, 0, 0]): SceneObject {
  return {
    geometry, material, bounds: { center: [0, 0, 0], radius: 1 },
    transform: { position, rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0 },
  };
}
const scene = (objects: SceneObject[], background: Vec3 = [0, 0, 0], glass: Scene['glass'] = null): Scene =>
  ({ glass, objects, lights: [AMBIENT], background });

function render(
  s: Scene, colorSpace: 'srgb' | 'none', view: Partial<ViewState> = {}, images: SceneImages = new Map([['white.png', WHITE]]), options: ReferenceOptions = {},
): ReferenceImage {
  return renderScene(s, { ...FRONT, ...view, colorSpace }, images, options);
}
const rgbAt = (img: ReferenceImage, x: number, y: number): number[] => Array.from(img.rgb.subarray(3 * (y * img.width + x), 3 * (y * img.width + x) + 3));
const bytesAt = (img: ReferenceImage, x: number, y: number): number[] => Array.from(img.rgba.subarray(4 * (y * img.width + x), 4 * (y * img.width + x) + 3));
function expectRgb(actual: number[], expected: number[], eps = 1e-9): void {
  for (let k = 0; k < 3; k++) expect(Math.abs(actual[k] - expected[k]), `channel ${k}: ${actual[k]} vs ${expected[k]}`).toBeLessThanOrEqual(eps);
}

describe('the hand-written curve these tests use', () => {
  it('gives the published figures', () => {
    expect(decode(200 / 255)).toBeCloseTo(0.5775804, 7);
    expect(decode(128 / 255)).toBeCloseTo(0.2158605, 7);
    expect(decode(0.5)).toBeCloseTo(0.2140411, 7);
    expect(encode(0.5)).toBeCloseTo(0.7353570, 7);
    expect(encode(0.2159)).toBeCloseTo(0.5020032, 7);
  });
});

describe('colour data are decoded, coefficients are not', () => {
  it('a white image under Ka = 0.2159 and an ambient light 1 shows 128 with srgb, 55 with none', () => {
    const s = scene([object(quad(8, 8), plain(0.2159))]);
    const srgb = render(s, 'srgb');
    expectRgb(rgbAt(srgb, 4, 4), [0.5020032, 0.5020032, 0.5020032], 5e-8); // encode(0.2159)
    expect(bytesAt(srgb, 4, 4)).toEqual([128, 128, 128]);
    const none = render(s, 'none');
    expectRgb(rgbAt(none, 4, 4), [0.2159, 0.2159, 0.2159], 1e-15);
    expect(bytesAt(none, 4, 4)).toEqual([55, 55, 55]); // round(0.2159·255)
  });

  it('an image texel is decoded: level 128 under Ka = 0.5 is encode(0.5·0.2158605) = 92, not 128', () => {
    const grey = new Map([['grey.png', image(1, 1, [128])]]);
    const s = scene([object(quad(8, 8), plain(0.5, 'grey.png'))]);
    const srgb = render(s, 'srgb', {}, grey);
    expectRgb(rgbAt(srgb, 4, 4), [0.3622491, 0.3622491, 0.3622491], 5e-8);
    expect(bytesAt(srgb, 4, 4)).toEqual([92, 92, 92]);
    // Under Ka = 1 the level comes back as it was: decoded, then encoded.
    const one = render(scene([object(quad(8, 8), plain(1, 'grey.png'))]), 'srgb', {}, grey);
    expectRgb(rgbAt(one, 4, 4), [128 / 255, 128 / 255, 128 / 255], 1e-12);
    expect(bytesAt(render(s, 'none', {}, grey), 4, 4)).toEqual([64, 64, 64]); // round(0.5·128)
  });

  it('texels are decoded before filtering: half-way between a black and a white texel is linear 0.5 (188)', () => {
    // A 2×1 image, texel centres at u = ¼ and ¾; the axis pixel reads u = ½.
    const images = new Map([['ramp.png', image(2, 1, [0, 255])]]);
    const s = scene([object(quad(8, 8), plain(1, 'ramp.png'))]);
    for (const textureFilter of ['point', 'box'] as const) {
      const n = textureFilter === 'point' ? 1 : 4;
      const srgb = render(s, 'srgb', {}, images, { textureFilter, samplesPerAxis: n });
      expectRgb(rgbAt(srgb, 4, 4), [0.735357, 0.735357, 0.735357], 1e-6); // encode(0.5)
      expect(bytesAt(srgb, 4, 4), textureFilter).toEqual([188, 188, 188]);
      expectRgb(rgbAt(render(s, 'none', {}, images, { textureFilter, samplesPerAxis: n }), 4, 4), [0.5, 0.5, 0.5], 1e-6);
    }
  });

  it('the procedural texture\'s 200/255 decodes to 0.5775804 before a plain material multiplies it', () => {
    // The cube's +Z face at the centre of a texel of level 200 (u = x + 1.5, v = y − 0.5), head-on.
    let at: [number, number] | null = null;
    for (let j = 320; j < 384 && at === null; j++) for (let i = 192; i < 256; i++) if (texel(i, j) === 200) { at = [i, j]; break; }
    expect(at).not.toBeNull();
    const [i, j] = at!;
    const view = { width: 33, height: 33, cameraPosition: [(i + 0.5) / 512 - 1.5, (j + 0.5) / 512 + 0.5, 7] as Vec3 };
    const cubeWith = (ka: number): Scene => {
      const s = defaultScene(2.5, 0);
      return { ...s, glass: null, lights: [AMBIENT], objects: [{ ...s.objects[0], material: plain(ka, 'procedural') }] };
    };
    const half = render(cubeWith(0.5), 'srgb', view);
    expectRgb(rgbAt(half, 16, 16), [0.5737748, 0.5737748, 0.5737748], 5e-8); // encode(0.5·0.5775804)
    expect(bytesAt(half, 16, 16)).toEqual([146, 146, 146]);
    expectRgb(rgbAt(render(cubeWith(1), 'srgb', view), 16, 16), [200 / 255, 200 / 255, 200 / 255], 1e-12);
    expectRgb(rgbAt(render(cubeWith(0.5), 'none', view), 16, 16), [100 / 255, 100 / 255, 100 / 255], 1e-12);
  });

  it('the background is a CSS colour: "0.5 0.5 0.5" is decoded, then encoded: 128 in both spaces, in the final and reflection views', () => {
    const s = scene([], [0.5, 0.5, 0.5]);
    for (const colorSpace of ['srgb', 'none'] as const) {
      for (const view of ['final', 'reflection'] as const) {
        const img = render(s, colorSpace, { view });
        expectRgb(rgbAt(img, 4, 4), [0.5, 0.5, 0.5], 1e-12);
        expect(bytesAt(img, 4, 4), `${colorSpace} ${view}`).toEqual([128, 128, 128]);
      }
    }
  });
});

describe('light is summed in linear light and encoded once', () => {
  it('a pixel half black, half white (4×4 samples) averages to encode(0.5) = 188 with srgb, 128 with none', () => {
    // The white quad covers x ≥ 0, the black one x ≤ 0: the axis column's samples split 8 / 8.
    // Point-sampled, the white image is exactly 1 (its box filter is 1 − 3e−15: 127.4999… would round to 127).
    const s = scene([object(quad(4, 8), plain(1), [2, 0, 0]), object(quad(4, 8), plain(0), [-2, 0, 0])], [0.5, 0.5, 0.5]);
    const options: ReferenceOptions = { samplesPerAxis: 4, textureFilter: 'point' };
    const srgb = render(s, 'srgb', {}, undefined, options);
    expectRgb(rgbAt(srgb, 4, 4), [0.735357, 0.735357, 0.735357], 1e-6);
    expect(bytesAt(srgb, 4, 4)).toEqual([188, 188, 188]);
    expect(bytesAt(srgb, 3, 4)).toEqual([0, 0, 0]);
    expect(bytesAt(srgb, 5, 4)).toEqual([255, 255, 255]);
    const none = render(s, 'none', {}, undefined, options);
    expectRgb(rgbAt(none, 4, 4), [0.5, 0.5, 0.5], 0);
    expect(bytesAt(none, 4, 4)).toEqual([128, 128, 128]);
  });

  it('opacity blends light: a white quad of opacity 0.5 over black shows encode(0.5) = 188', () => {
    const s = scene([object(quad(8, 8), { ...plain(1), opacity: 0.5 })]);
    expect(bytesAt(render(s, 'srgb'), 4, 4)).toEqual([188, 188, 188]);
    expect(bytesAt(render(s, 'none'), 4, 4)).toEqual([128, 128, 128]);
  });

  it('the glass equation mixes decoded R, B and D, then encodes: F·R + (1 − F)(T·B + (1 − T)·D)', () => {
    // The glass point whose UV is texel (100, 300)'s centre, seen head-on (F = 0.04 for n = 1.5);
    // behind it a quad of Ka (0.3, 0.5, 0.7) (linear, as written); in front nothing, so R = the background.
    const view: Partial<ViewState> = { width: 33, height: 33, fov: 60, cameraPosition: [100.5 / 64 - 4, 300.5 / 128 - 1, 4] };
    const B: Vec3 = [0.3, 0.5, 0.7];
    const s = scene([object(quad(20, 20), plain(B), [0, 0, -2])], [0.5, 0.5, 0.5], DEFAULT_GLASS);
    const tint = [0.7 * 0.35, 0.9 * 0.35, 1.0 * 0.35];
    const level = texel(100, 300) / 255;
    const f = 0.04, t = 0.5;
    const linear = tint.map((k, c) => f * decode(0.5) + (1 - f) * (t * B[c] + (1 - t) * decode(level) * k));
    const srgb = render(s, 'srgb', view);
    expectRgb(rgbAt(srgb, 16, 16), linear.map(encode), 1e-9);
    expect(bytesAt(srgb, 16, 16)).toEqual(linear.map((l) => Math.round(encode(l) * 255)));
    const asStored = tint.map((k, c) => f * 0.5 + (1 - f) * (t * B[c] + (1 - t) * level * k));
    expectRgb(rgbAt(render(s, 'none', view), 16, 16), asStored, 1e-9);
  });
});

describe('the fresnel view', () => {
  it('shows F unencoded, the same in both colour spaces (0.04 head-on: 10)', () => {
    const state: ReferenceState = defaultFrameState({
      width: 33, height: 33, spin: 0, cubeDistance: 2.5, cameraPosition: [100.5 / 64 - 4, 300.5 / 128 - 1, 4], yaw: -90, pitch: 0, view: 'fresnel',
    });
    const srgb = renderReference(state);
    const none = renderReference({ ...state, colorSpace: 'none' });
    expect(srgb.rgb).toEqual(none.rgb);
    expect(srgb.rgba).toEqual(none.rgba);
    expectRgb(rgbAt(srgb, 16, 16), [0.04, 0.04, 0.04], 1e-12);
    expect(bytesAt(srgb, 16, 16)).toEqual([10, 10, 10]);
  });
});
