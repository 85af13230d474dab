// Whole-image properties of the reference: the mirror identity, clear glass, clipping, regions, extremes, speed.
import { describe, expect, it } from 'vitest';
import {
  renderReference, REGION_BACKGROUND, REGION_CUBE, REGION_EDGE, REGION_GLASS, REGION_SPHERE,
  type ReferenceImage, type ReferenceState,
} from '../../src/reference';
import { projectToPixels } from './helpers/math';
import { defaultFrameState } from './helpers/frame-state';

const STATE: ReferenceState = defaultFrameState({
  width: 320, height: 180, spin: 0, cubeDistance: 2.5, cameraPosition: [2, 2, 6], yaw: -109.4, pitch: -6.3, colorSpace: 'none',
});
const DEFAULT_VIEW: ReferenceState = defaultFrameState({ width: 320, height: 180, time: 1.25, colorSpace: 'none' });

/** Pixels where red exceeds green: the cube (albedo 0.8, 0.3, 0.3), never the grey background or green sphere. */
function cubeMask(img: ReferenceImage): Uint8Array {
  const m = new Uint8Array(img.width * img.height);
  for (let i = 0; i < m.length; i++) m[i] = img.rgb[3 * i] > img.rgb[3 * i + 1] + 1e-9 ? 1 : 0;
  return m;
}

const project = projectToPixels;

describe('the mirror identity', () => {
  it('the reflection pass shows the cube exactly where a cube mirrored to z = −d is seen directly', () => {
    // spin 0: the cube is symmetric under z → −z, so its mirror image is the same cube at −d.
    const reflected = cubeMask(renderReference({ ...STATE, view: 'reflection' }));
    const mirrored = cubeMask(renderReference({ ...STATE, view: 'scene', cubeDistance: -2.5 }));
    let count = 0, differ = 0, sx = 0, sy = 0;
    for (let i = 0; i < reflected.length; i++) {
      count += reflected[i];
      differ += reflected[i] ^ mirrored[i];
      if (reflected[i]) { sx += (i % STATE.width) + 0.5; sy += Math.floor(i / STATE.width) + 0.5; }
    }
    expect(count).toBeGreaterThan(200);
    expect(differ).toBe(0);
    // Its centroid sits where the mirrored centre (−1, 1, −2.5) projects (perspective moves it < 1 px).
    const [px, py] = project(STATE, [-1, 1, -2.5]);
    expect(Math.hypot(sx / count - px, sy / count - py)).toBeLessThan(1);
  });

  it('the final image shows the reflection on the glass: removing the cube changes exactly those glass pixels', () => {
    const withCube = renderReference(STATE);
    const cubeGone = renderReference({ ...STATE, cubeDistance: -200 }); // beyond far, and behind the glass
    const reflected = cubeMask(renderReference({ ...STATE, view: 'reflection' }));
    let onGlass = 0;
    for (let i = 0; i < reflected.length; i++) {
      if (withCube.regions[i] !== REGION_GLASS) continue;
      const changed = [0, 1, 2].some((k) => withCube.rgb[3 * i + k] !== cubeGone.rgb[3 * i + k]);
      expect(changed, `pixel ${i}`).toBe(reflected[i] === 1);
      onGlass += reflected[i];
    }
    expect(onGlass).toBeGreaterThan(100);
  });

  it('transparency 1 with F = 0 (exact, ior 1) shows B unchanged: final = scene', () => {
    const clear = { ...DEFAULT_VIEW, width: 160, height: 90, transparency: 1, ior: 1 };
    const final = renderReference(clear);
    const scene = renderReference({ ...clear, view: 'scene' });
    let glass = 0, maxDiff = 0;
    for (let i = 0; i < final.regions.length; i++) glass += final.regions[i] === REGION_GLASS ? 1 : 0;
    for (let i = 0; i < final.rgb.length; i++) maxDiff = Math.max(maxDiff, Math.abs(final.rgb[i] - scene.rgb[i]));
    expect(glass).toBeGreaterThan(1000);
    expect(maxDiff).toBeLessThan(1e-12);
  });

  it('the reflection keeps only the eye\'s side: a cube behind the glass is not reflected, one crossing it is cut', () => {
    const behind = renderReference({ ...STATE, view: 'reflection', cubeDistance: -2.5 });
    expect(cubeMask(behind).reduce((a, b) => a + b, 0)).toBe(0);
    const whole = cubeMask(renderReference({ ...STATE, view: 'reflection', cubeDistance: 0.6 })).reduce((a, b) => a + b, 0);
    const cut = cubeMask(renderReference({ ...STATE, view: 'reflection', cubeDistance: 0.2 })).reduce((a, b) => a + b, 0);
    expect(whole).toBeGreaterThan(0);
    expect(cut).toBeGreaterThan(0);
    expect(cut).toBeLessThan(whole);
  });
});

const centre = (img: ReferenceImage): number[] => {
  const i = 3 * ((img.height >> 1) * img.width + (img.width >> 1));
  return [img.rgb[i], img.rgb[i + 1], img.rgb[i + 2]];
};

describe('depth range', () => {
  it('an object nearer than the near plane is clipped away (back faces culled): the camera sees through it', () => {
    // Eye 0.05 in front of the cube's +Z face (z = 3), looking at it: the face is at depth 0.05 < 0.1.
    const s: ReferenceState = { ...STATE, width: 9, height: 9, cameraPosition: [-1, 1, 3.05], yaw: -90, pitch: 0, view: 'scene' };
    expect(centre(renderReference(s))).toEqual([0.1, 0.1, 0.1]);
    expect(centre(renderReference({ ...s, cameraPosition: [-1, 1, 3.2] }))[0]).toBeGreaterThan(0.2);
  });

  it('beyond the far plane (100) nothing is drawn', () => {
    // The cube's +Z face (z = 3) at depth 100.1, then 99.9.
    const s: ReferenceState = { ...STATE, width: 9, height: 9, cameraPosition: [-1, 1, 103.1], yaw: -90, pitch: 0, view: 'scene' };
    expect(centre(renderReference(s))).toEqual([0.1, 0.1, 0.1]);
    expect(centre(renderReference({ ...s, cameraPosition: [-1, 1, 102.9] }))[0]).toBeGreaterThan(0.2);
  });
});

describe('regions', () => {
  it('the default view has every region, and supersampling puts silhouettes in the edge band', () => {
    const img = renderReference(DEFAULT_VIEW, { samplesPerAxis: 2 });
    const counts = [0, 0, 0, 0, 0];
    for (const r of img.regions) counts[r]++;
    for (const r of [REGION_BACKGROUND, REGION_CUBE, REGION_GLASS, REGION_EDGE]) expect(counts[r], `region ${r}`).toBeGreaterThan(50);
    // The sphere is only seen through the glass here: glass pixels. Without the glass it is its own region.
    expect(counts[REGION_SPHERE]).toBe(0);
    expect(renderReference({ ...DEFAULT_VIEW, view: 'scene' }).regions.filter((r) => r === REGION_SPHERE).length).toBeGreaterThan(50);
    // Every pixel whose colour differs from all its neighbours' by a silhouette's contrast is edge.
    for (let y = 1; y < img.height - 1; y++) {
      for (let x = 1; x < img.width - 1; x++) {
        const i = y * img.width + x;
        if (img.regions[i] !== REGION_CUBE) continue;
        for (const j of [i - 1, i + 1, i - img.width, i + img.width]) expect(img.regions[j], `neighbour of cube pixel ${x},${y}`).not.toBe(REGION_BACKGROUND);
      }
    }
  });
});

describe('robustness at the extremes (docs/rendering.md#numerical-stability)', () => {
  const extremes: [string, Partial<ReferenceState>][] = [
    ['eye on the glass plane', { cameraPosition: [0, 1, 0], yaw: -90 }],
    ['eye 1e-7 in front', { cameraPosition: [0, 1, 1e-7], yaw: -90 }],
    ['eye 1e-7 behind', { cameraPosition: [0, 1, -1e-7], yaw: 90 }],
    ['89.99° incidence', { cameraPosition: [0, 1, 0.5], yaw: -0.01 }],
    ['far away', { cameraPosition: [1e6, 1e6, 1e6], yaw: -135, pitch: -35 }],
    ['cube crossing the glass', { cubeDistance: 0, spin: 1, time: 0.4 }],
    ['looking straight down', { pitch: -89.9 }],
    ['ior 10, transparency 0, classic', { ior: 10, transparency: 0, fresnel: 'classic' }],
    ['ior 1, transparency 1, schlick', { ior: 1, transparency: 1, fresnel: 'schlick' }],
    ['fov 179', { fov: 179 }],
    ['fov 1', { fov: 1 }],
  ];
  for (const [name, patch] of extremes) {
    it(`${name}: finite colours in [0, 1] for every view`, () => {
      for (const view of ['final', 'scene', 'reflection', 'fresnel'] as const) {
        const img = renderReference({ ...STATE, width: 24, height: 16, ...patch, view }, { samplesPerAxis: 2 });
        for (const c of img.rgb) expect(c >= 0 && c <= 1, `${view}: ${c}`).toBe(true);
      }
    });
  }

  it('0×0 and 1×1 images', () => {
    expect(renderReference({ ...STATE, width: 0, height: 0 }).rgba.length).toBe(0);
    expect(renderReference({ ...STATE, width: 1, height: 1 }).rgba.length).toBe(4);
  });

  it('refuses the tiled "passes" view with a prefixed error', () => {
    expect(() => renderReference({ ...STATE, view: 'passes' })).toThrow(/^glass-plane-scene:/);
  });
});
