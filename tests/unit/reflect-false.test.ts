// An object kept out of the reflection (`<glass-object reflect="false">`, SceneObject.reflected,
// docs/scene-model.md#glass-object): in the software renderer and the float64 reference, the
// glass reflects the scene as if the object were not there, and everything else draws it as before.
import { describe, expect, it } from 'vitest';
import { REGION_GLASS, renderScene } from '../../src/reference';
import { SoftwareRenderer } from '../../src/software';
import { defaultScene } from '../../src/scene/default-scene';
import type { Scene } from '../../src/scene/scene';
import type { FrameState } from '../../src/frame/types';
import { defaultFrameState } from './helpers/frame-state';

const base = defaultScene(0.75, 0);
const [cube, sphere] = base.objects;
/** The default scene with the cube (on the viewer's side, reflected by default) kept out of the reflection. */
const unreflected: Scene = { ...base, objects: [{ ...cube, reflected: false }, sphere] };
const withoutCube: Scene = { ...base, objects: [sphere] };
const STATE: FrameState = defaultFrameState({ width: 48, height: 27, spin: 0, time: 0 });

const software = (scene: Scene, state: FrameState) => Buffer.from(new SoftwareRenderer().render(scene, state));
const reference = (scene: Scene, state: FrameState) => Buffer.from(renderScene(scene, state, null, { samplesPerAxis: 1 }).rgb.buffer);

describe('reflected: false', () => {
  for (const [name, draw] of [['software renderer', software], ['reference', reference]] as const) {
    it(`${name}: the reflection is the scene's without the object; the scene itself still shows it`, () => {
      const reflection = (s: Scene) => draw(s, { ...STATE, view: 'reflection' });
      expect(reflection(unreflected).equals(reflection(withoutCube))).toBe(true);
      expect(reflection(base).equals(reflection(withoutCube)), 'the cube is in the reflection by default').toBe(false);
      const sceneView = (s: Scene) => draw(s, { ...STATE, view: 'scene' });
      expect(sceneView(unreflected).equals(sceneView(base))).toBe(true);
    });
  }

  it('rough glass, both renderers: every glass pixel is the one drawn without the object', () => {
    const rough: FrameState = { ...STATE, roughness: 0.3 };
    const ref = (s: Scene) => renderScene(s, rough, null, { samplesPerAxis: 1, microfacetSamples: 4 });
    const a = ref(unreflected), b = ref(withoutCube), withCube = ref(base);
    let glass = 0, moved = 0;
    for (let p = 0; p < a.regions.length; p++) {
      if (a.regions[p] !== REGION_GLASS) continue;
      glass++;
      for (let k = 0; k < 3; k++) expect(a.rgb[3 * p + k], `reference pixel ${p}`).toBe(b.rgb[3 * p + k]);
      if (withCube.rgb[3 * p] !== b.rgb[3 * p]) moved++;
    }
    expect(glass).toBeGreaterThan(200);
    expect(moved, 'the cube is in the rough reflection by default').toBeGreaterThan(20);
    const sw = (s: Scene) => new SoftwareRenderer().render(s, rough);
    const sa = sw(unreflected), sb = sw(withoutCube);
    for (let p = 0; p < a.regions.length; p++) {
      if (a.regions[p] === REGION_GLASS) for (let k = 0; k < 3; k++) expect(sa[4 * p + k], `software pixel ${p}`).toBe(sb[4 * p + k]);
    }
  });
});
