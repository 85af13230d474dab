// The software renderer's pixels held to the bit (docs/software-renderer.md#frame-to-frame-caches): its speed-ups must not move a pixel.
// Each frame's RGBA8 digest against tests/unit/software-baseline.json, recorded from the renderer
// as it stood before them: software-reference.test.ts's scenes at 160×90 with 1 and 2×2 samples
// in both colour spaces, the default scene in each debug view, Fresnel model, shading mode,
// supersampled, rough, and at 640×360 as the cube turns. And a renderer that draws a run of
// frames, keeping what it may from one to the next (glass-cache.ts), gives each the pixels a fresh
// renderer gives it, whatever changes between them. A change that is meant to move pixels
// rewrites the file (UPDATE_BASELINE=1 npx vitest run tests/unit/software-baseline.test.ts) and
// says why in its commit. Digests are of V8's arithmetic (Math.pow, Math.log2): a new Node may
// move a last bit, which the reference comparisons tell apart from a defect.
import { createHash } from 'node:crypto';
import { readFileSync, writeFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { DEFAULT_CUBE_DISTANCE } from '../../src/element/attributes';
import type { FrameState } from '../../src/frame/types';
import { defaultScene } from '../../src/scene/default-scene';
import type { Scene } from '../../src/scene/scene';
import { SoftwareRenderer } from '../../src/software';
import { CASES, IMAGES, STATE } from './helpers/software-cases';
import { defaultFrameState } from './helpers/frame-state';
import { differingBytes } from './helpers/pixel-diff';
import { DEFAULT_GLASS, DEFAULT_LIGHT } from '../../src/scene/default-scene';

const FILE = new URL('./software-baseline.json', import.meta.url);
const UPDATE = process.env.UPDATE_BASELINE === '1';
const stored: Record<string, string> = UPDATE ? {} : JSON.parse(readFileSync(FILE, 'utf8'));
const recorded: Record<string, string> = {};

interface Frame { name: string; scene: Scene; state: FrameState; samplesPerAxis?: number }

const frames: Frame[] = [];
for (const c of CASES) {
  for (const colorSpace of ['none', 'srgb'] as const) {
    for (const samples of [0, 4]) {
      frames.push({ name: `${c.name}, ${colorSpace}, samples ${samples}`, scene: c.scene, state: { ...STATE, ...c.state, colorSpace, samples } });
    }
  }
}
const scene = defaultScene(0.75, 0.8);
const variants: [string, Partial<FrameState>, number?][] = [
  ['view scene', { view: 'scene' }], ['view reflection', { view: 'reflection' }], ['view fresnel', { view: 'fresnel' }],
  ['view passes', { view: 'passes', width: 161, height: 91 }],
  ['schlick, T 0.2', { fresnel: 'schlick', transparency: 0.2 }], ['classic, T 0.9', { fresnel: 'classic', transparency: 0.9 }],
  ['gouraud', { shading: 'gouraud' }], ['flat', { shading: 'flat' }], ['flat, samples 4', { shading: 'flat', samples: 4 }],
  ['supersampled 2×2', {}, 2], ['rough 0.3', { roughness: 0.3, samples: 4 }], ['rough 0.3, samples 0', { roughness: 0.3 }],
];
for (const [name, over, n] of variants) {
  for (const colorSpace of ['none', 'srgb'] as const) {
    frames.push({ name: `default scene, ${name}, ${colorSpace}`, scene, state: { ...STATE, ...over, colorSpace }, samplesPerAxis: n });
  }
}
// The bench's frame (bench/software-node.ts): 640×360, the cube turning.
const big = defaultScene(DEFAULT_CUBE_DISTANCE, 0.8);
for (const time of [0.4, 2.9]) {
  for (const [samples, colorSpace] of [[0, 'srgb'], [4, 'srgb'], [0, 'none'], [4, 'none']] as const) {
    frames.push({
      name: `default scene 640×360, t ${time}, samples ${samples}, ${colorSpace}`, scene: big,
      state: defaultFrameState({ time, colorSpace, samples }),
    });
  }
}

describe('software renderer: pixels bit for bit as recorded (software-baseline.json)', () => {
  const renderers = new Map<number, SoftwareRenderer>();
  for (const f of frames) {
    it(f.name, () => {
      const n = f.samplesPerAxis ?? 1;
      if (!renderers.has(n)) renderers.set(n, new SoftwareRenderer({ samplesPerAxis: n }));
      const pixels = renderers.get(n)!.render(f.scene, f.state, IMAGES);
      const digest = createHash('sha256').update(pixels).digest('hex').slice(0, 24);
      recorded[f.name] = digest;
      if (!UPDATE) expect(digest, `${f.name}: not recorded, or its pixels moved`).toBe(stored[f.name]);
    });
  }
  it('records the digests (UPDATE_BASELINE=1) or holds every one that is stored', () => {
    if (UPDATE) writeFileSync(FILE, `${JSON.stringify(recorded, null, 2)}\n`);
    else expect(Object.keys(stored).sort()).toEqual(frames.map((f) => f.name).sort());
  });
});

/**
 * Frames drawn one after another by one renderer: the cube turning with all else still (what the
 * caches keep: the glass's F and texel, the sphere's colours), then one change at a time, each
 * drawn twice (a cache keeps entries from a key's second frame) and kept by the frames after it —
 * each of what the glass and the objects depend on, and what they do not. Each frame must be what
 * a fresh renderer draws.
 */
describe('software renderer: a run of frames, each as a fresh renderer draws it', () => {
  const moved: Scene = { ...scene, glass: { ...DEFAULT_GLASS, center: [DEFAULT_GLASS.center[0] + 0.25, DEFAULT_GLASS.center[1], 0] } };
  const turned: Scene = { ...scene, glass: { ...DEFAULT_GLASS, normal: [0.1, 1, 0.05] } };
  const [cube, sphere] = scene.objects;
  // The sphere changed one thing at a time, each change kept by the next.
  const sphereSteps: [string, Scene][] = [];
  let changed = sphere;
  const change = (name: string, over: Partial<typeof sphere>) => {
    changed = { ...changed, ...over };
    sphereSteps.push([name, { ...scene, objects: [cube, changed] }]);
  };
  const lit: Scene = { ...scene, lights: [{ ...DEFAULT_LIGHT, diffuse: [0.6, 0.5, 0.4] }] };
  const twoLights: Scene = { ...scene, lights: [DEFAULT_LIGHT, { kind: 'point', vector: [1, 2.5, 2], ambient: [0, 0, 0], diffuse: [0.5, 0.4, 0.3], specular: [0.6, 0.6, 0.6] }] };
  const p = sphere.transform.position;
  change('sphere diffuse', { material: { ...sphere.material, diffuse: [0.3, 0.6, 0.9] } });
  change('sphere shininess', { material: { ...changed.material, shininess: 8 } });
  change('sphere moved', { transform: { ...sphere.transform, position: [p[0] + 0.05, p[1], p[2]] } });
  change('sphere turned', { transform: { ...changed.transform, rotation: [0, 10, 0] } });
  change('sphere triplanar', { material: { ...changed.material, mapping: 'triplanar' } });
  change('sphere bounds', { bounds: { ...sphere.bounds, radius: sphere.bounds.radius * 2 } });
  change('sphere image', { material: { ...changed.material, texture: { kind: 'image', url: 'checker.png' } } });
  const steps: [string, Partial<FrameState>, Scene?][] = [
    ['t 0.5', { time: 0.5 }], ['t 0.6', { time: 0.6 }], ['t 0.7', { time: 0.7 }],
    ['camera turned', { yaw: STATE.yaw + 0.5 }], ['camera moved', { cameraPosition: [STATE.cameraPosition[0], STATE.cameraPosition[1] + 0.01, STATE.cameraPosition[2]] }],
    ['fov', { fov: 61 }], ['ior 1.33', { ior: 1.33 }], ['schlick', { fresnel: 'schlick' }], ['classic', { fresnel: 'classic' }],
    ['transparency 0.2', { transparency: 0.2 }], ['srgb', { colorSpace: 'srgb' }], ['samples 4', { samples: 4 }], ['t 0.9', { time: 0.9 }],
    ['view fresnel', { view: 'fresnel' }], ['view final again', { view: 'final' }],
    ['161×91', { width: 161, height: 91 }], ['glass moved', {}, moved], ['glass turned', {}, turned], ['default glass', {}, scene],
    ['orthographic', { projection: 'orthographic' }], ['rough 0.3', { roughness: 0.3 }], ['polished again', { roughness: 0 }],
    ['samples 0', { samples: 0 }], ['t 1.1', { time: 1.1 }],
    ['light', {}, lit], ['two lights', {}, twoLights], ['default light', {}, scene],
    // Fixed tessellation: with 'auto' the sphere's mesh follows its bounds and position.
    ['tessellation', { tessellation: 24 }],
    ...sphereSteps.map(([name, sc]): [string, Partial<FrameState>, Scene] => [name, {}, sc]),
    ['default sphere', {}, scene], ['gouraud', { shading: 'gouraud' }], ['flat', { shading: 'flat' }], ['phong', { shading: 'phong' }],
    ['tessellation 8', { tessellation: 8 }], ['samples 4 again', { samples: 4 }], ['orthographic off', { projection: 'perspective' }],
  ];
  it(`${steps.length} frames, each as a fresh renderer draws it`, () => {
    const one = new SoftwareRenderer();
    let state: FrameState = STATE;
    for (const [name, over, sc] of steps) {
      for (const frame of ['first', 'second']) {
        state = { ...state, ...over, time: state.time + 0.05 };
        const got = one.render(sc ?? scene, state, IMAGES).slice();
        const want = new SoftwareRenderer().render(sc ?? scene, state, IMAGES);
        const differing = differingBytes(want, got);
        expect(differing, `${name}, ${frame} frame: bytes that differ from a fresh renderer's`).toBe(0);
      }
    }
  });
});
