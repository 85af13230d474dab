// Refinement at rest in the software renderer (docs/refinement.md): a still view of 1 + side² frames ends as the
// side × side supersampled picture, and is closer to the float64 reference than its first frame by far.
import { describe, expect, it } from 'vitest';
import { compareImages, renderScene } from '../../src/reference';
import { defaultScene } from '../../src/scene/default-scene';
import { SoftwareRenderer } from '../../src/software';
import { defaultFrameState } from './helpers/frame-state';

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
