// The scene value from attributes and children: with no children it is the default
// scene exactly; children's objects and lights replace the defaults; "0 0" removes the glass.
import { describe, expect, it } from 'vitest';
import { composeScene, sceneSpins, type SceneInputs } from '../../src/element/compose-scene';
import { defaultAttributes } from '../../src/element/attributes';
import { defaultScene, DEFAULT_LIGHT } from '../../src/scene/default-scene';
import type { SceneObject } from '../../src/scene/scene';
import { pbrMaterial } from './helpers/pbr-scenes';

const inputs = (over: Partial<SceneInputs> = {}): SceneInputs => ({ ...defaultAttributes(), spin: 0.8, ...over });

describe('composeScene', () => {
  it('gives a scene with a glTF material the studio at environment-intensity; none with environment="none"; a scene without one is left as it was', () => {
    const base = defaultScene(0.75, 0.8).objects[0];
    const gltf: SceneObject = { ...base, material: { ...base.material, pbr: pbrMaterial() } };
    expect(composeScene(inputs({ environmentIntensity: 2.5 }), { objects: [gltf], lights: null }).environment).toEqual({ kind: 'studio', intensity: 2.5 });
    expect(composeScene(inputs({ environment: 'none' }), { objects: [gltf], lights: null }).environment).toBeUndefined();
    expect('environment' in composeScene(inputs(), { objects: [base], lights: null })).toBe(false);
  });

  it('environment="url": the image once it is in, the lights alone while it loads, the studio after it failed; never without a glTF material', () => {
    const base = defaultScene(0.75, 0.8).objects[0];
    const gltf: SceneObject = { ...base, material: { ...base.material, pbr: pbrMaterial() } };
    const image = { width: 2, height: 1, rgb: new Float32Array(6) }, url = 'https://example.test/sky.hdr';
    const env = (environment: Parameters<typeof composeScene>[1]['environment'], objects = [gltf]) =>
      composeScene(inputs({ environment: 'sky.hdr', environmentIntensity: 3 }), { objects, lights: null, environment }).environment;
    expect(env({ url, image })).toEqual({ kind: 'image', intensity: 3, url, image });
    expect(env(null)).toBeUndefined();
    expect(env(undefined)).toBeUndefined();
    expect(env('neutral')).toEqual({ kind: 'studio', intensity: 3 });
    expect(env({ url, image }, [base])).toBeUndefined();
    expect(env('neutral', [base])).toBeUndefined();
  });

  it('is the default scene with the default attributes and no children', () => {
    expect(composeScene(inputs({ cubeDistance: 0.5, spin: 0.3 }), { objects: null, lights: null })).toEqual(defaultScene(0.5, 0.3));
  });

  it('replaces the default objects and light by the children\'s, even by none', () => {
    const object = defaultScene(0, 0).objects[1] as SceneObject;
    const light = { ...DEFAULT_LIGHT, kind: 'point' as const, vector: [1, 2, 3] as const };
    const s = composeScene(inputs(), { objects: [object], lights: [light] });
    expect(s.objects).toEqual([object]);
    expect(s.lights).toEqual([light]);
    // A <glass-object> whose model is still loading contributes nothing, and still replaces the defaults.
    expect(composeScene(inputs(), { objects: [], lights: null }).objects).toEqual([]);
  });

  it('takes the glass and background from the attributes; a zero side means no glass', () => {
    const s = composeScene(inputs({ glassCenter: [0, 0, 0], glassNormal: [0, 1, 0], glassSize: [6, 6], background: [1, 0, 0] }), { objects: null, lights: null });
    expect(s.glass).toEqual({ center: [0, 0, 0], normal: [0, 1, 0], size: [6, 6] });
    expect(s.background).toEqual([1, 0, 0]);
    expect(composeScene(inputs({ glassSize: [0, 0] }), { objects: null, lights: null }).glass).toBeNull();
    expect(composeScene(inputs({ glassSize: [3, 0] }), { objects: null, lights: null }).glass).toBeNull();
  });

  it('spins only where the default cube is: spin is its alone (docs/knobs.md#idle-elements)', () => {
    const none = { objects: null, lights: null };
    expect(sceneSpins(composeScene(inputs({ spin: 0.8 }), none)), 'default scene, spin 0.8').toBe(true);
    expect(sceneSpins(composeScene(inputs({ spin: 0 }), none)), 'default scene, spin 0').toBe(false);
    const sphere = defaultScene(0, 0).objects[1] as SceneObject;
    expect(sceneSpins(composeScene(inputs({ spin: 0.8 }), { objects: [sphere], lights: null })), 'children, spin 0.8').toBe(false);
    expect(sceneSpins(composeScene(inputs({ spin: 0.8 }), { objects: [], lights: null })), 'a child still loading').toBe(false);
  });
});
