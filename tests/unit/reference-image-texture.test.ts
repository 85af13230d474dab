// An image as the reference samples it (src/reference/image-texture.ts): three channels, rows flipped (v = 0 is the
// image's bottom row), bytes decoded by the colour space, and null for pixels that do not fit the size.
import { describe, expect, it } from 'vitest';
import { imageTexture } from '../../src/reference/image-texture';
import { byteLevels, proceduralGrey } from '../../src/reference/texture-sampler';
import { srgbToLinear } from '../../src/math/srgb';

/** A w×h RGBA image whose texel (x, y from the top) is (10·x + 40·y + 1, 2 + that, 200 − that, alpha 7). */
function image(w: number, h: number, extra = 0) {
  const data = new Uint8Array(w * h * 4 + extra);
  for (let y = 0; y < h; y++) {
    for (let x = 0; x < w; x++) {
      const b = 10 * x + 40 * y + 1;
      data.set([b, b + 2, 200 - b, 7], 4 * (y * w + x));
    }
  }
  return { width: w, height: h, data };
}

describe('imageTexture', () => {
  it("as stored ('none'): channel c of texture texel (i, j) is byte c of image pixel (i, H − 1 − j), over 255", () => {
    const t = imageTexture(image(2, 3), 'none')!;
    expect([t.width, t.height, t.channels.length]).toEqual([2, 3, 3]);
    for (const ch of t.channels) expect([ch.width, ch.height]).toEqual([2, 3]);
    // Texture row 0 is image row 2: bytes 81 (x 0) and 91 (x 1); row 2 is image row 0: 1 and 11.
    const [r, g, b] = t.channels;
    expect([r.texel(0, 0), r.texel(1, 0), r.texel(0, 1), r.texel(1, 1), r.texel(0, 2), r.texel(1, 2)])
      .toEqual([81, 91, 41, 51, 1, 11].map((v) => v / 255));
    expect([g.texel(0, 0), g.texel(1, 2)]).toEqual([83 / 255, 13 / 255]);
    expect([b.texel(0, 0), b.texel(1, 2)]).toEqual([119 / 255, 189 / 255]);
  });

  it("with 'srgb' the bytes are decoded to linear light", () => {
    const [r, g, b] = imageTexture(image(2, 3), 'srgb')!.channels;
    expect(r.texel(1, 0)).toBeCloseTo(srgbToLinear(91 / 255), 12);
    expect(g.texel(0, 2)).toBeCloseTo(srgbToLinear(3 / 255), 12);
    expect(b.texel(0, 1)).toBeCloseTo(srgbToLinear(159 / 255), 12);
    expect(r.texel(1, 0)).toBeLessThan(91 / 255 - 0.2);
  });

  it('a single texel, and one row or one column, are images too; extra bytes are ignored', () => {
    const one = imageTexture(image(1, 1), 'none')!;
    expect(one.channels.map((c) => c.texel(0, 0))).toEqual([1 / 255, 3 / 255, 199 / 255]);
    const row = imageTexture(image(3, 1, 5), 'none')!;
    expect([row.channels[0].texel(0, 0), row.channels[0].texel(2, 0)]).toEqual([1 / 255, 21 / 255]);
    const column = imageTexture(image(1, 2), 'none')!;
    expect([column.channels[0].texel(0, 0), column.channels[0].texel(0, 1)]).toEqual([41 / 255, 1 / 255]);
  });

  it('null for an empty or fractional size, or too few bytes', () => {
    const data = new Uint8Array(64);
    expect(imageTexture({ width: 0, height: 2, data }, 'none')).toBeNull();
    expect(imageTexture({ width: 2, height: 0, data }, 'none')).toBeNull();
    expect(imageTexture({ width: 1.5, height: 2, data }, 'none')).toBeNull();
    expect(imageTexture({ width: 2, height: 1.5, data }, 'none')).toBeNull();
    expect(imageTexture({ width: NaN, height: 2, data }, 'none')).toBeNull();
    expect(imageTexture({ width: 2, height: 2, data: new Uint8Array(15) }, 'none')).toBeNull();
    expect(imageTexture({ width: 2, height: 2, data: new Uint8Array(16) }, 'none')).not.toBeNull();
  });
});

describe('byteLevels, proceduralGrey', () => {
  it("'none' is b/255; 'srgb' the sRGB decoding of b/255", () => {
    const none = byteLevels('none'), srgb = byteLevels('srgb');
    expect([none.length, none[0], none[51], none[255]]).toEqual([256, 0, 0.2, 1]);
    expect(srgb[0]).toBe(0);
    expect(srgb[255]).toBeCloseTo(1, 12);
    expect(srgb[128]).toBeCloseTo(srgbToLinear(128 / 255), 12);
  });

  it('the procedural grey: 512², the same texels in either space up to the decoding', () => {
    const none = proceduralGrey('none'), srgb = proceduralGrey('srgb');
    expect(none.length).toBe(512 * 512);
    for (const i of [0, 1, 777, 512 * 512 - 1]) expect(srgb[i]).toBeCloseTo(srgbToLinear(none[i]), 12);
  });
});
