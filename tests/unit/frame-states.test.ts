// The element's FrameStates (src/element/frame-state.ts): tone-mapping="auto" decided by the scene (docs/pbr.md#in-the-frame),
// the other keywords and the exposure as parsed.
import { describe, expect, it } from 'vitest';
import { FrameStates, refineFrames } from '../../src/element/frame-state';
import { defaultAttributes, type SceneAttributes } from '../../src/element/attributes';
import { defaultScene } from '../../src/scene/default-scene';
import type { Scene } from '../../src/scene/scene';
import { pbrMaterial, withPbr } from './helpers/pbr-scenes';

const fill = (over: Partial<SceneAttributes>, scene: Scene | null) =>
  new FrameStates().fill({ ...defaultAttributes(), ...over }, 0, 64, 32, 0, scene);

describe('tone mapping in the frame state', () => {
  const plain = defaultScene(0.75, 0);
  const gltf: Scene = { ...plain, objects: [...plain.objects, { ...plain.objects[0], material: withPbr(pbrMaterial()) }] };

  it('auto: neutral with a glTF material, none without (or before any scene)', () => {
    expect(fill({}, gltf).toneMapping).toBe('neutral');
    expect(fill({}, plain).toneMapping).toBe('none');
    expect(fill({}, null).toneMapping).toBe('none');
  });

  it('a curve asked for is the curve, whatever the scene; the exposure as parsed', () => {
    for (const t of ['neutral', 'aces', 'none'] as const) {
      expect(fill({ toneMapping: t }, gltf).toneMapping).toBe(t);
      expect(fill({ toneMapping: t }, plain).toneMapping).toBe(t);
    }
    expect(fill({}, plain).exposure).toBe(1);
    expect(fill({ exposure: 2.5 }, plain).exposure).toBe(2.5);
  });
});

describe('the rest of the frame state', () => {
  it('every attribute the frame reads, as parsed; debug-view none is the final view', () => {
    const states = new FrameStates();
    const v: SceneAttributes = {
      ...defaultAttributes(), time: 2.5, cubeDistance: -1.25, transparency: 0.3, ior: 2.2, fresnel: 'classic', debugView: 'reflection',
      reflectionScale: 0.5, samples: 2, shading: 'flat', tessellation: 48, reflectionFormat: 'rgba16f', colorSpace: 'none',
      roughness: 0.4, roughnessQuality: 'high', toneMapping: 'aces', exposure: 3,
    };
    const s = states.fill(v, 1000, 320, 200, 0.6, null);
    expect({ ...s, cameraPosition: undefined, fov: undefined, yaw: undefined, pitch: undefined, projection: undefined, target: undefined }).toEqual({
      width: 320, height: 200, time: 2.5, spin: 0.6, cubeDistance: -1.25, transparency: 0.3, ior: 2.2, fresnel: 'classic', view: 'reflection',
      reflectionScale: 0.5, samples: 2, shading: 'flat', tessellation: 48, reflectionFormat: 'rgba16f', colorSpace: 'none',
      roughness: 0.4, roughnessQuality: 'high', toneMapping: 'aces', exposure: 3, refinement: 0, refinementFrames: 10,
      cameraPosition: undefined, fov: undefined, yaw: undefined, pitch: undefined, projection: undefined, target: undefined,
    });
    expect(s).toBe(states.current);
    expect(states.fill({ ...v, debugView: 'none' }, 0, 1, 1, 0).view).toBe('final');
    // Before any fill: the defaults a renderer could draw (the camera's part is the rig's).
    expect(new FrameStates().current).toMatchObject({
      width: 1, height: 1, time: 0, fresnel: 'exact', view: 'final', samples: 4, shading: 'phong', tessellation: 'auto',
      reflectionFormat: 'rgba8', colorSpace: 'srgb', projection: 'perspective', target: null, roughnessQuality: 'medium',
      toneMapping: 'none', exposure: 1, fov: 60, cameraPosition: [0, 0, 0],
    });
  });

  it('the live clock counts seconds from the first frame\'s timestamp; a fixed time wins', () => {
    const states = new FrameStates();
    const live = { ...defaultAttributes(), time: null };
    expect(states.fill(live, 500, 1, 1, 0).time).toBe(0);
    expect(states.fill(live, 2000, 1, 1, 0).time).toBe(1.5);
    expect(states.fill({ ...live, time: 7 }, 3000, 1, 1, 0).time).toBe(7);
    // A first frame at timestamp 0 starts the clock there.
    const zero = new FrameStates();
    zero.fill(live, 0, 1, 1, 0);
    expect(zero.fill(live, 250, 1, 1, 0).time).toBe(0.25);
  });

  it('drawn() keeps a copy of the last state, its camera position copied (the live pose moves on)', () => {
    const states = new FrameStates();
    expect(states.last).toBeNull();
    const s = states.fill(defaultAttributes(), 0, 10, 10, 0);
    const position: [number, number, number] = [1, 2, 3];
    s.cameraPosition = position;
    states.drawn(s);
    position[0] = 99;
    s.width = 77;
    expect(states.last).not.toBe(s);
    expect(states.last!.cameraPosition).toEqual([1, 2, 3]);
    expect(states.last!.width).toBe(10);
    const kept = states.last;
    states.drawn({ ...s, width: 5, cameraPosition: [4, 5, 6] });
    expect(states.last).toBe(kept);
    expect(states.last!.width).toBe(5);
    expect(states.last!.cameraPosition).toEqual([4, 5, 6]);
  });
});

describe('refinement in the frame state (docs/refinement.md#the-attribute)', () => {
  const at = (over: Partial<SceneAttributes>, refinement: number) =>
    new FrameStates().fill({ ...defaultAttributes(), ...over }, 0, 64, 32, 0, null, refinement);

  it('refine 0: every frame at `samples`, refining nothing', () => {
    for (const k of [0, 1, 2]) expect(at({ refine: 0, samples: 4 }, k).samples).toBe(4);
    expect(at({ refine: 0 }, 0).refinement).toBe(0);
    expect(at({ refine: 0 }, 0).refinementFrames).toBe(0);
  });

  it('refine N: moving and strata frames at one sample, the preview at `samples`; k and N travel in the state', () => {
    expect(at({ refine: 10, samples: 4 }, 0).samples).toBe(0);
    expect(at({ refine: 10, samples: 4 }, 1).samples).toBe(4);
    expect(at({ refine: 10, samples: 2 }, 1).samples).toBe(2);
    expect(at({ refine: 10, samples: 4 }, 2).samples).toBe(0);
    const s = at({ refine: 10 }, 7);
    expect([s.refinement, s.refinementFrames]).toEqual([7, 10]);
  });

  it('with color-space none or a debug view nothing refines: `samples` as set, and refineFrames is 0', () => {
    expect(at({ refine: 10, samples: 4, colorSpace: 'none' }, 0).samples).toBe(4);
    expect(at({ refine: 10, samples: 4, debugView: 'scene' }, 2).samples).toBe(4);
    expect(refineFrames({ ...defaultAttributes(), refine: 10 })).toBe(10);
    expect(refineFrames({ ...defaultAttributes(), refine: 10, colorSpace: 'none' })).toBe(0);
    expect(refineFrames({ ...defaultAttributes(), refine: 10, debugView: 'fresnel' })).toBe(0);
    expect(refineFrames(defaultAttributes())).toBe(10); // docs/refinement.md#the-attribute: the default
  });
});
