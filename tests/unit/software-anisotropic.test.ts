// The software renderer's anisotropic texture reads (srgb textures; mip-texture.ts) against values
// worked out here: N taps along the footprint's major axis at the level of its width, as the
// WebGL renderer's EXT_texture_filter_anisotropic reads do, where one isotropic level blurs a
// surface seen at a slant; a square footprint reads exactly as before; `none` stays isotropic.
import { describe, expect, it } from 'vitest';
import { imageMipTexture, MAX_ANISOTROPY, MipTexture, proceduralMipTexture } from '../../src/software/mip-texture';
import { SoftwareRenderer } from '../../src/software';
import { TEXTURE_SIZE } from '../../src/scene/default-scene';
import type { DecodedImage } from '../../src/scene/decoded-image';
import type { ColorSpace } from '../../src/math/srgb';
import type { Scene } from '../../src/scene/scene';
import { AMBIENT, material, N, STATE, unitQuad } from './helpers/quad-scenes';

const S = 16;

/** An S×S grey texture, value(i, j) at column i, row j; anisotropic or not. */
function texture(value: (i: number, j: number) => number, anisotropic: boolean): MipTexture {
  const data = new Float32Array(S * S);
  for (let j = 0; j < S; j++) for (let i = 0; i < S; i++) data[j * S + i] = value(i, j);
  return new MipTexture(1, S, S, data, anisotropic);
}

/** One read at UV (u, v) with ∂(s,t)/∂x = (sx, tx) and ∂(s,t)/∂y = (sy, ty) given in texels. */
function read(t: MipTexture, u: number, v: number, sx: number, tx: number, sy: number, ty: number): number {
  const out = new Float64Array(3);
  t.sample(Float64Array.of(u, v, sx / S, tx / S, sy / S, ty / S), out);
  expect(out[1]).toBe(out[0]);
  return out[0];
}

/** Row 3 white, the rest black: a band across t. */
const BAND = (_i: number, j: number): number => (j === 3 ? 1 : 0);
/** Columns 0–3 and 8–11 white, 4–7 and 12–15 black: stripes 4 texels wide across s. */
const STRIPES = (i: number): number => ((i >> 2) % 2 === 0 ? 1 : 0);

describe('MipTexture, anisotropic reads (EXT_texture_filter_anisotropic)', () => {
  it('a footprint 1×4 texels across a one-texel band: 4 taps at level 0 give its exact mean 0.25; one isotropic level gives 0.15625', () => {
    // At the band's centre (t = 3 in texel-centre space), the footprint spans t = 1..5 and 1
    // texel of s. The texture there is the tent 1 − |t − 3| (bilinear between rows), whose mean
    // over 4 texels is 1/4 — what the reference's box filter takes. N = 4 taps at λ = log2(4/4)
    // = 0, at the midpoints of four equal parts: t = 1.5, 2.5, 3.5, 4.5, reading 0, ½, ½, 0.
    // (The extension's i/(N + 1) spacing would read t = 1.8, 2.6, 3.4, 4.2: 0.3.)
    const u = 5.5 / S, v = 3.5 / S;
    expect(read(texture(BAND, true), u, v, 1, 0, 0, 4)).toBe(0.25);
    // Isotropic: λ = log2(4) = 2, level 2 (4×4) has row 0 = mean of rows 0–3 = ¼ and the rest 0;
    // at t₂ = v·4 − ½ = 0.375 that reads ¼·(1 − 0.375).
    expect(read(texture(BAND, false), u, v, 1, 0, 0, 4)).toBe(0.15625);
    // The same footprint with its axes swapped (major along ∂/∂x) reads the same.
    expect(read(texture(BAND, true), u, v, 0, 4, 1, 0)).toBe(0.25);
    // Centred on t = 5 the footprint (t = 3..7) holds half the tent: a mean of 1/8. The taps at
    // t = 3.5, 4.5, 5.5, 6.5 read ½, 0, 0, 0 (taps from the footprint's start, t = 3, 4, 5, 6,
    // would read 1, 0, 0, 0).
    expect(read(texture(BAND, true), u, 5.5 / S, 1, 0, 0, 4)).toBe(0.125);
  });

  it('an anisotropy of 2.4 takes round(2.4) = 2 taps at λ = log2(Pmax / 2.4), a quarter of the footprint either side of its centre', () => {
    // 1 × 2.4 texels centred on the band: λ = log2(2.4/2.4) = 0, taps at t = 3 ± 0.6 reading
    // 0.4 each. (Three taps, t = 2.2, 3, 3.8, would read 0.467; the exact mean is 1/2.4 = 0.417.)
    expect(read(texture(BAND, true), 5.5 / S, 3.5 / S, 1, 0, 0, 2.4)).toBeCloseTo(0.4, 14);
    // 2 × 4.8 texels across the stripes' long way at column 1's centre: λ = log2(4.8/2.4) = 1,
    // level 1 (8 wide: columns 1, 1, 0, 0, …) at s₁ = 1.5/2 − ½ = ¼, between two white columns,
    // and at column 3's centre s₁ = 1.25, ¾ white. (λ = log2(4.8/2) = 1.26, from the tap count,
    // would mix in a quarter of level 2, columns 1, 0, 1, 0: 0.967 and 0.717.)
    expect(read(texture(STRIPES, true), 1.5 / S, 0.3, 2, 0, 0, 4.8)).toBeCloseTo(1, 14);
    expect(read(texture(STRIPES, true), 3.5 / S, 0.3, 2, 0, 0, 4.8)).toBeCloseTo(0.75, 14);
  });

  it('a footprint barely longer than wide (4 × 4.4 texels) takes one tap at the level of its width, log2(4) = 2, as an isotropic 4 × 4 one does', () => {
    // ⌈4.4/4⌉ = 2 taps at log2(4.4/2) (the extension's own formula) would read a level sharper
    // than the footprint is wide: the aliasing the default scene's cube showed at 60°.
    const value = (i: number, j: number) => ((i * 7 + j * 13 + ((i * j) % 5)) % 11) / 10;
    for (const [u, v] of [[0.1, 0.2], [0.53, 0.91], [0.37, 0.61]]) {
      expect(read(texture(value, true), u, v, 4, 0, 0, 4.4)).toBeCloseTo(read(texture(value, false), u, v, 4, 0, 0, 4), 12);
    }
  });

  it('stripes seen at a steep slant (1 texel across them, 8 along): anisotropic reads keep them black and white, isotropic ones are grey', () => {
    // The footprint runs along the stripes, so its mean is what one texel of s reads: 1 at a
    // white column's centre, 0 at a black one's, ½ on the edge between (s = 3.5). Isotropic:
    // λ = log2(8) = 3, and level 3 (2×2) holds the mean of 8 columns, ½ everywhere.
    const aniso = texture(STRIPES, true), iso = texture(STRIPES, false);
    const columns = [[1.5, 1], [3.5, 1], [4, 0.5], [5.5, 0], [9.5, 1], [14.5, 0]];
    for (const [s, mean] of columns) {
      expect(read(aniso, s / S, 0.3, 1, 0, 0, 8), `anisotropic, column ${s}`).toBeCloseTo(mean, 14);
      expect(read(iso, s / S, 0.3, 1, 0, 0, 8), `isotropic, column ${s}`).toBeCloseTo(0.5, 14);
    }
  });

  it('a skewed footprint is as wide as its area over its length: (4, 0) and (2, 3) texels read one tap at λ = log2(12/4), not at its shorter side |(2, 3)| = 3.61', () => {
    // Anisotropy 4² / |det| = 16/12 = 1.33: one tap, at λ = log2(4/1.33) = log2(3), what an
    // isotropic read of a 3×3 footprint takes. (Pmax/Pmin = 1.11 would read at log2(3.61).)
    const value = (i: number, j: number) => ((i * 7 + j * 13 + ((i * j) % 5)) % 11) / 10;
    for (const [u, v] of [[0.1, 0.2], [0.53, 0.91], [0.37, 0.61]]) {
      expect(read(texture(value, true), u, v, 4, 0, 2, 3)).toBeCloseTo(read(texture(value, false), u, v, 3, 0, 0, 3), 12);
    }
  });

  it(`N stops at ${MAX_ANISOTROPY}: a 1×64 footprint takes ${MAX_ANISOTROPY} taps at λ = log2(64/${MAX_ANISOTROPY}) = 2, which blurs the stripes to 0.875`, () => {
    // Level 2 (4×4) of the stripes is columns 1, 0, 1, 0. At s = 1.5 (a white column's centre)
    // s₂ = 1.5/4 − ½ = −0.125: ⅞ of column 0 (white) and ⅛ of column 3 (black) by REPEAT. With
    // no cap (64 taps at level 0) it would read 1; a cap of 15 or 17 mixes in level 3 or 1.
    expect(MAX_ANISOTROPY).toBe(16);
    expect(read(texture(STRIPES, true), 1.5 / S, 0.3, 1, 0, 0, 64)).toBeCloseTo(0.875, 14);
    // A footprint of zero width (a surface seen edge-on) takes the most taps too.
    expect(read(texture(STRIPES, true), 1.5 / S, 0.3, 0, 0, 0, 64)).toBeCloseTo(0.875, 14);
  });

  it('a tie in length makes the x derivative the major axis, as SwiftShader (CmpNLT(dUV2.x, dUV2.y)) does', () => {
    // Columns 0–7 white, 8–15 black. (17, 0) and (15, 8) texels, both 17 long: |det| = 136, r =
    // 289/136 = 2.125, 2 taps at λ = ½·log2(289/2.125²) = ½·log2(64) = 3: level 3 (2×2) holds
    // columns 1, 0. The taps a quarter of (17, 0) either side of s = 4 (u = ¼, s₃ = 0) read at
    // s₃ = ±0.53125: 0.46875 each. Swapped, (15, 8) is the x one: its quarter puts them at ±0.46875, 0.53125.
    const halves = texture((i) => (i < 8 ? 1 : 0), true);
    expect(read(halves, 0.25, 0.3, 17, 0, 15, 8)).toBe(0.46875);
    expect(read(halves, 0.25, 0.3, 15, 8, 17, 0)).toBe(0.53125);
  });

  it('a NaN derivative reads the base level at (u, v), an infinite one the last level, each with one tap', () => {
    // Row 3 white: the band's own texel reads 1 at level 0; the 1×1 level holds the mean, 1/16.
    expect(read(texture(BAND, true), 5.5 / S, 3.5 / S, NaN, 0, 0, 1)).toBe(1);
    expect(read(texture(BAND, true), 5.5 / S, 3.5 / S, Infinity, 0, 0, 1)).toBe(0.0625);
  });

  it('a MipTexture is isotropic unless made anisotropic', () => {
    // The band's 1×4 footprint of the first test, isotropic: 0.15625.
    const data = new Float32Array(S * S).fill(1, 3 * S, 4 * S);
    expect(read(new MipTexture(1, S, S, data), 5.5 / S, 3.5 / S, 1, 0, 0, 4)).toBe(0.15625);
  });

  it('a square footprint (perpendicular axes of one length) reads exactly as the isotropic texture does, at every scale', () => {
    // A texture with something to blur at every level: a hash of (i, j).
    const value = (i: number, j: number) => ((i * 7 + j * 13 + ((i * j) % 5)) % 11) / 10;
    const aniso = texture(value, true), iso = texture(value, false);
    const a = new Float64Array(6), x = new Float64Array(3), y = new Float64Array(3);
    let differs = 0;
    for (const [p, q] of [[0.3, 0.1], [0, 0.7], [1.2, -2.1], [3, 4], [-5, 12], [40, 9], [0.02, 0]]) {
      for (const [u, v] of [[0.1, 0.2], [0.53, 0.91], [-0.37, 1.61]]) {
        a.set([u, v, p / S, q / S, -q / S, p / S]);
        aniso.sample(a, x);
        iso.sample(a, y);
        expect(Array.from(x), `(${p}, ${q}) at (${u}, ${v})`).toEqual(Array.from(y));
        // Not vacuous: the same axes at 1 : 3 read otherwise.
        a.set([u, v, p / S, q / S, (-3 * q) / S, (3 * p) / S]);
        aniso.sample(a, x);
        iso.sample(a, y);
        if (x[0] !== y[0]) differs++;
      }
    }
    expect(differs).toBeGreaterThan(15);
  });

  it('the procedural texture and images are anisotropic in srgb only: with none a 1×16 footprint reads as a 16×16 one', () => {
    // Isotropic filtering sees only the longer axis: 1×16 and 16×16 texels both read level 4.
    const image: DecodedImage = { width: S, height: S, data: new Uint8Array(S * S * 4) };
    for (let p = 0; p < S * S; p++) image.data.set([(p * 37) % 256, (p * 91) % 256, (p * 53) % 256, 255], 4 * p);
    const narrow = new Float64Array(3), square = new Float64Array(3);
    for (const space of ['none', 'srgb'] as ColorSpace[]) {
      for (const [name, t, size] of [['procedural', proceduralMipTexture(space), TEXTURE_SIZE], ['image', imageMipTexture(image, space)!, S]] as const) {
        t.sample(Float64Array.of(0.37, 0.61, 1 / size, 0, 0, 16 / size), narrow);
        t.sample(Float64Array.of(0.37, 0.61, 16 / size, 0, 0, 16 / size), square);
        if (space === 'none') expect(Array.from(narrow), `${name}, none`).toEqual(Array.from(square));
        else expect(Math.abs(narrow[0] - square[0]), `${name}, srgb`).toBeGreaterThan(1e-3);
      }
    }
  });
});

describe('software renderer: anisotropic reads with srgb, isotropic with none', () => {
  // quad-scenes.ts's frame: 17×17 pixels, fov 90°, the eye at (0, 0, 2) looking down −Z; the
  // quad x, y ∈ [−1, 1] at z = 0 covers pixels 4.25..12.75. Its u runs 0..1 across x and v 0..68
  // up y: on a 4×1 image of stripes (white, white, black, black) a pixel's footprint is
  // 4/8.5 = 0.47 texel across the stripes and 68/8.5 = 8 texels along them — the footprint of a
  // striped floor seen at a slant, with the derivatives the same at every pixel.
  const stripes: DecodedImage = { width: 4, height: 1, data: new Uint8Array([255, 255, 255, 255, 255, 255, 255, 255, 0, 0, 0, 255, 0, 0, 0, 255]) };
  const scene: Scene = {
    glass: null, lights: [AMBIENT], background: [0, 0, 0],
    objects: [unitQuad(material([1, 1, 1], { kind: 'image', url: 'stripes' }), [0, 0, 1, 0, 1, 68, 0, 68], 'stretched quad')],
  };
  const IMAGES = new Map([['stripes', stripes]]);

  it('srgb: columns on the white stripe show 255 and on the black one 0 (16 taps at level 0); none: every column 0.5 from the 1×1 level', () => {
    // Anisotropy 8/0.47 = 17 → 16 taps along v at λ = log2(8/16) < 0 → level 0: the bilinear
    // stripes at u = (i + 0.5 − 4.25)/8.5, s = 4u − ½: columns 5, 6 at s = 0.09, 0.56 (between
    // two white texels), columns 10, 11 at s = 2.44, 2.91 (between two black ones). Isotropic:
    // λ = log2(8) = 3, past the top of the chain (4×1, 2×1, 1×1): the mean ½ everywhere — with
    // srgb that would show encode(½) = 188, with none 127.5.
    const expected: Record<ColorSpace, Record<number, number[]>> = { srgb: { 5: [255], 6: [255], 10: [0], 11: [0] }, none: { 5: [127, 128], 6: [127, 128], 10: [127, 128], 11: [127, 128] } };
    for (const space of ['srgb', 'none'] as ColorSpace[]) {
      const rgba = new SoftwareRenderer().render(scene, { ...STATE, colorSpace: space }, IMAGES);
      for (const [column, levels] of Object.entries(expected[space])) {
        for (let j = 5; j <= 11; j++) {
          for (let k = 0; k < 3; k++) expect(levels, `${space} pixel (${column}, ${j})`).toContain(rgba[4 * (j * N + Number(column)) + k]);
        }
      }
    }
  });
});
