// Helpers for the stability and fuzz tests (docs/rendering.md#numerical-stability, docs/element.md#attribute-table): pixel differences between two frames,
// a "garbage pixel" proxy for NaN, a look-at camera, and the GL limits of the page's context.
import type { Page } from '@playwright/test';
import path from 'node:path';
import { OUTPUT_DIR, writePng, type RgbaImage } from './golden';
import type { Vec3 } from './projection';

const DEG = 180 / Math.PI;

/** yaw/pitch (degrees, docs/default-scene.md#the-camera) of a camera at `from` looking at `to`. */
export function lookAt(from: Vec3, to: Vec3): { yaw: number; pitch: number } {
  const d = [to[0] - from[0], to[1] - from[1], to[2] - from[2]];
  const len = Math.hypot(d[0], d[1], d[2]);
  return { yaw: Math.atan2(d[2], d[0]) * DEG, pitch: Math.asin(d[1] / len) * DEG };
}

/** camera-position / camera-rotation attributes, full float64 precision. */
export function cameraAttrs(position: Vec3, yaw: number, pitch: number): Record<string, string> {
  return { 'camera-position': position.join(' '), 'camera-rotation': `${yaw} ${pitch}` };
}

export interface FrameDiff {
  /** Mean |a − b| over R, G and B of every pixel, in 8-bit levels. */
  mean: number;
  /** Largest |a − b| of any channel. */
  max: number;
  /** Pixels with some channel differing by more than `level`. */
  changed: number;
  /** changed ÷ pixel count. */
  fraction: number;
}

export function diffImages(a: RgbaImage, b: RgbaImage, level = 8): FrameDiff {
  if (a.width !== b.width || a.height !== b.height) {
    throw new Error(`image sizes differ: ${a.width}×${a.height} vs ${b.width}×${b.height}`);
  }
  let sum = 0;
  let max = 0;
  let changed = 0;
  for (let i = 0; i < a.data.length; i += 4) {
    let m = 0;
    for (let c = 0; c < 3; c++) {
      const e = Math.abs(a.data[i + c] - b.data[i + c]);
      sum += e;
      if (e > m) m = e;
    }
    if (m > max) max = m;
    if (m > level) changed++;
  }
  const pixels = a.width * a.height;
  return { mean: sum / (3 * pixels), max, changed, fraction: changed / pixels };
}

export const formatDiff = (d: FrameDiff): string =>
  `mean ${d.mean.toFixed(3)}, max ${d.max}, ${d.changed} px (${(100 * d.fraction).toFixed(2)}%) beyond 8 levels`;

/**
 * Pixels that are pure black (0, 0, 0) or pure white (255, 255, 255) in the FINAL view.
 *
 * 8-bit pixels cannot hold NaN; a NaN or ±Inf in a shader shows up as a saturated pixel (a
 * NaN written to an UNORM target becomes 0 on SwiftShader, ±Inf becomes 0 or 255). The final
 * view never produces either legitimately (the default scene's numbers, docs/default-scene.md): the background is 0.1 grey
 * (26); the darkest lit colour is the cube's or sphere's ambient Ka·Ia with tex ≥ 85/255, i.e.
 * (10, 4, 4) or (4, 10, 4), never three zeros; the glass body D is ≥ (0.08, 0.10, 0.11)·(1−F)
 * and the reflection is at least the background; the brightest colour, a highlight on the
 * cube (diffuse + specular + ambient), saturates red only — green and blue stay below ~200 —
 * and F ≤ 1 keeps the glass within the colours it blends. So either extreme means garbage.
 * (The `fresnel` debug view is black off the glass and white at grazing by design: don't use
 * this on it.)
 */
export function garbagePixels(image: RgbaImage): { black: number; white: number } {
  let black = 0;
  let white = 0;
  const d = image.data;
  for (let i = 0; i < d.length; i += 4) {
    if (d[i] === 0 && d[i + 1] === 0 && d[i + 2] === 0) black++;
    else if (d[i] === 255 && d[i + 1] === 255 && d[i + 2] === 255) white++;
  }
  return { black, white };
}

/** Distinct RGB values of an image with their pixel counts, most frequent first. */
export function histogram(image: RgbaImage, top = 5): string {
  const counts = new Map<number, number>();
  for (let i = 0; i < image.data.length; i += 4) {
    const k = (image.data[i] << 16) | (image.data[i + 1] << 8) | image.data[i + 2];
    counts.set(k, (counts.get(k) ?? 0) + 1);
  }
  return [...counts.entries()]
    .sort((a, b) => b[1] - a[1])
    .slice(0, top)
    .map(([k, n]) => `(${k >> 16},${(k >> 8) & 255},${k & 255})×${n}`)
    .join(' ');
}

export interface GlLimits {
  maxViewport: [number, number];
  maxTexture: number;
  maxRenderbuffer: number;
  maxSamples: number;
}

/** The WebGL2 limits of this page, read from a throwaway canvas (its context is released). */
export async function glLimits(page: Page): Promise<GlLimits> {
  return page.evaluate(() => {
    const gl = document.createElement('canvas').getContext('webgl2');
    if (!gl) throw new Error('no WebGL2');
    const vp = gl.getParameter(gl.MAX_VIEWPORT_DIMS) as Int32Array;
    const out = {
      maxViewport: [vp[0], vp[1]] as [number, number],
      maxTexture: gl.getParameter(gl.MAX_TEXTURE_SIZE) as number,
      maxRenderbuffer: gl.getParameter(gl.MAX_RENDERBUFFER_SIZE) as number,
      maxSamples: gl.getParameter(gl.MAX_SAMPLES) as number,
    };
    gl.getExtension('WEBGL_lose_context')?.loseContext();
    return out;
  });
}

/** mulberry32: a small seeded PRNG, so the fuzz is the same sequence on every run (the unit tests' own, tests/unit/helpers/seeded.ts). */
export { seeded as mulberry32 } from '../../unit/helpers/seeded';

/** STABILITY_DEBUG=1: print the measured figures and keep the frames (tests/e2e/__output__/stability/). */
export const DEBUG = process.env.STABILITY_DEBUG === '1';

export function debugLog(line: string): void {
  if (DEBUG) console.log(line);
}

export function dumpImage(name: string, image: RgbaImage): void {
  if (!DEBUG) return;
  writePng(path.join(OUTPUT_DIR, 'stability', `${name.replace(/[^\w.-]+/g, '_')}.png`), image);
}
