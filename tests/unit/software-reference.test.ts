// The software renderer (docs/software-renderer.md) against the float64 reference, at 160×90 with 4×4 samples per
// pixel on both sides (the same sample positions): PSNR per scene and per region, each bound
// MARGIN_DB below the figure measured (both renderers are deterministic: the figures repeat to
// the last digit run after run), figures printed. The reference shares fresnel.ts, mapping.ts and
// the other modules named in their headers with this renderer: those are tied to hand-computed
// values in their own tests, which this comparison cannot replace.
import { describe, expect, it } from 'vitest';
import { compareImages, renderScene, type ImageComparison } from '../../src/reference';
import { defaultScene } from '../../src/scene/default-scene';
import type { FrameState } from '../../src/frame/types';
import { SoftwareRenderer } from '../../src/software';
import { CASES, IMAGES, STATE, type Case, type Figures } from './helpers/software-cases';

const SAMPLES = 4;

/**
 * Each bound is the figure measured less this. Rounding both images to 8 bits alone caps a
 * region near 54–59 dB, so the figures sit there and a real defect drops one by far more (the hand
 * mutations once in scripts/mutations/software.mjs, retired: StrykerJS mutates src/ now): T and
 * 1 − T swapped takes the glass from 58.6 to 26.1 dB at T = 0.2; kt and 1 − kt swapped takes the
 * transparent spheres' objects from 57.5 to 31.8; the exact model's F where Schlick's is asked
 * takes the fresnel view's glass from 58.5 to 35.9 (and the final image's glass at T = 0.2 from
 * 58.6 to 56.1). Regions count too, since a small object drawn wrong hardly moves the whole
 * image's figure.
 */
const MARGIN_DB = 2;

/** Every region's figure within MARGIN_DB of what was measured (an empty region stays empty). */
function expectFigures(cmp: ImageComparison, measured: Partial<Figures>, line: string): void {
  for (const [region, figure] of Object.entries(measured) as [keyof Figures, number | null][]) {
    const got = cmp.psnr[region];
    if (figure === null) expect(got, `${line}: ${region} empty`).toBeNaN();
    else expect(got, `${line}: ${region}, measured ${figure} dB`).toBeGreaterThanOrEqual(figure - MARGIN_DB);
  }
}

const describe2 = (c: ImageComparison): string => {
  const p = c.psnr;
  return `PSNR ${p.all.toFixed(1)} dB (objects ${p.objects.toFixed(1)}, glass ${p.glass.toFixed(1)}, `
    + `background ${p.background.toFixed(1)}, edges ${p.edges.toFixed(1)}, dark ${p.dark.toFixed(1)} over ${c.pixels.dark} px), `
    + `max error ${c.maxError.toFixed(0)}`;
};

describe(`software renderer against the reference (${STATE.width}×${STATE.height}, ${SAMPLES}×${SAMPLES} samples)`, () => {
  const renderer = new SoftwareRenderer({ samplesPerAxis: SAMPLES });
  for (const c of CASES) {
    it(`${c.name}: every region within ${MARGIN_DB} dB of its measured figure`, () => {
      const state = { ...STATE, ...c.state };
      const ref = renderScene(c.scene, state, IMAGES, { samplesPerAxis: SAMPLES });
      const cmp = compareImages(ref, renderer.render(c.scene, state, IMAGES));
      const line = `${c.name}: ${describe2(cmp)}`;
      console.log(line);
      expectFigures(cmp, c.measured, line);
    });
  }

  /**
   * The default scene in each debug view, and its glass with each Fresnel model at two
   * transparencies where T and 1 − T differ (at the default T = 0.5 a swap of the two cannot
   * show). The fresnel view shows F itself: another model's F moves it by several levels where
   * the final image, whose glass mostly reflects the dark background, moves by less than one.
   */
  const VIEWS: { view: FrameState['view']; fresnel: FrameState['fresnel']; transparency: number; measured: Figures }[] = [
    { view: 'scene', fresnel: 'exact', transparency: 0.5, measured: { all: 52.7, objects: 52.3, glass: null, background: 54.2, edges: 46.8 } },
    { view: 'reflection', fresnel: 'exact', transparency: 0.5, measured: { all: 53.7, objects: 57.2, glass: null, background: 54.2, edges: 47.3 } },
    // F is 0 off the glass in both: objects and background are exact (Infinity).
    { view: 'fresnel', fresnel: 'exact', transparency: 0.5, measured: { all: 61.4, objects: Infinity, glass: 59.0, background: Infinity, edges: 63.6 } },
    { view: 'fresnel', fresnel: 'schlick', transparency: 0.5, measured: { all: 60.9, objects: Infinity, glass: 58.5, background: Infinity, edges: 63.8 } },
    { view: 'fresnel', fresnel: 'classic', transparency: 0.5, measured: { all: 61.3, objects: Infinity, glass: 58.9, background: Infinity, edges: 63.7 } },
    { view: 'final', fresnel: 'exact', transparency: 0.2, measured: { all: 55.4, objects: 58.0, glass: 58.6, background: 54.2, edges: 52.3 } },
    { view: 'final', fresnel: 'exact', transparency: 0.9, measured: { all: 54.2, objects: 58.0, glass: 57.1, background: 54.2, edges: 49.7 } },
    { view: 'final', fresnel: 'schlick', transparency: 0.2, measured: { all: 55.4, objects: 58.0, glass: 58.6, background: 54.2, edges: 52.3 } },
    { view: 'final', fresnel: 'schlick', transparency: 0.9, measured: { all: 54.2, objects: 58.0, glass: 57.0, background: 54.2, edges: 49.6 } },
    { view: 'final', fresnel: 'classic', transparency: 0.2, measured: { all: 54.5, objects: 58.0, glass: 57.4, background: 54.2, edges: 50.1 } },
    { view: 'final', fresnel: 'classic', transparency: 0.9, measured: { all: 53.6, objects: 58.0, glass: 55.9, background: 54.2, edges: 48.9 } },
  ];
  for (const v of VIEWS) {
    it(`default scene, view ${v.view}, fresnel ${v.fresnel}, transparency ${v.transparency}: every region within ${MARGIN_DB} dB`, () => {
      const scene = defaultScene(0.75, 0.8);
      const state = { ...STATE, view: v.view, fresnel: v.fresnel, transparency: v.transparency };
      const cmp = compareImages(renderScene(scene, state, null, { samplesPerAxis: SAMPLES }), renderer.render(scene, state));
      const line = `default scene, view ${v.view}, fresnel ${v.fresnel}, T ${v.transparency}: ${describe2(cmp)}`;
      console.log(line);
      expectFigures(cmp, v.measured, line);
    });
  }

  it('one sample per pixel: edges alias against the supersampled reference, the rest does not', () => {
    const one = new SoftwareRenderer();
    const scene = defaultScene(0.75, 0.8);
    const cmp = compareImages(renderScene(scene, STATE, null, { samplesPerAxis: SAMPLES }), one.render(scene, STATE));
    const line = `default scene at 1 sample per pixel: ${describe2(cmp)}`;
    console.log(line);
    expectFigures(cmp, { all: 44.8, objects: 47.1, glass: 52.3, background: 54.2, edges: 36.4 }, line);
  });
});

/**
 * Linear light (docs/colour.md#srgb): the same comparison with colorSpace 'srgb' on both sides (textures and
 * background decoded, light summed and averaged linearly, one encode), the dark region included
 * (the background, 0.1, is dark). srgb textures are read anisotropically (mip-texture.ts), as the
 * WebGL renderer reads them; with isotropic reads these figures were lower — default scene 52.8
 * dB (objects 55.9, glass 56.2, edges 46.8), textured mesh 56.0 (glass 57.6, edges 54.5),
 * transparent spheres 55.4 (objects 55.6, glass 56.6), Schlick at T = 0.2 53.4 (glass 56.5, edges
 * 48.0): the edge band crosses the glass and a cube face seen at a slant, whose texture one
 * isotropic level blurred. The fresnel view's figures are 'none''s to the digit: F is unencoded
 * on both sides. Defects drop a region by far more than the margin (the retired hand mutations
 * S13–S20 of scripts/mutations/software.mjs): the procedural texture not decoded takes the
 * default scene's objects from 56.4 to 20.7 dB; the background not decoded, its background from
 * 54.2 to 12.1; samples encoded before the box filter, its objects to 39.2; an image not decoded,
 * the textured mesh's objects from 58.8 to 17.6; colour held as 8-bit linear levels, the default
 * scene's objects to 51.1.
 */
describe(`software renderer against the reference in linear light (colorSpace srgb, ${STATE.width}×${STATE.height}, ${SAMPLES}×${SAMPLES} samples)`, () => {
  const renderer = new SoftwareRenderer({ samplesPerAxis: SAMPLES });
  const byName = (name: string): Case => CASES.find((c) => c.name === name)!;
  const SRGB_CASES: Case[] = [
    { name: 'default scene', scene: defaultScene(0.75, 0.8), measured: { all: 54.7, objects: 56.4, glass: 57.4, background: 54.2, edges: 50.7, dark: 54.2 } },
    { ...byName('textured mesh (image texture)'), measured: { all: 56.8, objects: 58.8, glass: 59.0, background: 54.2, edges: 57.1, dark: 54.2 } },
    { ...byName('half-transparent spheres in front of and across the glass'), measured: { all: 56.3, objects: 56.8, glass: 58.0, background: 54.2, edges: 54.4, dark: 54.2 } },
    {
      name: 'default scene, fresnel schlick, transparency 0.2', scene: defaultScene(0.75, 0.8), state: { fresnel: 'schlick', transparency: 0.2 },
      measured: { all: 55.9, objects: 56.4, glass: 58.5, background: 54.2, edges: 54.9, dark: 54.2 },
    },
    {
      name: 'default scene, view fresnel, fresnel schlick (F unencoded on both sides)', scene: defaultScene(0.75, 0.8), state: { view: 'fresnel', fresnel: 'schlick' },
      measured: { all: 60.9, objects: Infinity, glass: 58.5, background: Infinity, edges: 63.8, dark: 61.6 },
    },
  ];
  for (const c of SRGB_CASES) {
    it(`${c.name}: every region within ${MARGIN_DB} dB of its measured figure`, () => {
      const state: FrameState = { ...STATE, ...c.state, colorSpace: 'srgb' };
      const ref = renderScene(c.scene, state, IMAGES, { samplesPerAxis: SAMPLES });
      const cmp = compareImages(ref, renderer.render(c.scene, state, IMAGES));
      const line = `srgb, ${c.name}: ${describe2(cmp)}`;
      console.log(line);
      expectFigures(cmp, c.measured, line);
    });
  }

  /**
   * One sample per pixel, where a pixel's texture read has its whole footprint to cover: with
   * isotropic reads this measured 39.0 dB (objects 39.8, glass 45.0, edges 30.7, dark 52.5), the
   * floor's and the cube's slanted faces blurred to the level of the footprint's longest side.
   * Edges alias against the supersampled reference as with 'none'.
   */
  it('one sample per pixel: each pixel reads its texture over its whole footprint', () => {
    const scene = defaultScene(0.75, 0.8);
    const state: FrameState = { ...STATE, colorSpace: 'srgb' };
    const cmp = compareImages(renderScene(scene, state, null, { samplesPerAxis: SAMPLES }), new SoftwareRenderer().render(scene, state));
    const line = `srgb, default scene at 1 sample per pixel: ${describe2(cmp)}`;
    console.log(line);
    expectFigures(cmp, { all: 40.2, objects: 42.4, glass: 49.7, background: 54.2, edges: 31.5, dark: 52.9 }, line);
  });
});

describe('software renderer: the passes debug view', () => {
  it('tiles reflection | scene over fresnel | final like the WebGL renderer, every pixel written on an odd size', () => {
    const r = new SoftwareRenderer();
    const scene = defaultScene(0.75, 0.8);
    const state: FrameState = { ...STATE, width: 161, height: 91, view: 'passes' };
    const tiled = r.render(scene, state).slice();
    for (let i = 3; i < tiled.length; i += 4) expect(tiled[i]).toBe(255);
    // left 80, right 81; bottom 45, top 46 (top row first in the output).
    const quadrants: [FrameState['view'], number, number, number, number][] = [
      ['reflection', 0, 0, 80, 46], ['scene', 80, 0, 81, 46], ['fresnel', 0, 46, 80, 45], ['final', 80, 46, 81, 45],
    ];
    for (const [view, x, y, w, h] of quadrants) {
      const alone = r.render(scene, { ...state, view, width: w, height: h });
      let differing = 0;
      for (let row = 0; row < h; row++) {
        for (let col = 0; col < w * 4; col++) if (tiled[4 * ((y + row) * 161 + x) + col] !== alone[4 * row * w + col]) differing++;
      }
      expect(differing, `${view} tile`).toBe(0);
    }
    // Not four copies of one view.
    const a = r.render(scene, { ...state, view: 'reflection', width: 80, height: 46 }).slice();
    const b = r.render(scene, { ...state, view: 'final', width: 80, height: 46 });
    expect(a.some((v, i) => v !== b[i])).toBe(true);
  });
});
