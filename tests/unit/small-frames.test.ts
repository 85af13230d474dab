// Both CPU renderers' small frames held to the bit (small-frames.json): the software renderer's
// RGBA8 and the float64 reference's RGB, regions and keys, at 32×18 for every case of
// software-reference.test.ts and the default scene in each view, Fresnel model, shading mode,
// projection, camera kind, colour space, samples and roughness. software-baseline.test.ts holds
// the software renderer's bigger frames; these are small enough that a generated mutant of either
// renderer (npm run test:mutations:folder -- software | reference) is judged in a fraction of a
// second. The accuracy of each renderer is judged elsewhere: the reference by hand-computed pixels
// (reference-pixels.test.ts, reference-rough.test.ts), the software renderer against it
// (software-reference.test.ts). A change meant to move pixels rewrites the file
// (UPDATE_BASELINE=1 npx vitest run tests/unit/small-frames.test.ts) and says why in its commit.
// Digests are of V8's arithmetic: a new Node may move a last bit (see software-baseline.test.ts).
import { createHash } from 'node:crypto';
import { readFileSync, writeFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import type { FrameState } from '../../src/frame/types';
import { DEFAULT_GLASS, DEFAULT_LIGHT, defaultScene } from '../../src/scene/default-scene';
import type { Scene } from '../../src/scene/scene';
import { SoftwareRenderer, putBand, renderBand, splitRows, type Band } from '../../src/software';
import { renderScene } from '../../src/reference';
import { CASES, IMAGES, STATE, courseCamera } from './helpers/software-cases';

const FILE = new URL('./small-frames.json', import.meta.url);
const UPDATE = process.env.UPDATE_BASELINE === '1';
const stored: Record<string, string> = UPDATE ? {} : JSON.parse(readFileSync(FILE, 'utf8'));
const recorded: Record<string, string> = {};

const SMALL: FrameState = { ...STATE, width: 32, height: 18 };

interface Frame { name: string; scene: Scene; state: FrameState; samplesPerAxis: number }

const frames: Frame[] = [];
for (const c of CASES) {
  for (const colorSpace of ['none', 'srgb'] as const) {
    frames.push({ name: `${c.name}, ${colorSpace}`, scene: c.scene, state: { ...SMALL, ...c.state, colorSpace }, samplesPerAxis: 1 });
  }
  frames.push({ name: `${c.name}, 2×2`, scene: c.scene, state: { ...SMALL, ...c.state, samples: 4 }, samplesPerAxis: 2 });
}
const scene = defaultScene(0.75, 0.8);
const variants: [string, Partial<FrameState>, number?][] = [
  ['view scene', { view: 'scene' }], ['view reflection', { view: 'reflection' }], ['view fresnel', { view: 'fresnel' }],
  ['view fresnel, srgb', { view: 'fresnel', colorSpace: 'srgb' }],
  ['schlick, T 0.2', { fresnel: 'schlick', transparency: 0.2 }], ['classic, T 0.9', { fresnel: 'classic', transparency: 0.9 }],
  ['ior 1.33', { ior: 1.33 }], ['gouraud', { shading: 'gouraud' }], ['flat', { shading: 'flat' }],
  ['course camera', { courseCamera: courseCamera() }],
  ['course camera mirrored', { courseCamera: { ...courseCamera(), hx: -0.6 } }],
  ['time 2.9', { time: 2.9 }], ['camera below the glass', { cameraPosition: [3.6, -2.4, 0.2], pitch: 30 }],
  ['rough 0.3', { roughness: 0.3 }], ['rough 0.6, srgb', { roughness: 0.6, colorSpace: 'srgb' }],
  ['rough 0.3, 2×2', { roughness: 0.3, samples: 4 }, 2], ['rough 0.3, orthographic', { roughness: 0.3, projection: 'orthographic' }],
];
for (const [name, over, n] of variants) {
  frames.push({ name: `default scene, ${name}`, scene, state: { ...SMALL, ...over }, samplesPerAxis: n ?? 1 });
}

const digest = (...arrays: ArrayBufferView[]) => {
  const hash = createHash('sha256');
  for (const a of arrays) hash.update(new Uint8Array(a.buffer, a.byteOffset, a.byteLength));
  return hash.digest('hex').slice(0, 24);
};

describe('small frames of both CPU renderers, bit for bit as recorded (small-frames.json)', () => {
  for (const f of frames) {
    it(`software: ${f.name}`, () => {
      const key = `software: ${f.name}`;
      recorded[key] = digest(new SoftwareRenderer({ samplesPerAxis: f.samplesPerAxis }).render(f.scene, f.state, IMAGES));
      if (!UPDATE) expect(recorded[key], `${key}: not recorded, or its pixels moved`).toBe(stored[key]);
    });
    it(`reference: ${f.name}`, () => {
      const key = `reference: ${f.name}`;
      // 16 microfacet normals per pixel for rough glass: enough to reach every branch of its Monte Carlo.
      const image = renderScene(f.scene, f.state, IMAGES, { samplesPerAxis: f.samplesPerAxis, microfacetSamples: 16 });
      recorded[key] = digest(image.rgb, image.rgba, image.regions, image.keys);
      if (!UPDATE) expect(recorded[key], `${key}: not recorded, or its pixels moved`).toBe(stored[key]);
    });
  }
  it('records the digests (UPDATE_BASELINE=1) or holds every one that is stored', () => {
    if (UPDATE) writeFileSync(FILE, `${JSON.stringify(recorded, null, 2)}\n`);
    else expect(Object.keys(stored).sort()).toEqual(frames.flatMap((f) => [`software: ${f.name}`, `reference: ${f.name}`]).sort());
  });
});

/**
 * One software renderer drawing a run of small frames, keeping what its caches may (glass-cache.ts,
 * object-cache.ts): each frame must be a fresh renderer's. Each step is drawn three times (a cache
 * keeps entries from a key's second frame and reads them from the third), time moving on.
 */
describe('small frames: a run of frames by one software renderer, each as a fresh renderer draws it', () => {
  const [cube, sphere] = scene.objects;
  const material = sphere.material;
  const steps: [string, Partial<FrameState>, Scene?][] = [
    ['start', {}], ['camera turned', { yaw: SMALL.yaw + 0.5 }], ['fov', { fov: 61 }], ['ior 1.33', { ior: 1.33 }],
    ['schlick', { fresnel: 'schlick' }], ['transparency 0.2', { transparency: 0.2 }], ['srgb', { colorSpace: 'srgb' }],
    ['samples 4', { samples: 4 }], ['view fresnel', { view: 'fresnel' }], ['view final', { view: 'final' }],
    ['33×19', { width: 33, height: 19 }], ['33×18', { height: 18 }],
    ['glass moved', {}, { ...scene, glass: { ...DEFAULT_GLASS, center: [DEFAULT_GLASS.center[0] + 0.25, DEFAULT_GLASS.center[1], 0] } }],
    ['glass turned', {}, { ...scene, glass: { ...DEFAULT_GLASS, normal: [0.1, 1, 0.05] } }], ['default glass', {}, scene],
    ['rough 0.3', { roughness: 0.3 }], ['polished', { roughness: 0 }], ['samples 0', { samples: 0 }],
    ['light', {}, { ...scene, lights: [{ ...DEFAULT_LIGHT, diffuse: [0.6, 0.5, 0.4] }] }], ['default light', {}, scene],
    ['sphere diffuse', {}, { ...scene, objects: [cube, { ...sphere, material: { ...material, diffuse: [0.3, 0.6, 0.9] } }] }],
    ['sphere moved', {}, { ...scene, objects: [cube, { ...sphere, transform: { ...sphere.transform, position: [0.05, 0, 0] } }] }],
    ['sphere image', {}, { ...scene, objects: [cube, { ...sphere, material: { ...material, texture: { kind: 'image', url: 'checker.png' } } }] }],
    ['default sphere', {}, scene], ['gouraud', { shading: 'gouraud' }], ['flat', { shading: 'flat' }], ['phong', { shading: 'phong' }],
    ['orthographic', { projection: 'orthographic' }],
  ];
  it(`${steps.length} steps, three frames each`, () => {
    const one = new SoftwareRenderer();
    let state: FrameState = { ...SMALL, spin: 0.3 };
    for (const [name, over, sc] of steps) {
      for (const frame of [1, 2, 3]) {
        state = { ...state, ...over, time: state.time + 0.05 };
        const got = one.render(sc ?? scene, state, IMAGES);
        const want = new SoftwareRenderer().render(sc ?? scene, state, IMAGES);
        expect(got.length, `${name}, frame ${frame}`).toBe(want.length);
        expect(Buffer.from(got).equals(Buffer.from(want)), `${name}, frame ${frame}: a fresh renderer's pixels`).toBe(true);
      }
    }
  });
});

/** Bands (bands.ts): every band's rows drawn by a renderer of its own and put together are the whole frame. */
describe('small frames in bands, each band by its own renderer, are the whole frame bit for bit', () => {
  const banded = (state: FrameState, bands: Band[], n: number, renderers = bands.map(() => new SoftwareRenderer({ samplesPerAxis: n }))) => {
    const frame = new Uint8ClampedArray(4 * state.width * state.height);
    bands.forEach((band, i) => putBand(frame, renderBand(renderers[i], scene, state, IMAGES, band), band, state.width));
    return Buffer.from(frame);
  };
  for (const [name, over, n] of [
    ['plain', {}, 1], ['samples 4', { samples: 4 }, 1], ['2×2, 33×19', { width: 33, height: 19 }, 2], ['rough 0.3', { roughness: 0.3 }, 1],
    ['course camera', { courseCamera: courseCamera() }, 1], ['view passes, 33×19', { view: 'passes', width: 33, height: 19 }, 1],
  ] as [string, Partial<FrameState>, number][]) {
    it(`${name}: 2 even bands, 4 uneven ones (one empty), one row each`, () => {
      const state: FrameState = { ...SMALL, ...over };
      const whole = Buffer.from(renderBand(new SoftwareRenderer({ samplesPerAxis: n }), scene, state, IMAGES, null));
      expect(whole.length).toBe(4 * state.width * state.height);
      expect(banded(state, splitRows(state.height, 2), n).equals(whole)).toBe(true);
      expect(banded(state, splitRows(state.height, 4, [1, 0.01, 3, 2]), n).equals(whole)).toBe(true);
      expect(banded(state, [{ top: 0, bottom: 5 }, { top: 5, bottom: 5 }, { top: 5, bottom: 11 }, { top: 11, bottom: state.height }], n).equals(whole)).toBe(true);
      if (state.roughness) return; // rough glass draws the whole frame for each band: a frame per row shows nothing more
      const rows = Array.from({ length: state.height }, (_, y) => ({ top: y, bottom: y + 1 }));
      const one = new SoftwareRenderer({ samplesPerAxis: n });
      expect(banded(state, rows, n, rows.map(() => one)).equals(whole)).toBe(true);
    });
  }
});

/** A run of sizes by one renderer (its caches sized for the largest): each frame a fresh renderer's. */
describe('small frames: a run of sizes by one software renderer', () => {
  const sizes: [number, number][] = [[32, 24], [32, 24], [32, 24], [32, 18], [32, 18], [24, 32], [24, 32], [32, 18], [32, 18], [40, 18], [40, 18]];
  for (const [label, over] of [['plain', {}], ['samples 4', { samples: 4 }], ['rough 0.3', { roughness: 0.3 }], ['course camera', { courseCamera: courseCamera() }]] as [string, Partial<FrameState>][]) {
    it(`${label}: every frame, a height alone changing among them, is a fresh renderer's`, () => {
      const live = new SoftwareRenderer();
      for (const [width, height] of sizes) {
        const state: FrameState = { ...SMALL, spin: 0, ...over, width, height };
        const got = Buffer.from(live.render(scene, state, IMAGES));
        expect(got.length, `${width}×${height}`).toBe(4 * width * height);
        expect(got.equals(Buffer.from(new SoftwareRenderer().render(scene, state, IMAGES))), `${width}×${height}`).toBe(true);
      }
    });
  }
});
