// Bounds close to what is measured. SwiftShader is a deterministic CPU rasterizer and
// the Chromium is pinned (package-lock), so a figure measured here is the same, run after run; a
// bound far under it would let a real regression through unseen. Each bound in the specs has the
// figure it was set from beside it, and is one of:
//  - a PSNR at most MARGIN_DB under the measured figure (expectPsnr);
//  - a pixel count or level within a stated margin of the measured one, with the reason.
import { expect, test } from '../fixtures';
import type { ImageComparison, RegionName } from '../../../src/reference';

/** How far a PSNR bound sits under the figure measured here, in dB. */
export const MARGIN_DB = 2;

/** Prints a measured figure and keeps it with the test's result. */
export function note(line: string): void {
  console.log(line);
  test.info().annotations.push({ type: 'figure', description: line });
}

/**
 * Expects each region of `cmp` at most MARGIN_DB under the figure `measured` gives for it (dB,
 * as measured on this machine); regions not given are not bounded.
 */
export function expectPsnr(cmp: Pick<ImageComparison, 'psnr'>, measured: Partial<Record<RegionName, number>>, what: string): void {
  for (const [region, figure] of Object.entries(measured) as [RegionName, number][]) {
    expect(cmp.psnr[region], `${what}: PSNR ${region} ${cmp.psnr[region].toFixed(1)} dB, measured ${figure} dB, bound ${figure - MARGIN_DB} dB`)
      .toBeGreaterThanOrEqual(figure - MARGIN_DB);
  }
}

/** PSNR (dB) of two RGBA8 images of the same size over their colour channels (alpha left out). */
export function psnr(a: ArrayLike<number>, b: ArrayLike<number>): number {
  let se = 0, n = 0;
  for (let i = 0; i < a.length; i++) {
    if (i % 4 === 3) continue;
    se += (a[i] - b[i]) ** 2;
    n++;
  }
  return 10 * Math.log10((255 * 255 * n) / se);
}
