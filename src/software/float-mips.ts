// A mip chain of an RGBA Float32 buffer (colour in linear light, and rough glass's distance code
// in the fourth channel), read trilinearly: what rough glass gathers its reflection and
// transmission from (docs/rough-glass.md#transmission), as the GL path reads a mipmapped texture with textureLod.

export class FloatMips {
  constructor(readonly channels = 4) {}
  /** Level k: width ⌈W/2^k⌉ × height ⌈H/2^k⌉, RGBA; level 0 aliases the source. */
  private levels: Float32Array[] = [];
  private widths: number[] = [];
  private heights: number[] = [];
  private owned: Float32Array[] = [];

  /** Builds the chain of `source` (W × H RGBA) down to 1×1 by 2×2 box filters (the last column or row kept at odd sizes). */
  build(source: Float32Array, W: number, H: number): void {
    this.levels.length = 0;
    this.widths.length = 0;
    this.heights.length = 0;
    this.levels.push(source);
    this.widths.push(W);
    this.heights.push(H);
    let w = W, h = H, k = 0;
    while (w > 1 || h > 1) {
      const nw = Math.max(1, (w + 1) >> 1), nh = Math.max(1, (h + 1) >> 1);
      const C = this.channels;
      if (!this.owned[k] || this.owned[k].length < C * nw * nh) this.owned[k] = new Float32Array(C * nw * nh);
      const src = this.levels[k], dst = this.owned[k];
      for (let y = 0; y < nh; y++) {
        const y0 = Math.min(2 * y, h - 1), y1 = Math.min(2 * y + 1, h - 1);
        for (let x = 0; x < nw; x++) {
          const x0 = Math.min(2 * x, w - 1), x1 = Math.min(2 * x + 1, w - 1);
          const a = C * (y0 * w + x0), b = C * (y0 * w + x1), c = C * (y1 * w + x0), d = C * (y1 * w + x1), o = C * (y * nw + x);
          for (let ch = 0; ch < C; ch++) dst[o + ch] = 0.25 * (src[a + ch] + src[b + ch] + src[c + ch] + src[d + ch]);
        }
      }
      this.levels.push(dst);
      this.widths.push(nw);
      this.heights.push(nh);
      w = nw; h = nh; k++;
    }
  }

  /**
   * Adds weight·texel at level-0 position (x, y) (texel units, centres at i + ½) and level of
   * detail `lod` (0: level 0; fractional: between two levels) into out[0..3]; edges clamp.
   */
  addSample(out: Float64Array, x: number, y: number, lod: number, weight: number): void {
    const top = this.levels.length - 1;
    const l = lod <= 0 ? 0 : lod >= top ? top : lod;
    const k = Math.floor(l), f = l - k;
    this.bilinear(out, k, x, y, weight * (1 - f));
    if (f > 0) this.bilinear(out, k + 1, x, y, weight * f);
  }

  private bilinear(out: Float64Array, k: number, x: number, y: number, weight: number): void {
    const s = 1 / (1 << k), w = this.widths[k], h = this.heights[k], src = this.levels[k];
    let fx = x * s - 0.5, fy = y * s - 0.5;
    fx = fx < 0 ? 0 : fx > w - 1 ? w - 1 : fx;
    fy = fy < 0 ? 0 : fy > h - 1 ? h - 1 : fy;
    const x0 = Math.floor(fx), y0 = Math.floor(fy);
    const x1 = x0 + 1 < w ? x0 + 1 : x0, y1 = y0 + 1 < h ? y0 + 1 : y0;
    const ax = fx - x0, ay = fy - y0;
    const C = this.channels, a = C * (y0 * w + x0), b = C * (y0 * w + x1), c = C * (y1 * w + x0), d = C * (y1 * w + x1);
    const wa = (1 - ax) * (1 - ay) * weight, wb = ax * (1 - ay) * weight, wc = (1 - ax) * ay * weight, wd = ax * ay * weight;
    for (let ch = 0; ch < C; ch++) out[ch] += wa * src[a + ch] + wb * src[b + ch] + wc * src[c + ch] + wd * src[d + ch];
  }
}
