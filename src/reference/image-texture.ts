// A material's texture as the reference samples it: the procedural grey, or an image's R, G and B.
import { byteLevels, TextureSampler } from './texture-sampler';
import type { DecodedImage } from '../scene/decoded-image';
import type { ColorSpace } from '../math/srgb';

/** One sampler (grey: R = G = B) or three (R, G, B), all of one size. */
export interface ChannelTexture {
  readonly channels: readonly TextureSampler[];
  readonly width: number;
  readonly height: number;
}

/**
 * An image as three bilinear channels. OBJ convention (docs/scene-model.md#image-textures): v = 0 is the bottom row of
 * the image, so texture row j (v = (j + ½)/H) is image row H − 1 − j. Texels are decoded to
 * linear light with `srgb` (docs/colour.md#srgb: an image is colour data), used as stored with `none`.
 * Null when the pixels do not match the size (the caller falls back to the procedural texture).
 */
export function imageTexture(image: DecodedImage, colorSpace: ColorSpace, alpha = false): ChannelTexture | null {
  const { width: w, height: h, data } = image;
  const levels = byteLevels(alpha ? 'none' : colorSpace);
  if (!(w >= 1 && h >= 1 && Number.isInteger(w) && Number.isInteger(h)) || data.length < w * h * 4) return null;
  // `alpha`: the alpha channel as stored, in all three (glTF's alpha mask, docs/gltf.md#alpha).
  const channels = (alpha ? [3, 3, 3] : [0, 1, 2]).map((c) => {
    const grey = new Float64Array(w * h);
    // Stryker disable next-line EqualityOperator: a row j = h would be written past the end of grey (w·h long): dropped
    for (let j = 0; j < h; j++) {
      const row = (h - 1 - j) * w;
      // Stryker disable next-line EqualityOperator: texel i = w is the next row's first, written again (or past the end)
      for (let i = 0; i < w; i++) grey[j * w + i] = levels[data[(row + i) * 4 + c]];
    }
    return new TextureSampler(grey, w, h);
  });
  return { channels, width: w, height: h };
}
