// The software renderer's textures (src/software/mip-texture.ts) by hand, isotropic reads: the mip
// chain down to 1×1, REPEAT on sides that are not powers of two, and which decoded images make a
// texture at all. Anisotropic reads are software-anisotropic.test.ts's.
import { describe, expect, it } from 'vitest';
import { imageMipTexture, MipTexture } from '../../src/software/mip-texture';

/** The read at (u, v) with no derivatives: the base level, bilinear. */
function read(t: MipTexture, u: number, v: number): number {
  const out = new Float64Array(3);
  t.sample(Float64Array.of(u, v, 0, 0, 0, 0), out);
  return out[0];
}

describe('MipTexture', () => {
  it('halves its levels down to 1×1, a side of 1 staying 1: 1×4, 1×2, 1×1', () => {
    const t = new MipTexture(1, 1, 4, new Float32Array([0, 0.25, 0.5, 1]));
    expect(t.levels.map((l) => [l.width, l.height, ...l.data])).toEqual([
      [1, 4, 0, 0.25, 0.5, 1],
      [1, 2, 0.125, 0.75], // (0 + 0.25) / 2, (0.5 + 1) / 2
      [1, 1, 0.4375],
    ]);
  });

  it('repeats a texture whose sides are not powers of two (3×3): a whole period away reads the same', () => {
    // Texel (i, j) holds i + 10j; s = 3u − ½ and t = 3v − ½ in texels from texel (0, 0)'s centre.
    const t = new MipTexture(1, 3, 3, Float32Array.from({ length: 9 }, (_, p) => (p % 3) + 10 * Math.floor(p / 3)));
    // Texel (1, 1)'s centre, and the same a period and more away on either side.
    expect([read(t, 0.5, 0.5), read(t, 1.5, -0.5), read(t, -2.5, 2.5)]).toEqual([11, 11, 11]);
    // s = t = ¼: ¾ of texel 0 and ¼ of texel 1 either way, 0.25 + 10 × 0.25.
    expect(read(t, 0.25, 0.25)).toBe(2.75);
    // The same a period back in u, a period on in v (s = −2.75, t = 3.25).
    expect(read(t, -0.75, 1.25)).toBe(2.75);
    // s = −½: half of column 2 (by REPEAT) and half of column 0, 1; t = ¼: 2.5.
    expect(read(t, 0, 0.25)).toBe(3.5);
  });
});

describe('imageMipTexture', () => {
  const image = (width: number, height: number, bytes: number) => ({ width, height, data: new Uint8Array(bytes) });

  it('makes a texture of an image whose pixels fill its size, and none of any other', () => {
    expect(imageMipTexture(image(1, 2, 8), 'none')?.levels[0]).toMatchObject({ width: 1, height: 2 });
    for (const [w, h, bytes] of [[1, 2, 4], [0, 2, 8], [2, 0, 8], [1.5, 2, 12], [2, 1.5, 12]]) {
      expect(imageMipTexture(image(w, h, bytes), 'none'), `${w}×${h}, ${bytes} bytes`).toBeNull();
    }
  });
});
