// Error figures against the reference (PSNR/RMSE per region, max error), and the module's portability.
import { describe, expect, it } from 'vitest';
import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { instrumented } from './helpers/collections';
import {
  compareImages, REGION_BACKGROUND, REGION_CUBE, REGION_EDGE, REGION_GLASS, REGION_SPHERE, type ReferenceImage,
} from '../../src/reference';

/** A 5-pixel reference, one pixel per region, every channel 0.5. */
function tiny(): ReferenceImage {
  const regions = new Uint8Array([REGION_BACKGROUND, REGION_CUBE, REGION_SPHERE, REGION_GLASS, REGION_EDGE]);
  const rgb = new Float64Array(15).fill(0.5);
  const rgba = new Uint8ClampedArray(20);
  for (let i = 0; i < 5; i++) rgba.set([128, 128, 128, 255], 4 * i);
  return { width: 5, height: 1, view: 'final', samplesPerAxis: 1, textureFilter: 'point', rgb, rgba, regions, keys: new Int32Array(5) };
}

describe('compareImages', () => {
  it('identical to the 8-bit reference: infinite PSNR; against float the rounding (0.5 level) shows', () => {
    const ref = tiny();
    const q = compareImages(ref, ref.rgba, { against: 'rgba8' });
    expect(q.psnr.all).toBe(Infinity);
    expect(q.maxError).toBe(0);
    const f = compareImages(ref, ref.rgba);
    expect(f.rmse.all).toBeCloseTo(0.5, 12);
    expect(f.maxError).toBeCloseTo(0.5, 12);
    expect(f.psnr.all).toBeCloseTo(20 * Math.log10(255 / 0.5), 9);
  });

  it('routes pixels to their regions (cube and sphere are "objects")', () => {
    const ref = tiny();
    const img = new Uint8ClampedArray(ref.rgba);
    img[4 * 1] += 10; // cube pixel, red off by 10
    img[4 * 4 + 2] -= 6; // edge pixel, blue off by 6
    const c = compareImages(ref, img, { against: 'rgba8' });
    expect(c.pixels).toEqual({ all: 5, glass: 1, objects: 2, background: 1, edges: 1, dark: 0 });
    expect(c.rmse.objects).toBeCloseTo(Math.sqrt(100 / 6), 12);
    expect(c.rmse.edges).toBeCloseTo(Math.sqrt(36 / 3), 12);
    expect(c.rmse.background).toBe(0);
    expect(c.rmse.all).toBeCloseTo(Math.sqrt(136 / 15), 12);
    expect(c.maxError).toBe(10);
    expect(c.maxErrorByRegion.edges).toBe(6);
    expect(c.psnr.glass).toBe(Infinity);
  });

  it('"dark" counts pixels whose reference is below 32/255 in every channel, on top of their own region', () => {
    // Reference levels (of 255) per pixel, its region, and the image's error on one channel.
    const pixels: [number[], number, number, number][] = [
      [[20, 10, 5], REGION_BACKGROUND, 0, 3], // dark
      [[31.6, 0, 31], REGION_GLASS, 1, 4], // dark: the reference is below 32, though its byte is 32
      [[32, 0, 0], REGION_GLASS, 0, 10], // 32 is not
      [[128, 128, 128], REGION_CUBE, 0, 0],
      [[0, 0, 40], REGION_EDGE, 2, -7], // one channel above
      [[0, 0, 0], REGION_EDGE, 2, 2], // dark
    ];
    const n = pixels.length;
    const rgb = new Float64Array(3 * n), rgba = new Uint8ClampedArray(4 * n), img = new Uint8ClampedArray(4 * n);
    pixels.forEach(([levels, , channel, error], i) => {
      levels.forEach((l, c) => { rgb[3 * i + c] = l / 255; rgba[4 * i + c] = l; img[4 * i + c] = l + (c === channel ? error : 0); });
    });
    const ref: ReferenceImage = {
      width: n, height: 1, view: 'final', samplesPerAxis: 1, textureFilter: 'point', rgb, rgba,
      regions: new Uint8Array(pixels.map((p) => p[1])), keys: new Int32Array(n),
    };
    const c = compareImages(ref, img, { against: 'rgba8' });
    expect(c.pixels).toEqual({ all: 6, glass: 2, objects: 1, background: 1, edges: 2, dark: 3 });
    expect(c.rmse.dark).toBeCloseTo(Math.sqrt((9 + 16 + 4) / 9), 12);
    expect(c.maxErrorByRegion.dark).toBe(4);
    // The other regions as without it: each pixel once in its own region and in 'all'.
    expect(c.rmse.glass).toBeCloseTo(Math.sqrt((16 + 100) / 6), 12);
    expect(c.rmse.edges).toBeCloseTo(Math.sqrt((49 + 4) / 6), 12);
    expect(c.rmse.all).toBeCloseTo(Math.sqrt((9 + 16 + 100 + 49 + 4) / 18), 12);
    expect(c.maxError).toBe(10);
    expect(rgba[4]).toBe(32);
    expect(compareImages(ref, img).pixels.dark).toBe(3);
  });

  it('empty regions give NaN, a wrong-sized image throws a prefixed error', () => {
    const ref = { ...tiny(), regions: new Uint8Array(5) };
    expect(compareImages(ref, ref.rgba).rmse.glass).toBeNaN();
    expect(() => compareImages(ref, new Uint8Array(16))).toThrow('glass-plane-scene: image has 16 bytes, the 5×1 reference needs 20');
  });
});

describe('compareImages: images of more than one row', () => {
  it('counts width × height pixels, row by row', () => {
    // 2×3, every pixel background at 0.5 (reference byte 128); the image's bottom-right pixel off by 6 in green.
    const rgb = new Float64Array(18).fill(0.5), rgba = new Uint8ClampedArray(24);
    for (let i = 0; i < 6; i++) rgba.set([128, 128, 128, 255], 4 * i);
    const ref: ReferenceImage = {
      width: 2, height: 3, view: 'final', samplesPerAxis: 1, textureFilter: 'point', rgb, rgba, regions: new Uint8Array(6), keys: new Int32Array(6),
    };
    const img = new Uint8ClampedArray(rgba);
    img[4 * 5 + 1] += 6;
    const c = compareImages(ref, img, { against: 'rgba8' });
    expect(c.pixels.all).toBe(6);
    expect(c.pixels.background).toBe(6);
    expect(c.rmse.all).toBeCloseTo(Math.sqrt(36 / 18), 12);
    expect(c.maxError).toBe(6);
    expect(() => compareImages(ref, new Uint8Array(20))).toThrow('glass-plane-scene: image has 20 bytes, the 2×3 reference needs 24');
  });
});

describe('portability', () => {
  // Under StrykerJS the files read are its instrumented copies, which reach for its globals.
  it.skipIf(instrumented)('src/reference uses no Node-only API (runs in the browser and in workers)', () => {
    const dir = join(__dirname, '../../src/reference');
    const files = readdirSync(dir).filter((f) => f.endsWith('.ts'));
    expect(files.length).toBeGreaterThan(5);
    let imports = 0;
    for (const f of files) {
      const text = readFileSync(join(dir, f), 'utf8');
      expect(text, f).not.toMatch(/from '(node:|fs|path|os|url|worker_threads|perf_hooks)/);
      expect(text, f).not.toMatch(/\b(Buffer|process|require|__dirname|__filename|setImmediate)\b/);
      // Only pure modules at run time: math, scene data, gl-matrix; the frame's state only for types.
      for (const [, typeOnly, spec] of text.matchAll(/^(?:import|export) (type )?[^;]*? from '([^']+)'/gms)) {
        const allowed = typeOnly ? /^(\.\/|\.\.\/math\/|\.\.\/scene\/|\.\.\/frame\/types$|gl-matrix$)/ : /^(\.\/|\.\.\/math\/|\.\.\/scene\/|gl-matrix$)/;
        expect(spec, `${f} imports ${spec}`).toMatch(allowed);
        imports++;
      }
      expect(text.split('\n').length, `${f} is short`).toBeLessThan(300);
    }
    expect(imports).toBeGreaterThan(20);
  });
});
