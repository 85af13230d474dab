// RGBA images in Node: PNG read/write and comparison against the goldens in tests/e2e/goldens/.
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { PNG } from 'pngjs';
import pixelmatch from 'pixelmatch';

/** Top row first, 4 bytes per pixel, like ImageData. */
export interface RgbaImage {
  width: number;
  height: number;
  data: Uint8Array;
}

const E2E_DIR = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
export const GOLDEN_DIR = path.join(E2E_DIR, 'goldens');
export const OUTPUT_DIR = path.join(E2E_DIR, '__output__');

/**
 * pixelmatch's per-pixel colour threshold (YIQ distance, 0..1). 0.1 lets 26 of 255 grey levels
 * through, enough to hide a Fresnel bug; 0.02 is about 5 levels.
 */
export const PIXEL_THRESHOLD = 0.02;

/**
 * Fraction of pixels allowed to differ beyond PIXEL_THRESHOLD. SwiftShader is a deterministic
 * CPU rasterizer and the Chromium is pinned (@sparticuz/chromium in package-lock), so the same
 * frame gives the same bytes from run to run and machine to machine; the budget only absorbs
 * rasterization ties on edges (a triangle edge passing exactly through a pixel centre can go
 * either way if a matrix differs in its last ulp). A real change (a pass missing, a wrong
 * Fresnel, a shifted reflection) touches thousands of pixels.
 */
export const DIFF_BUDGET = 0.001;

export function readPng(file: string): RgbaImage {
  const png = PNG.sync.read(fs.readFileSync(file));
  return { width: png.width, height: png.height, data: new Uint8Array(png.data.buffer, png.data.byteOffset, png.data.length) };
}

export function writePng(file: string, image: RgbaImage): void {
  const png = new PNG({ width: image.width, height: image.height });
  png.data = Buffer.from(image.data.buffer, image.data.byteOffset, image.data.byteLength);
  fs.mkdirSync(path.dirname(file), { recursive: true });
  fs.writeFileSync(file, PNG.sync.write(png));
}

export interface Comparison {
  /** Pixels beyond the colour threshold. */
  differing: number;
  /** RGBA diff image (pixelmatch's rendering): differing pixels in red over a faded copy. */
  diff: RgbaImage;
}

export function compareImages(a: RgbaImage, b: RgbaImage, threshold = PIXEL_THRESHOLD): Comparison {
  if (a.width !== b.width || a.height !== b.height) {
    throw new Error(`image sizes differ: ${a.width}×${a.height} vs ${b.width}×${b.height}`);
  }
  const diff = { width: a.width, height: a.height, data: new Uint8Array(a.width * a.height * 4) };
  const differing = pixelmatch(a.data, b.data, diff.data, a.width, a.height, { threshold, includeAA: true });
  return { differing, diff };
}

export const updatingGoldens = (): boolean => process.env.UPDATE_GOLDENS === '1';

/**
 * Compares `image` with tests/e2e/goldens/<name>.png and throws when more than DIFF_BUDGET of the
 * pixels differ, leaving <name>-actual.png, -expected.png and -diff.png in tests/e2e/__output__/.
 * A missing golden is a failure: goldens are made on purpose (`npm run goldens`, which sets
 * UPDATE_GOLDENS=1 and makes this write the golden instead), never as a side effect of a test run.
 */
export function compareToGolden(name: string, image: RgbaImage): void {
  const goldenFile = path.join(GOLDEN_DIR, `${name}.png`);
  if (updatingGoldens()) {
    writePng(goldenFile, image);
    console.log(`updated golden ${path.relative(process.cwd(), goldenFile)} (${image.width}×${image.height})`);
    return;
  }
  if (!fs.existsSync(goldenFile)) {
    writePng(path.join(OUTPUT_DIR, `${name}-actual.png`), image);
    throw new Error(
      `missing golden ${path.relative(process.cwd(), goldenFile)}; the rendered image is in ` +
        `${path.relative(process.cwd(), OUTPUT_DIR)}/${name}-actual.png. Look at it, then run \`npm run goldens\`.`,
    );
  }
  const golden = readPng(goldenFile);
  if (golden.width !== image.width || golden.height !== image.height) {
    writePng(path.join(OUTPUT_DIR, `${name}-actual.png`), image);
    throw new Error(`${name}: size ${image.width}×${image.height}, golden is ${golden.width}×${golden.height}`);
  }
  const { differing, diff } = compareImages(image, golden);
  const budget = Math.floor(image.width * image.height * DIFF_BUDGET);
  if (differing > budget) {
    writePng(path.join(OUTPUT_DIR, `${name}-actual.png`), image);
    writePng(path.join(OUTPUT_DIR, `${name}-expected.png`), golden);
    writePng(path.join(OUTPUT_DIR, `${name}-diff.png`), diff);
    throw new Error(
      `${name}: ${differing} pixels differ from the golden (budget ${budget}, threshold ${PIXEL_THRESHOLD}); ` +
        `see ${path.relative(process.cwd(), OUTPUT_DIR)}/${name}-{actual,expected,diff}.png`,
    );
  }
}
