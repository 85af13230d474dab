// glTF materials under the scene's lights (docs/pbr.md#the-scenes-lights), in the float64 reference and the software
// renderer: a box face head-on to the camera and to a directional light (N = V = L = H, so D = 1/(πα²),
// Vis = 1/4, F = F0) whose centre pixel is worked out by hand for each material below; the grid
// of spheres against the reference (every region within MARGIN_DB of what was measured); the
// frame's shading does not apply (lit per pixel always).
import { describe, expect, it } from 'vitest';
import { compareImages, renderScene, type ImageComparison } from '../../src/reference';
import { SoftwareRenderer } from '../../src/software';
import type { Scene, Vec3 } from '../../src/scene/scene';
import { defaultFrameState } from './helpers/frame-state';
import { instrumented } from './helpers/collections';
import { BOX_STATE as STATE, HAND_CASES as CASES, boxScene, pbrMaterial, sphereGrid } from './helpers/pbr-scenes';

const CENTRE = 16 * 33 + 16;

describe('the base colour texture', () => {
  it('multiplies the base colour, and so a metal\'s F0: a 1×1 image (0.5, 0.25, 1) on a white metal of roughness ½', () => {
    // Head-on, 0.2·F0/(4α²) with F0 = the textured base and 4α² = ¼: (0.4, 0.2, 0.8).
    const url = 'https://example.com/one.png';
    const images = new Map([[url, { width: 1, height: 1, data: new Uint8ClampedArray([Math.round(0.5 * 255), Math.round(0.25 * 255), 255, 255]) }]]);
    const tex = [Math.round(0.5 * 255) / 255, Math.round(0.25 * 255) / 255, 1];
    const scene = boxScene(pbrMaterial({ baseColor: [1, 1, 1, 1], metallic: 1, roughness: 0.5 }));
    const textured: Scene = { ...scene, objects: [{ ...scene.objects[0], material: { ...scene.objects[0].material, texture: { kind: 'image', url } } }] };
    const ref = renderScene(textured, STATE, images, { samplesPerAxis: 1 }).rgb;
    const soft = new SoftwareRenderer({ samplesPerAxis: 1 }).render(textured, STATE, images);
    tex.forEach((t, k) => {
      expect(ref[3 * CENTRE + k], `reference channel ${k}`).toBeCloseTo(0.8 * t, 12);
      expect(soft[4 * CENTRE + k], `software channel ${k}`).toBe(Math.round(0.8 * t * 255));
    });
  });
});

describe('a glTF material head-on to a directional light, worked by hand', () => {
  it('is lit per pixel whatever the frame\'s shading (a box lit by a near point light: Blinn-Phong\'s gouraud and flat differ)', () => {
    const near = (pbr: boolean): Scene => {
      const s = boxScene(pbrMaterial({ baseColor: [0.5, 0.5, 0.5, 1], metallic: 1, roughness: 0.4 }));
      const o = s.objects[0];
      const material = pbr ? o.material : { ...o.material, pbr: undefined, specular: [0.5, 0.5, 0.5] as Vec3, shininess: 20 };
      return { ...s, objects: [{ ...o, material }], lights: [{ ...s.lights[0], kind: 'point', vector: [0.3, 0.2, 1.2] }] };
    };
    for (const pbr of [true, false]) {
      const draw = (shading: 'phong' | 'gouraud' | 'flat') => Buffer.from(new SoftwareRenderer({ samplesPerAxis: 1 }).render(near(pbr), { ...STATE, shading }));
      const phong = draw('phong');
      expect(draw('gouraud').equals(phong), `gouraud, ${pbr ? 'glTF' : 'Blinn-Phong'}`).toBe(pbr);
      expect(draw('flat').equals(phong), `flat, ${pbr ? 'glTF' : 'Blinn-Phong'}`).toBe(pbr);
    }
  });

  for (const c of CASES) {
    it(`${c.name}: the reference to 1e-12, the software renderer to the 8-bit level`, () => {
      const scene = boxScene(pbrMaterial(c.pbr), c.emissive, c.light);
      const ref = renderScene(scene, STATE, null, { samplesPerAxis: 1 }).rgb;
      const soft = new SoftwareRenderer({ samplesPerAxis: 1 }).render(scene, STATE);
      c.want.forEach((w, k) => {
        expect(ref[3 * CENTRE + k], `reference channel ${k}`).toBeCloseTo(Math.min(w, 1), 12);
        expect(soft[4 * CENTRE + k], `software channel ${k}`).toBe(Math.round(Math.min(w, 1) * 255));
      });
    });
  }
});

/** Each bound is the figure measured less this: the 8-bit rounding of both images caps a region near 54–59 dB. */
const MARGIN_DB = 2;
const GRID_STATE = defaultFrameState({ width: 160, height: 90, cameraPosition: [0, 1.5, 3.3], yaw: -90, pitch: -8, colorSpace: 'srgb', time: 0, spin: 0, samples: 0 });
const SAMPLES = 4;

const line = (c: ImageComparison): string => {
  const p = c.psnr;
  return `all ${p.all.toFixed(1)}, objects ${p.objects.toFixed(1)}, glass ${p.glass.toFixed(1)}, edges ${p.edges.toFixed(1)}, dark ${p.dark.toFixed(1)} dB`;
};

describe('the grid of spheres (metallic × roughness) over a glass floor', () => {
  // Under StrykerJS a frame of either renderer takes seconds: the box worked by hand judges the mutants.
  it.skipIf(instrumented)(`the software renderer against the reference (${SAMPLES}×${SAMPLES} samples): every region within ${MARGIN_DB} dB of its figure`, () => {
    const scene = sphereGrid();
    const ref = renderScene(scene, GRID_STATE, null, { samplesPerAxis: SAMPLES });
    const cmp = compareImages(ref, new SoftwareRenderer({ samplesPerAxis: SAMPLES }).render(scene, GRID_STATE));
    console.log(`PBR sphere grid, software against the reference: ${line(cmp)}`);
    const measured = { all: 45.4, objects: 50.7, glass: 57.9, edges: 41.0, dark: 47.6 };
    for (const [region, figure] of Object.entries(measured) as [keyof typeof measured, number][]) {
      expect(cmp.psnr[region], `${region}: ${line(cmp)}`).toBeGreaterThanOrEqual(figure - MARGIN_DB);
    }
  });

  it('is lit per pixel whatever the frame\'s shading: gouraud draws what phong draws', () => {
    const scene = sphereGrid();
    const draw = (shading: 'phong' | 'gouraud') => Buffer.from(new SoftwareRenderer({ samplesPerAxis: 1 }).render(scene, { ...GRID_STATE, shading }));
    expect(draw('gouraud').equals(draw('phong'))).toBe(true);
  });
});
