// `npm run bench`, the scene rows: the Gaussian at 40² and 400² under flat, Gouraud and
// Phong (ms/frame and PSNR against the float64 reference), and a ~100k-triangle mesh over a glass
// floor, full frame against the scene pass alone (the reflection's overhead). In linear light
// (color-space srgb, the default), with one row as stored (none) against its own reference. Writes
// bench/scenes.md; BENCH_SMOKE=1 runs one small row so the pipeline cannot rot.
import { writeFileSync } from 'node:fs';
import { test, expect } from '../tests/e2e/fixtures';
import { renderScene, compareImages, type ReferenceImage } from '../src/reference';
import { defaultFrameState } from '../tests/unit/helpers/frame-state';
import type { ColorSpace, FrameState, Shading } from '../src/frame/types';
import { BENCH_SCENES } from './scenes';
import { summary, shuffled } from './stats';
import type { Scene } from './bench-page';
import type { Knobs } from './configs';

const SMOKE = process.env.BENCH_SMOKE === '1';
const SIZE: Scene = SMOKE ? { width: 160, height: 90, time: 0 } : { width: 640, height: 360, time: 0 };
const SPP_AXIS = SMOKE ? 1 : 4;
const REPETITIONS = SMOKE ? 1 : 5;
const FRAMES = SMOKE ? 2 : 6;
const WARMUP = SMOKE ? 0 : 2;
const SHADINGS: readonly Shading[] = ['flat', 'gouraud', 'phong'];

type Page = import('@playwright/test').Page;
interface SceneBench {
  bench: {
    sceneTime(i: number, shading: Shading, size: Scene, mode: 'final' | 'scene', frames: number, warmup: number, knobs: Partial<Knobs>): Promise<number>;
    scenePixels(i: number, shading: Shading, size: Scene, knobs: Partial<Knobs>): Promise<{ width: number; height: number; data: string }>;
  };
}

/** A row: the defaults (tessellation 'auto'), or the full-detail reflection a numeric tessellation draws. */
interface Variant { label: string; knobs: Partial<Knobs> }
const AUTO: Variant = { label: '', knobs: {} };
const FULL_REFLECTION: Variant = { label: ', tessellation 64 (full-detail reflection)', knobs: { tessellation: 64 } };
const AS_STORED: Variant = { label: ', color-space none', knobs: { colorSpace: 'none' } };
const spaceOf = (v: Variant): ColorSpace => v.knobs.colorSpace ?? 'srgb';

function reference(i: number, colorSpace: ColorSpace): ReferenceImage {
  const b = BENCH_SCENES[i];
  const view: FrameState = defaultFrameState({
    width: SIZE.width, height: SIZE.height, spin: 0, cameraPosition: b.view.cameraPosition, yaw: b.view.yaw, pitch: b.view.pitch, colorSpace,
  });
  return renderScene(b.scene, view, null, { samplesPerAxis: SPP_AXIS });
}

async function time(page: Page, i: number, shading: Shading, mode: 'final' | 'scene', v: Variant): Promise<number> {
  return page.evaluate(([i, shading, size, mode, frames, warmup, knobs]) =>
    (window as unknown as SceneBench).bench.sceneTime(i, shading, size, mode, frames, warmup, knobs), [i, shading, SIZE, mode, FRAMES, WARMUP, v.knobs] as const);
}

test('bench: scenes beyond the default one', async ({ page }) => {
  test.setTimeout(30 * 60_000);
  await page.goto('/bench/page.html');
  await page.waitForFunction(() => 'bench' in window);
  const indices = SMOKE ? [0] : BENCH_SCENES.map((_, i) => i);
  const shadings = SMOKE ? (['phong'] as const) : SHADINGS;
  // Scenes with glass also get the full-detail reflection in Phong: what the clustered one saves and costs.
  const rows = indices.flatMap((i) => [
    ...shadings.map((shading) => ({ i, shading, v: AUTO })),
    ...(BENCH_SCENES[i].scene.glass && !SMOKE ? [{ i, shading: 'phong' as Shading, v: FULL_REFLECTION }] : []),
    // The smallest scene also as stored (the course's convention), so the two spaces' costs and figures sit side by side.
    ...(i === 0 ? [{ i, shading: 'phong' as Shading, v: AS_STORED }] : []),
  ]);
  const key = (r: { i: number; shading: Shading; v: Variant }, mode: string) => `${r.i}|${r.shading}|${r.v.label}|${mode}`;
  const jobs = rows.flatMap((r) => (['final', 'scene'] as const).map((mode) => ({ ...r, mode })));
  const ms = new Map<string, number[]>();
  for (let rep = 0; rep < REPETITIONS; rep++) {
    for (const j of shuffled(jobs, 77 + rep)) {
      const k = key(j, j.mode);
      ms.set(k, [...(ms.get(k) ?? []), await time(page, j.i, j.shading, j.mode, j.v)]);
    }
  }
  const lines = [
    '# Bench: scenes beyond the default one', '',
    `${SIZE.width}×${SIZE.height}, default knobs (samples 4, reflection-scale 1, tessellation auto: the reflection of a dense mesh from a clustered copy) but for shading and where the row says; ${REPETITIONS} repetitions × ${FRAMES} frames, shuffled; ` +
      `PSNR against the float64 reference (renderScene) at ${SPP_AXIS ** 2} spp, per-pixel Phong: the ideal each shading mode approximates. ` +
      'Every row in linear light (color-space srgb, the default) against the srgb reference, but the one marked color-space none (values as stored) against the none reference. ' +
      'dark: pixels whose reference, as displayed, is below 32/255 in every channel (also counted in their own region; "—" where there are none).', '',
    '| scene | triangles | shading | ms/frame median [IQR] | scene pass alone, ms | full ÷ scene-only | PSNR dB all / objects / glass / edges / dark | max err |',
    '|---|---|---|---|---|---|---|---|',
  ];
  const references = new Map<string, ReferenceImage>();
  const f1 = (x: number) => (Number.isFinite(x) ? x.toFixed(1) : '—');
  for (const r of rows) {
    const { i, shading, v } = r;
    const b = BENCH_SCENES[i];
    const refKey = `${i}|${spaceOf(v)}`;
    if (!references.has(refKey)) references.set(refKey, reference(i, spaceOf(v)));
    const ref = references.get(refKey)!;
    {
      const full = summary(ms.get(key(r, 'final'))!);
      const sceneOnly = summary(ms.get(key(r, 'scene'))!);
      const px = await page.evaluate(([i, shading, size, knobs]) => (window as unknown as SceneBench).bench.scenePixels(i, shading, size, knobs), [i, shading, SIZE, v.knobs] as const);
      const c = compareImages(ref, new Uint8Array(Buffer.from(px.data, 'base64')));
      expect(Number.isFinite(c.psnr.all), `${b.name} ${shading} PSNR`).toBe(true);
      lines.push(`| ${b.name} | ${b.triangles.toLocaleString('en')} | ${shading}${v.label} | ${full.median.toFixed(2)} [${full.iqr.toFixed(2)}] | ${sceneOnly.median.toFixed(2)} | ` +
        `${(full.median / sceneOnly.median).toFixed(2)}× | ${(['all', 'objects', 'glass', 'edges', 'dark'] as const).map((g) => f1(c.psnr[g])).join(' / ')} | ${c.maxError.toFixed(0)} |`);
    }
  }
  const md = lines.join('\n') + '\n';
  console.log('\n' + md);
  if (!SMOKE) writeFileSync(new URL('./scenes.md', import.meta.url), md);
});
