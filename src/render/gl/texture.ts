// An RGBA8 2D texture from pixels (row 0 uploaded first: a decoded image's top row), optionally
// mipmapped and repeating; `srgb` stores it as SRGB8_ALPHA8, which the GPU
// decodes to linear light before filtering (docs/colour.md#srgb), and whose mipmaps it averages in linear.
import type { ResourceCounter } from './resource-counter';

export interface TextureOptions {
  width: number;
  height: number;
  data: Uint8Array | Uint8ClampedArray | null;
  mipmap?: boolean;
  repeat?: boolean;
  /** Colour data in sRGB (SRGB8_ALPHA8): sampled as linear light. */
  srgb?: boolean;
  /**
   * Filter anisotropically (EXT_texture_filter_anisotropic, up to 16 taps), where a surface seen
   * at a slant needs more texels along one direction than the other: closer to the mean over the
   * pixel's footprint that the reference takes than one isotropic mip level.
   */
  anisotropic?: boolean;
}

/** Most taps an anisotropic read takes here: beyond 16 the figures stop improving. */
const MAX_ANISOTROPY = 16;

export class Texture {
  readonly handle: WebGLTexture;

  constructor(private readonly gl: WebGL2RenderingContext, private readonly counter: ResourceCounter, o: TextureOptions) {
    const t = gl.createTexture()!;
    counter.add('textures');
    gl.bindTexture(gl.TEXTURE_2D, t);
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
    const format = o.srgb ? gl.SRGB8_ALPHA8 : gl.RGBA8;
    // No flip on upload: the shader reads images at (u, 1 − v), which puts OBJ's v = 0 on the image's bottom row.
    gl.texImage2D(gl.TEXTURE_2D, 0, format, o.width, o.height, 0, gl.RGBA, gl.UNSIGNED_BYTE, o.data);
    const wrap = o.repeat ? gl.REPEAT : gl.CLAMP_TO_EDGE;
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, wrap);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, wrap);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, o.mipmap ? gl.LINEAR_MIPMAP_LINEAR : gl.LINEAR);
    if (o.mipmap) gl.generateMipmap(gl.TEXTURE_2D);
    const aniso = o.anisotropic && o.mipmap ? gl.getExtension('EXT_texture_filter_anisotropic') : null;
    if (aniso) {
      const max = gl.getParameter(aniso.MAX_TEXTURE_MAX_ANISOTROPY_EXT) as number;
      gl.texParameterf(gl.TEXTURE_2D, aniso.TEXTURE_MAX_ANISOTROPY_EXT, Math.min(MAX_ANISOTROPY, max));
    }
    gl.bindTexture(gl.TEXTURE_2D, null);
    this.handle = t;
  }

  bind(unit: number): void {
    const gl = this.gl;
    gl.activeTexture(gl.TEXTURE0 + unit);
    gl.bindTexture(gl.TEXTURE_2D, this.handle);
  }

  dispose(): void {
    this.gl.deleteTexture(this.handle);
    this.counter.add('textures', -1);
  }
}
