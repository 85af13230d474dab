// Refinement at rest in the software renderer (docs/refinement.md): a still view of 1 + side² frames ends as the
// side × side supersampled picture, and is closer to the float64 reference than its first frame by far.
import { describe, expect, it } from 'vitest';
import { compareImages, renderScene } from '../../src/reference';
import { defaultScene } from '../../src/scene/default-scene';
import { SoftwareRenderer } from '../../src/software';
import { defaultFrameState } from './helpers/frame-state';
import { roughFloorScene, ROUGH_FLOOR_VIEW } from '../../bench/rough-scene';

const scene = defaultScene(0.75, 0.8);
const state = defaultFrameState({ width: 160, height: 90, time: 1.25, samples: 0 });

/** The picture after each of `frames` refinement frames, by frame. */
function refine(frames: number, renderer = new SoftwareRenderer()): Uint8ClampedArray[] {
  const out: Uint8ClampedArray[] = [];
  for (let k = 1; k <= frames; k++) out.push(renderer.render(scene, { ...state, refinement: k, refinementFrames: frames }).slice());
  return out;
}

describe('refinement in the software renderer', () => {
  it('after 1 + 3² frames the picture is the 3 × 3 supersampled one; frame 1 is the frame drawn alone', () => {
    const frames = refine(10);
    const ssaa = new SoftwareRenderer({ samplesPerAxis: 3 }).render(scene, state);
    let differ = 0, most = 0;
    for (let i = 0; i < ssaa.length; i++) {
      const d = Math.abs(frames[9][i] - ssaa[i]);
      if (d > 1) differ++;
      most = Math.max(most, d);
    }
    // Measured: 121 bytes of 57,600 differ, by at most 8 levels (edges whose samples the two grids round to different
    // fixed-point positions: the moved projection against the finer grid).
    expect(differ, `${differ} bytes differ, the most by ${most}`).toBeLessThan(300);
    expect(Array.from(frames[0])).toEqual(Array.from(new SoftwareRenderer().render(scene, state)));
  });

  it('against the reference (8 × 8): each stage of the still view closer than the frame alone, the last by 11 dB', () => {
    const ref = renderScene(scene, state, null, { samplesPerAxis: 8 });
    const figures = refine(10).map((px) => compareImages(ref, px).psnr);
    console.log(`refinement, 10 frames, PSNR all by frame: ${figures.map((p) => p.all.toFixed(1)).join(' ')}`);
    // Measured: all 40.2 (frame 1) … 51.6 (frame 10); objects 42.4 … 54.1; edges 31.6 … 44.6.
    expect(figures[9].all).toBeGreaterThan(figures[0].all + 11);
    expect(figures[9].objects).toBeGreaterThan(53);
    expect(figures[9].edges).toBeGreaterThan(43.5);
    for (let k = 1; k < 10; k++) expect(figures[k].all, `frame ${k + 1}`).toBeGreaterThan(figures[0].all - 0.5);
  });
});

describe('rough glass at rest in the software renderer (docs/refinement.md#rough-glass)', () => {
  it('the bench floor at roughness 0.3, ior 10: ten frames take the glass 4.5 dB closer to the Monte Carlo reference', () => {
    const v = ROUGH_FLOOR_VIEW, floor = roughFloorScene();
    const rough = defaultFrameState({
      width: 160, height: 90, spin: 0, transparency: 0.5, ior: 10, roughness: 0.3, samples: 0,
      cameraPosition: v.cameraPosition, yaw: v.yaw, pitch: v.pitch,
    });
    const ref = renderScene(floor, rough, null, { samplesPerAxis: 3, microfacetSamples: 256 });
    const renderer = new SoftwareRenderer();
    const glass: number[] = [];
    for (let k = 1; k <= 10; k++) glass.push(compareImages(ref, renderer.render(floor, { ...rough, refinement: k, refinementFrames: 10 })).psnr.glass);
    console.log(`rough glass at rest, 10 frames, PSNR glass by frame: ${glass.map((p) => p.toFixed(1)).join(' ')}`);
    // Measured: 46.1 alone … 50.8 after ten; with the pixel moved but each ring's samples where they are alone, 46.5: the
    // samples' places in their sectors (gatherJitter) are what converges.
    expect(glass[9]).toBeGreaterThan(glass[0] + 4.5);
    expect(glass[9]).toBeGreaterThan(50.3);
  });
});
