// Supersampling convergence of the reference: 16, 64 and 256 spp agree away from edges (docs/knobs.md#measuring-accuracy).
import { describe, expect, it } from 'vitest';
import { renderReference, REGION_EDGE, type ReferenceImage, type ReferenceState } from '../../src/reference';
import { defaultFrameState } from './helpers/frame-state';

/** The element's default view (cube, its reflection, the sphere through the glass), shrunk to 64×36. */
const DEFAULT_VIEW: ReferenceState = defaultFrameState({ width: 64, height: 36, time: 1.25, colorSpace: 'none' });
const OBLIQUE_VIEW: ReferenceState = { ...DEFAULT_VIEW, cameraPosition: [2.5, 1.6, 5], yaw: -115, pitch: -8 };

interface Difference { max: number; mean: number; pixels: number }

/** Channel differences in 8-bit levels over pixels that no image puts in the edge band. */
function difference(a: ReferenceImage, b: ReferenceImage, all: readonly ReferenceImage[]): Difference {
  let max = 0, sum = 0, pixels = 0;
  for (let i = 0; i < a.width * a.height; i++) {
    if (all.some((img) => img.regions[i] === REGION_EDGE)) continue;
    pixels++;
    for (let c = 0; c < 3; c++) {
      const d = Math.abs(a.rgb[3 * i + c] - b.rgb[3 * i + c]) * 255;
      max = Math.max(max, d);
      sum += d;
    }
  }
  return { max, mean: sum / (3 * pixels), pixels };
}

function renders(state: ReferenceState): ReferenceImage[] {
  return [4, 8, 16].map((samplesPerAxis) => renderReference(state, { samplesPerAxis }));
}

describe('16 vs 64 vs 256 spp, away from edges', () => {
  // The one feature that converges slowly off the edges is the sphere's specular highlight
  // (shininess 32), about one pixel wide at 64×36. Stratum-centre sampling integrates a smooth
  // feature with an O(1/n²) error, so the bounds are per sample count: 16 spp within 0.75 of a
  // level of 256 spp, 64 spp within 0.15, and the first at least 3× the second (5× for an exact
  // C/n² law). In the first design's view the highlight was ~7 px of sphere away, through the glass at
  // an angle that dimmed it, and every pair sat under 0.1; the default view (docs/element.md#the-default-view) sees
  // the sphere 2.4× closer through the glass: 0.61 and 0.13 at the highlight, < 0.02 elsewhere.
  for (const [name, state] of [['default', DEFAULT_VIEW], ['oblique', OBLIQUE_VIEW]] as const) {
    it(`${name} view, final image: 16 and 64 spp converge on 256 as 1/n², the mean within 0.01 of a level`, () => {
      const [s16, s64, s256] = renders(state);
      const all = [s16, s64, s256];
      const d16 = difference(s16, s256, all), d64 = difference(s64, s256, all);
      for (const d of [d16, d64, difference(s16, s64, all)]) {
        expect(d.pixels).toBeGreaterThan(0.5 * 64 * 36);
        expect(d.mean).toBeLessThan(0.01);
      }
      expect(d16.max, '16 vs 256 spp').toBeLessThan(0.75);
      expect(d64.max, '64 vs 256 spp').toBeLessThan(0.15);
      expect(d16.max / d64.max, 'second-order convergence').toBeGreaterThan(3);
    });
  }

  it('scene pass alone: the mean differs by < 0.1 level; the max is set by the 1-px specular highlight and falls as 1/n²', () => {
    // Without the glass in front the highlight is undimmed: 1.34 levels at 16 spp, 0.29 at 64.
    const [s16, s64, s256] = renders({ ...DEFAULT_VIEW, view: 'scene' });
    const all = [s16, s64, s256];
    const d16 = difference(s16, s256, all), d64 = difference(s64, s256, all);
    for (const d of [d16, d64, difference(s16, s64, all)]) expect(d.mean).toBeLessThan(0.1);
    expect(d16.max).toBeLessThan(1.5);
    expect(d64.max).toBeLessThan(0.35);
    // Second order: with error C/n², |e₄ − e₁₆| / |e₈ − e₁₆| = (1/16 − 1/256)/(1/64 − 1/256) = 5.
    expect(d16.max / d64.max).toBeGreaterThan(3);
  });

  it('edges are where the remaining difference lives: including the band, 16 vs 256 spp differ by levels', () => {
    const [s16, , s256] = renders(DEFAULT_VIEW);
    let max = 0;
    for (let i = 0; i < s16.rgb.length; i++) max = Math.max(max, Math.abs(s16.rgb[i] - s256.rgb[i]) * 255);
    expect(max).toBeGreaterThan(1);
  });
});
