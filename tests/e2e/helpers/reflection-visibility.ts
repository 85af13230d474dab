// How plainly the reflection shows (docs/knobs.md#bars-the-tests-hold): the final image with the
// default ior against ior 1 (F = 0, no reflection), per pixel the largest |Δ| over RGB, summarised
// over all pixels and over a mask (where the glass reflects the cube). reflection-visibility.spec.ts
// holds the perspective view to its bar with it, orthographic.spec.ts the orthographic one.
import type { Page } from '@playwright/test';
import { capture, setAttributes, type RgbaImage } from '../fixtures';

/** A pixel counts as showing the reflection at this many levels of difference or more. */
export const LEVEL = 15;

export interface Visibility {
  max: number;
  atLeast15: number;
  cubeMax: number;
  cubeAtLeast15: number;
  /** Pixels where the glass reflects the cube (geometry). */
  cubePixels: number;
}

/** Per-pixel max |Δ| over RGB between the two images, summarised over all pixels and over `mask`. */
export function visibility(withReflection: RgbaImage, without: RgbaImage, mask: Uint8Array): Visibility {
  const v: Visibility = { max: 0, atLeast15: 0, cubeMax: 0, cubeAtLeast15: 0, cubePixels: 0 };
  const a = withReflection.data, b = without.data;
  for (let p = 0; p < withReflection.width * withReflection.height; p++) {
    const i = 4 * p;
    const d = Math.max(Math.abs(a[i] - b[i]), Math.abs(a[i + 1] - b[i + 1]), Math.abs(a[i + 2] - b[i + 2]));
    v.max = Math.max(v.max, d);
    if (d >= LEVEL) v.atLeast15++;
    if (mask[p]) {
      v.cubePixels++;
      v.cubeMax = Math.max(v.cubeMax, d);
      if (d >= LEVEL) v.cubeAtLeast15++;
    }
  }
  return v;
}

/** Final frames of `selector` at `time` with the default ior and with ior 1 (no reflection), then back. */
export async function pair(page: Page, selector: string, time: number): Promise<[RgbaImage, RgbaImage]> {
  await setAttributes(page, selector, { time, ior: null });
  const on = await capture(page, undefined, selector);
  await setAttributes(page, selector, { ior: 1 });
  const off = await capture(page, undefined, selector);
  await setAttributes(page, selector, { ior: null });
  return [on, off];
}
