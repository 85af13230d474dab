// Pixels of a framebuffer as the page sees them: RGBA8, top row first.
import { linearToSrgbByte } from '../../math/srgb';

export interface Pixels {
  width: number;
  height: number;
  /** RGBA8, top row first. */
  data: Uint8ClampedArray<ArrayBuffer>;
}

/**
 * RGBA8, top row first; a half-float target is read as float and rounded as an 8-bit one would
 * be (encoded first when it holds linear light).
 */
export function readFramebuffer(
  gl: WebGL2RenderingContext, framebuffer: WebGLFramebuffer | null, width: number, height: number, float = false, encode = false,
): Pixels {
  let raw = new Uint8Array(width * height * 4);
  gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
  gl.pixelStorei(gl.PACK_ALIGNMENT, 1);
  if (float) {
    const f = new Float32Array(width * height * 4);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.FLOAT, f);
    raw = Uint8Array.from(f, (x, i) => (encode && i % 4 !== 3 ? linearToSrgbByte(x) : Math.round(Math.min(1, Math.max(0, x)) * 255)));
  } else {
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, raw);
  }
  gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  const data = new Uint8ClampedArray(raw.length);
  const row = width * 4;
  for (let y = 0; y < height; y++) data.set(raw.subarray((height - 1 - y) * row, (height - y) * row), y * row);
  return { width, height, data };
}
