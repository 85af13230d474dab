// Debug views as a whole: the 'passes' tiles cover the canvas, whatever its size; the 'fresnel'
// view shows the same F as the TypeScript Fresnel functions.
import { test, expect, mount, openPage, capture, setAttributes } from './fixtures';
import { pixelRay, type Camera } from './helpers/projection';
import { note } from './helpers/bounds';
import { fresnel, FRESNEL_MODELS } from '../../src/math/fresnel';

test.describe('debug-view passes', () => {
  for (const samples of [0, 4]) {
    test(`odd-sized canvas, samples ${samples}: every pixel is written by one of the four tiles`, async ({ page }) => {
      await openPage(page);
      // 161×91: the halves are 80 and 81 wide, 45 and 46 high; a tile of floor(size / 2) each
      // side leaves the middle column and row unwritten (transparent black).
      const { selector } = await mount(page, { time: 1.25, 'debug-view': 'passes', 'pixel-ratio': 1, samples }, { width: 161, height: 91 });
      const image = await capture(page, undefined, selector);
      expect([image.width, image.height]).toEqual([161, 91]);
      const unwritten: string[] = [];
      for (let y = 0; y < image.height; y++) {
        for (let x = 0; x < image.width; x++) {
          if (image.data[(y * image.width + x) * 4 + 3] !== 255) unwritten.push(`(${x}, ${y})`);
        }
      }
      expect(unwritten.length, `pixels no tile wrote (alpha ≠ 255), e.g. ${unwritten.slice(0, 5).join(' ')}`).toBe(0);
    });
  }
});

// The Fresnel term is written twice, in src/math/fresnel.ts and shaders/glass.frag. debug-view
// fresnel shows the shader's F as grey on the glass; here it must match the TypeScript fresnel()
// at each glass pixel's analytic cosθ, so a change to either formula (an exponent, a sign) fails.
test.describe('debug-view fresnel matches fresnel() of src/math/fresnel.ts', () => {
  const W = 160, H = 90;
  const VIEWS: Array<{ name: string; camera: Camera }> = [
    { name: 'head-on', camera: { position: [0, 1, 3], yaw: -90, pitch: 0 } },
    { name: 'oblique', camera: { position: [3, 2, 3], yaw: -135, pitch: -13.26 } },
    { name: 'grazing', camera: { position: [6, 1, 1.2], yaw: -168.7, pitch: 0 } },
  ];
  /** Does the ray through pixel (x, y) meet the glass rectangle (x ∈ [−4, 4], y ∈ [−1, 3], z = 0)? */
  const onGlass = (c: Camera, x: number, y: number) => {
    const d = pixelRay(c, x, y, W, H);
    const t = -c.position[2] / d[2];
    if (!(t > 0)) return false;
    const gx = c.position[0] + t * d[0];
    const gy = c.position[1] + t * d[1];
    return gx > -4 && gx < 4 && gy > -1 && gy < 3;
  };

  for (const model of FRESNEL_MODELS) {
    test(`fresnel ${model}`, async ({ page }) => {
      await openPage(page);
      // The cube far behind the glass, so nothing stands in front of it; no MSAA, so each pixel is its centre.
      const { selector } = await mount(page, {
        time: 1.25, spin: 0, 'debug-view': 'fresnel', fresnel: model, ior: 1.5, 'cube-distance': -50, samples: 0, 'pixel-ratio': 1,
      }, { width: W, height: H });
      let compared = 0;
      let worst = { diff: 0, at: '' };
      let largestF = 0;
      for (const { name, camera } of VIEWS) {
        await setAttributes(page, selector, {
          'camera-position': camera.position.join(' '), 'camera-rotation': `${camera.yaw} ${camera.pitch}`,
        });
        const image = await capture(page, undefined, selector);
        expect([image.width, image.height]).toEqual([W, H]);
        for (let y = 1; y < H - 1; y += 2) {
          for (let x = 1; x < W - 1; x += 2) {
            // Away from the glass's edges: the pixel and its eight neighbours are all on it.
            let inside = true;
            for (let dy = -1; dy <= 1 && inside; dy++) for (let dx = -1; dx <= 1 && inside; dx++) inside = onGlass(camera, x + dx, y + dy);
            if (!inside) continue;
            const d = pixelRay(camera, x, y, W, H);
            const cos = Math.abs(d[2]) / Math.hypot(d[0], d[1], d[2]);
            const expected = fresnel(model, cos, 1.5) * 255;
            const got = image.data[(y * W + x) * 4];
            const diff = Math.abs(got - expected);
            if (diff > worst.diff) worst = { diff, at: `${name} (${x}, ${y}): cosθ ${cos.toFixed(4)}, shader ${got}, fresnel() ${expected.toFixed(2)}` };
            largestF = Math.max(largestF, expected);
            compared++;
          }
        }
      }
      note(`fresnel ${model}: ${compared} glass px compared, largest F ${(largestF / 255).toFixed(3)}, worst ${worst.diff.toFixed(2)} levels at ${worst.at}`);
      expect(compared, 'glass pixels compared').toBeGreaterThan(1000);
      expect(largestF, 'the views reach strong reflectance, where the models differ most').toBeGreaterThan(0.3 * 255);
      // Measured 0.59–0.61 levels for the three models (0.5 of it is the 8-bit rounding of the
      // shader's F); the bound, 0.85, is √2 × that (3 dB).
      expect(worst.diff, `largest difference in grey levels, at ${worst.at}`).toBeLessThanOrEqual(0.85);
    });
  }
});
