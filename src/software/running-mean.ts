// Refinement at rest in the software renderer (docs/refinement.md#averaging): frame 1 of a still view is kept as the
// preview, frames 2..N are averaged into the strata's mean (each pixel's n × n samples box-filtered first), all in
// linear light, and the picture resolved is the preview blended into the mean by frame/refinement.ts's meanShare.
import { meanShare, refinementWeight } from '../frame/refinement';

export class RunningMean {
  /** Linear RGB per pixel of the whole frame; a band writes only its rows. */
  private preview = new Float32Array(0);
  private mean = new Float32Array(0);
  private shown = new Float32Array(0);

  /**
   * Adds rows [top, bottom) of a `width`-wide frame of `height` rows, drawn with n × n samples per pixel in `source` (the
   * band's samples, first row first), as frame k of a still view of `frames`. Returns the band of the picture to show.
   */
  add(source: Float32Array, width: number, height: number, top: number, bottom: number, n: number, k: number, frames: number): Float32Array {
    const size = 3 * width * height;
    if (this.mean.length < size) {
      this.preview = new Float32Array(size);
      this.mean = new Float32Array(size);
      this.shown = new Float32Array(size);
    }
    const from = 3 * top * width, to = 3 * bottom * width;
    const preview = this.preview.subarray(from, to);
    if (k < 2) {
      // Stryker disable next-line ArithmeticOperator: bottom + top rows write only past the band's end (a subarray: dropped)
      boxInto(preview, source, width, bottom - top, n, 0, 1);
      return preview;
    }
    const mean = this.mean.subarray(from, to), shown = this.shown.subarray(from, to);
    const w = refinementWeight(k);
    // Stryker disable next-line ConditionalExpression,EqualityOperator: at k = 2 the weight is 1, so 1 − w is the 0 it keeps
    boxInto(mean, source, width, bottom - top, n, k > 2 ? 1 - w : 0, w);
    const t = meanShare(k, frames);
    // Stryker disable next-line EqualityOperator: i = shown.length writes past the band's end (dropped)
    for (let i = 0; i < shown.length; i++) shown[i] = (1 - t) * preview[i] + t * mean[i];
    return shown;
  }
}

/** out = keep·out + w·(the mean of each pixel's n × n samples in `source`), for `rows` rows of `width` pixels. */
function boxInto(out: Float32Array, source: Float32Array, width: number, rows: number, n: number, keep: number, w: number): void {
  const scale = w / (n * n), W = width * n;
  // Stryker disable next-line EqualityOperator: y = rows writes past the band's end (dropped)
  for (let y = 0; y < rows; y++) {
    for (let x = 0; x < width; x++) {
      let r = 0, g = 0, b = 0;
      for (let sy = 0; sy < n; sy++) {
        let o = 3 * ((y * n + sy) * W + x * n);
        for (let sx = 0; sx < n; sx++, o += 3) {
          r += source[o]; g += source[o + 1]; b += source[o + 2];
        }
      }
      const p = 3 * (y * width + x);
      out[p] = keep * out[p] + scale * r;
      out[p + 1] = keep * out[p + 1] + scale * g;
      out[p + 2] = keep * out[p + 2] + scale * b;
    }
  }
}
