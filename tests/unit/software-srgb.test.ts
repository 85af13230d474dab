// The software renderer's colour spaces (docs/colour.md#srgb) against values worked out here: with 'srgb'
// colour data (image texels, the procedural texture's texels, the background) are decoded, light
// is summed, filtered, blended and averaged linearly, and the frame is encoded once at the end;
// 'fresnel' shows F unencoded. Each case is drawn in 'none' too, where values are used as stored.
// The curve comes from src/math/srgb.ts (tied to published levels by srgb.test.ts) and the
// checker's texels from procedural-texture.ts (tied down by texture.test.ts).
import { describe, expect, it } from 'vitest';
import { SoftwareRenderer } from '../../src/software';
import { encodeByte, ENCODE_BINS } from '../../src/software/encode';
import { linearToSrgb, linearToSrgbByte, srgbToLinear, type ColorSpace } from '../../src/math/srgb';
import { texel } from '../../src/scene/procedural-texture';
import { TEXTURE_SIZE } from '../../src/scene/default-scene';
import type { FrameState } from '../../src/frame/types';
import { AMBIENT, material, N, quad, STATE } from './helpers/quad-scenes';
import type { DecodedImage } from '../../src/scene/decoded-image';
import type { Glass, Scene, SceneObject } from '../../src/scene/scene';

// quad-scenes.ts's 17×17 frame: a point (x, y, 0) lands on pixel column 8.5·(1 + x/2), row 8.5·(1 − y/2).
const SPACES: ColorSpace[] = ['srgb', 'none'];

const solid = (r: number, g: number, b: number): DecodedImage => ({ width: 1, height: 1, data: new Uint8Array([r, g, b, 255]) });
/** A 2×2 checker of black and white texels: every mip level above the base is its mean. */
const BLACK_WHITE: DecodedImage = { width: 2, height: 2, data: new Uint8Array([0, 0, 0, 255, 255, 255, 255, 255, 255, 255, 255, 255, 0, 0, 0, 255]) };
const IMAGES = new Map([['white', solid(255, 255, 255)], ['grey188', solid(188, 188, 188)], ['black-white', BLACK_WHITE]]);

const scene = (objects: SceneObject[], background: [number, number, number], glass: Glass | null = null): Scene =>
  ({ glass, objects, lights: [AMBIENT], background });

/** What an 8-bit sRGB (or, with 'none', plain 8-bit) target shows for linear value x: 255·encode(x), unrounded. */
const shown = (x: number, space: ColorSpace): number => 255 * (space === 'srgb' ? linearToSrgb(x) : Math.min(1, Math.max(0, x)));
/** Colour data (0..1, encoded) as the renderer must read it in `space`. */
const decoded = (c: number, space: ColorSpace): number => (space === 'srgb' ? srgbToLinear(c) : c);

/** Every channel of pixel (i, j) of a `width`-wide frame within half a level of shown(expected). */
function expectPixel(rgba: ArrayLike<number>, width: number, i: number, j: number, expected: readonly number[], space: ColorSpace): void {
  const o = 4 * (j * width + i);
  for (let k = 0; k < 3; k++) {
    const want = shown(expected[k], space);
    expect(Math.abs(rgba[o + k] - want), `${space} pixel (${i}, ${j}) channel ${k}: ${rgba[o + k]} vs ${want.toFixed(2)}`).toBeLessThanOrEqual(0.5 + 1e-3);
  }
}

/** The quad of x, y ∈ [−1, 1] covers pixels 4.25..12.75: 5..11 lie wholly inside. */
const INSIDE: [number, number][] = [];
for (let j = 5; j <= 11; j++) for (let i = 5; i <= 11; i++) INSIDE.push([i, j]);

describe('software renderer, color-space srgb against none (docs/colour.md#none)', () => {
  it("a white image, Ka = 0.2159, Ia = 1 shows 128 with srgb (encode(0.2159) = 0.50196), 55 with none", () => {
    const s = scene([quad(-1, -1, 1, 1, 0, material([0.2159, 0.2159, 0.2159], { kind: 'image', url: 'white' }))], [0, 0, 0]);
    const expected: Record<ColorSpace, number> = { srgb: 128, none: 55 };
    for (const space of SPACES) {
      const rgba = new SoftwareRenderer().render(s, { ...STATE, colorSpace: space }, IMAGES);
      for (const [i, j] of INSIDE) for (let k = 0; k < 3; k++) expect(rgba[4 * (j * N + i) + k], `${space} (${i}, ${j})`).toBe(expected[space]);
    }
  });

  it('an image texel is decoded before the light multiplies it: grey 188 under Ka = 0.5 is encode(0.5·decode(188/255)), 94 with none', () => {
    const s = scene([quad(-1, -1, 1, 1, 0, material([0.5, 0.5, 0.5], { kind: 'image', url: 'grey188' }))], [0, 0, 0]);
    for (const space of SPACES) {
      const rgba = new SoftwareRenderer().render(s, { ...STATE, colorSpace: space }, IMAGES);
      const c = 0.5 * decoded(188 / 255, space);
      for (const [i, j] of INSIDE) expectPixel(rgba, N, i, j, [c, c, c], space);
    }
    // 137 against 94: the two spaces are far apart here.
    expect(Math.round(shown(0.5 * srgbToLinear(188 / 255), 'srgb'))).toBe(137);
  });

  it('darks keep their levels: Ka = 0.0005, 0.0015, 0.004 show 2, 5, 13 with srgb (a buffer of 8-bit linear levels would hold 0, 0, 1)', () => {
    // Three quads side by side, their centres on pixel columns 3, 8 and 14 of row 8.
    const grey = (k: number) => material([k, k, k], { kind: 'image', url: 'white' });
    const s = scene([quad(-1.8, -1, -0.7, 1, 0, grey(0.0005)), quad(-0.5, -1, 0.5, 1, 0, grey(0.0015)), quad(0.7, -1, 1.8, 1, 0, grey(0.004))], [0, 0, 0]);
    const levels = [0.0005, 0.0015, 0.004], columns = [3, 8, 14];
    const expected: Record<ColorSpace, number[]> = { srgb: [2, 5, 13], none: [0, 0, 1] };
    for (const space of SPACES) {
      const rgba = new SoftwareRenderer().render(s, { ...STATE, colorSpace: space }, IMAGES);
      for (let q = 0; q < 3; q++) {
        expectPixel(rgba, N, columns[q], 8, [levels[q], levels[q], levels[q]], space);
        expect(rgba[4 * (8 * N + columns[q])], `${space} Ka ${levels[q]}`).toBe(expected[space][q]);
      }
    }
  });

  it('the background is decoded, so it shows as given, and opacity 0.3 blends over it in linear light', () => {
    const bg: [number, number, number] = [0.2, 0.4, 0.6];
    const ka = [0.8, 0.5, 0.2] as const;
    const s = scene([quad(-1, -1, 1, 1, 0, material([...ka], { kind: 'image', url: 'white' }, 0.3))], bg);
    for (const space of SPACES) {
      const rgba = new SoftwareRenderer().render(s, { ...STATE, colorSpace: space }, IMAGES);
      const back = bg.map((c) => decoded(c, space));
      // Outside the quad: decode then encode gives back 51, 102, 153 in both spaces.
      expectPixel(rgba, N, 1, 1, back, space);
      for (let k = 0; k < 3; k++) expect(rgba[4 * (N + 1) + k]).toBe([51, 102, 153][k]);
      // colour·(1 − kt) + framebuffer·kt with kt = 0.7, in linear light with srgb.
      const blended = ka.map((c, k) => 0.3 * c + 0.7 * back[k]);
      for (const [i, j] of INSIDE) expectPixel(rgba, N, i, j, blended, space);
    }
  });

  it('4×4 samples, half black and half white: the mean 0.5 is encoded after the average, 188 (not 128)', () => {
    // The white quad's left edge x = 0 runs down the middle of pixel column 8: 8 of its 16 samples.
    const s = scene([quad(0, -3, 3, 3, 0, material([1, 1, 1], { kind: 'image', url: 'white' }))], [0, 0, 0]);
    const expected: Record<ColorSpace, number[]> = { srgb: [0, 188, 255], none: [0, 128, 255] };
    for (const space of SPACES) {
      const rgba = new SoftwareRenderer({ samplesPerAxis: 4 }).render(s, { ...STATE, colorSpace: space }, IMAGES);
      for (let j = 0; j < N; j++) {
        for (let i = 7; i <= 9; i++) {
          for (let k = 0; k < 3; k++) expect(rgba[4 * (j * N + i) + k], `${space} (${i}, ${j})`).toBe(expected[space][i - 7]);
        }
      }
    }
    expect(Math.round(shown(0.5, 'srgb'))).toBe(188);
  });

  it('mipmaps average linear light: a black and white image read at its 1×1 level shows 188 with srgb, 128 with none', () => {
    // UVs 0..64 over 8.5 pixels: 15 texels per pixel, λ ≈ 3.9, past the top of a 2×2 chain.
    const s = scene([quad(-1, -1, 1, 1, 0, material([1, 1, 1], { kind: 'image', url: 'black-white' }), 64)], [0, 0, 0]);
    const expected: Record<ColorSpace, number> = { srgb: 188, none: 128 };
    for (const space of SPACES) {
      const rgba = new SoftwareRenderer().render(s, { ...STATE, colorSpace: space }, IMAGES);
      for (const [i, j] of INSIDE) for (let k = 0; k < 3; k++) expect(rgba[4 * (j * N + i) + k], `${space} (${i}, ${j})`).toBe(expected[space]);
    }
  });

  it("the procedural texture's texels are decoded before its mipmaps: its 1×1 level is the mean of decoded texels", () => {
    // UVs 0..64 over 8.5 pixels: 3855 texels per pixel, λ ≈ 11.9, the top of the 512² chain.
    const s = scene([quad(-1, -1, 1, 1, 0, material([1, 1, 1], { kind: 'procedural' }), 64)], [0, 0, 0]);
    const n = TEXTURE_SIZE;
    for (const space of SPACES) {
      let sum = 0;
      for (let y = 0; y < n; y++) for (let x = 0; x < n; x++) sum += decoded(texel(x, y) / 255, space);
      const mean = sum / (n * n);
      const rgba = new SoftwareRenderer().render(s, { ...STATE, colorSpace: space });
      for (const [i, j] of INSIDE) expectPixel(rgba, N, i, j, [mean, mean, mean], space);
    }
    // Levels 100 and 200 average to 160 in light, 150 as stored.
    expect(Math.round(shown((srgbToLinear(100 / 255) + srgbToLinear(200 / 255)) / 2, 'srgb'))).toBe(160);
  });
});

describe('software renderer, the glass in linear light (docs/rendering.md#the-glass-equation, docs/colour.md#srgb)', () => {
  // 32×32 pixels, fov 90°, the eye 2 from the glass z = 0 on its axis: a pixel is 1/8 unit there.
  // The glass, 64×64 with its u = 0, v = 0 corner at the view's bottom-left (−2, −2), spans the
  // procedural texture's 512 texels over 512 pixels, so pixel (i, j) reads exactly texel
  // (i, 31 − j) at level 0. Behind it a quad of Ka = (0.6, 0.3, 0.1) fills the view (B); the eye's
  // side is empty, so the reflection (R) is the background.
  const W = 32;
  const GLASS: Glass = { center: [30, 30, 0], normal: [0, 0, 1], size: [64, 64] };
  const KA = [0.6, 0.3, 0.1] as const, BG: [number, number, number] = [0.2, 0.5, 0.9];
  const BODY = [0.7, 0.9, 1.0].map((c) => c * 0.35);
  const glassScene = scene([quad(-10, -10, 10, 10, -1, material([...KA], { kind: 'image', url: 'white' }))], BG, GLASS);
  const state = (space: ColorSpace, view: FrameState['view'] = 'final'): FrameState =>
    ({ ...STATE, width: W, height: W, colorSpace: space, view, fresnel: 'exact', ior: 1.5, transparency: 0.3 });

  /** cos θ at pixel (i, j): the ray through its centre is (x_ndc, y_ndc, −1). */
  const cosAt = (i: number, j: number): number => 1 / Math.hypot((2 * (i + 0.5)) / W - 1, 1 - (2 * (j + 0.5)) / W, 1);
  /** Unpolarised Fresnel from the textbook (Snell's law, then rs and rp). */
  function fresnelByHand(c: number, n: number): number {
    const cosT = Math.sqrt(1 - (1 - c * c) / (n * n));
    const rs = (c - n * cosT) / (c + n * cosT), rp = (n * c - cosT) / (n * c + cosT);
    return (rs * rs + rp * rp) / 2;
  }

  it('F·R + (1 − F)·(T·B + (1 − T)·D), D = decode(tex) ⊙ tint ⊙ 0.35, R the decoded background, encoded once', () => {
    for (const space of SPACES) {
      const rgba = new SoftwareRenderer().render(glassScene, state(space), IMAGES);
      const r = BG.map((c) => decoded(c, space));
      for (let j = 0; j < W; j++) {
        for (let i = 0; i < W; i++) {
          const f = fresnelByHand(cosAt(i, j), 1.5), tex = decoded(texel(i, 31 - j) / 255, space);
          expectPixel(rgba, W, i, j, BODY.map((b, k) => f * r[k] + (1 - f) * (0.3 * KA[k] + 0.7 * tex * b)), space);
        }
      }
    }
  });

  it('the fresnel view shows F unencoded, the same bytes in both spaces', () => {
    const srgb = new SoftwareRenderer().render(glassScene, state('srgb', 'fresnel'), IMAGES).slice();
    const none = new SoftwareRenderer().render(glassScene, state('none', 'fresnel'), IMAGES);
    expect(srgb).toEqual(none);
    for (let j = 0; j < W; j++) {
      for (let i = 0; i < W; i++) {
        const f = fresnelByHand(cosAt(i, j), 1.5);
        expectPixel(srgb, W, i, j, [f, f, f], 'none');
      }
    }
    // F runs from 0.040 to 0.066 here: 10 to 17 levels unencoded, 56 to 73 if encoded.
    expect(Math.max(...srgb.filter((_, k) => k % 4 === 0))).toBeLessThan(20);
  });

  it('passes: each tile follows its own view, the fresnel tile unencoded and the other three encoded', () => {
    // A grey quad on the eye's side, so the reflection holds more than the background (which
    // decodes and encodes back to itself).
    const passesScene = { ...glassScene, objects: [...glassScene.objects, quad(-0.5, -0.5, 0.5, 0.5, 0.5, material([0.25, 0.25, 0.25], { kind: 'image', url: 'white' }))] };
    const r = new SoftwareRenderer();
    const tiled: Record<ColorSpace, Uint8ClampedArray> = {
      srgb: r.render(passesScene, { ...state('srgb', 'passes'), width: 2 * W, height: 2 * W }, IMAGES).slice(),
      none: r.render(passesScene, { ...state('none', 'passes'), width: 2 * W, height: 2 * W }, IMAGES).slice(),
    };
    const tile = (px: Uint8ClampedArray, x: number, y: number): number[] => {
      const out: number[] = [];
      for (let row = 0; row < W; row++) out.push(...px.subarray(4 * ((y + row) * 2 * W + x), 4 * ((y + row) * 2 * W + x + W)));
      return out;
    };
    const quadrants: [FrameState['view'], number, number][] = [['reflection', 0, 0], ['scene', W, 0], ['fresnel', 0, W], ['final', W, W]];
    for (const [view, x, y] of quadrants) {
      for (const space of SPACES) {
        expect(tile(tiled[space], x, y), `${space} ${view} tile`).toEqual([...r.render(passesScene, state(space, view), IMAGES)]);
      }
      const a = tile(tiled.srgb, x, y), b = tile(tiled.none, x, y);
      const same = a.every((v, k) => v === b[k]);
      expect(same, `${view}: srgb and none ${view === 'fresnel' ? 'equal' : 'differ'}`).toBe(view === 'fresnel');
    }
  });
});

/** The double next to x towards +∞ (up) or −∞ (down), x > 0. */
function nextDouble(x: number, up: boolean): number {
  const f = new Float64Array([x]), i = new BigInt64Array(f.buffer);
  i[0] += up ? 1n : -1n;
  return f[0];
}

describe("the resolve's encode (a table read) gives linearToSrgbByte's byte", () => {
  /** Where the byte steps from b − 1 to b: decode((b − ½)/255), b = 1..255, written out from the curve of docs/colour.md#the-transfer-curve. */
  const steps: number[] = [];
  for (let b = 1; b < 256; b++) {
    const c = (b - 0.5) / 255;
    steps.push(c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4);
  }

  it('no bin of the table holds two steps (the closest two are 1/(255·12.92) apart, a bin 1/4096)', () => {
    const bins = steps.map((t) => Math.floor(t * ENCODE_BINS));
    expect(new Set(bins).size).toBe(255);
    expect(steps[1] - steps[0]).toBeCloseTo(1 / (255 * 12.92), 12);
  });

  it('at every step, a double either side, every bin edge, the ends and 100 000 values drawn at random', () => {
    const values = [0, -0, -1, NaN, 1, 2, Infinity, 1e-12, nextDouble(1, false)];
    for (const t of steps) values.push(t, nextDouble(t, true), nextDouble(t, false), Math.fround(t));
    for (let i = 0; i <= ENCODE_BINS; i++) values.push(i / ENCODE_BINS, Math.max(0, nextDouble(i / ENCODE_BINS || 1e-300, false)));
    // A fixed linear congruential sequence: the same values every run, squared to favour the darks.
    let seed = 12345;
    for (let i = 0; i < 100_000; i++) {
      seed = (Math.imul(seed, 1103515245) + 12345) >>> 0;
      values.push((seed / 2 ** 32) ** 2);
    }
    let wrong = 0, first = '';
    for (const v of values) {
      if (encodeByte(v) !== linearToSrgbByte(v)) {
        if (!wrong) first = `${v}: ${encodeByte(v)} vs ${linearToSrgbByte(v)}`;
        wrong++;
      }
    }
    expect(wrong, first).toBe(0);
    // And the bytes at the steps themselves are b (ties round up), the doubles below them b − 1.
    for (let b = 1; b < 256; b++) {
      expect(encodeByte(steps[b - 1]), `step ${b}`).toBe(b);
      expect(encodeByte(nextDouble(steps[b - 1], false)), `below step ${b}`).toBe(b - 1);
    }
  });
});
