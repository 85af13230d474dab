// Objects scaled unevenly or mirrored (docs/scene-model.md#glass-object): their bounds grow with the
// largest |scale|, so the reflection culls them only when wholly beyond the glass (a tall, thin
// post through a glass floor) and draws a clustered mesh as fine as its largest side needs
// (docs/rendering.md#what-is-skipped).
import { describe, expect, it } from 'vitest';
import { FrameSetup } from '../../src/frame/frame-setup';
import { Renderer } from '../../src/render/renderer';
import { SoftwareRenderer } from '../../src/software';
import { renderScene } from '../../src/reference';
import { defaultMaterial, DEFAULT_LIGHT } from '../../src/scene/default-scene';
import type { Scene, SceneObject, Vec3 } from '../../src/scene/scene';
import { fakeGl } from './helpers/fake-gl';
import { defaultFrameState } from './helpers/frame-state';
import { differingBytes } from './helpers/pixel-diff';

const FLOOR: Scene['glass'] = { center: [0, 0, 0], normal: [0, 1, 0], size: [8, 8] };
const object = (geometry: SceneObject['geometry'], position: Vec3, scale: Vec3, radius: number): SceneObject => ({
  geometry, transform: { position, rotation: [0, 0, 0], scale, spin: 0 },
  material: { ...defaultMaterial([0.9, 0.6, 0.2]), texture: { kind: 'none' } }, bounds: { center: [0, 0, 0], radius },
});
const sceneOf = (...objects: SceneObject[]): Scene => ({ glass: FLOOR, objects, lights: [DEFAULT_LIGHT], background: [0.1, 0.1, 0.1] });
/** A unit box made a post 4 tall and 0.5 thick, its centre 1 under the floor: its top 1 stands above. */
const POST = object({ kind: 'box', size: 1 }, [0, -1, 0], [0.5, 4, 0.5], Math.sqrt(3) / 2);
const VIEW = defaultFrameState({ width: 160, height: 90, spin: 0, cameraPosition: [0, 1.2, 4], yaw: -90, pitch: -10, view: 'reflection' });

describe('a scaled object\'s bounds', () => {
  it('the radius is the bounds\' times the largest |scale|, whichever axis and sign', () => {
    for (const scale of [[4, 0.5, 0.5], [0.5, 4, 0.5], [0.5, 0.5, 4], [0.5, -4, 0.5]] as Vec3[]) {
      const setup = new FrameSetup();
      setup.update(VIEW, sceneOf({ ...POST, transform: { ...POST.transform, scale } }));
      expect(setup.objects[0].radius, scale.join(' ')).toBeCloseTo(4 * Math.sqrt(3) / 2, 12);
    }
  });
});

describe('a tall, thin post through a glass floor', () => {
  // Its centre is 1 beyond the glass, its top 1 on the viewer's side: reflected, not culled.
  it('the reference reflects its top', () => {
    const with_ = renderScene(sceneOf(POST), VIEW).rgba, without = renderScene(sceneOf(), VIEW).rgba;
    expect(differingBytes(with_, without)).toBeGreaterThan(100);
  });

  it('the software renderer reflects its top as the reference does', () => {
    const ref = renderScene(sceneOf(POST), VIEW).rgba;
    const px = new SoftwareRenderer().render(sceneOf(POST), VIEW);
    const empty = new SoftwareRenderer().render(sceneOf(), VIEW);
    expect(differingBytes(px, empty)).toBeGreaterThan(100);
    let far = 0;
    for (let i = 0; i < px.length; i++) if (Math.abs(px[i] - ref[i]) > 24) far++;
    expect(far).toBeLessThan(60); // measured: the edges of an unsampled frame
  });

  it('the WebGL renderer draws it into the reflection', async () => {
    const r = new Renderer(fakeGl().gl);
    const state = { ...VIEW, view: 'final' as const };
    await r.load(sceneOf(POST), state);
    r.render(sceneOf(POST), state);
    expect(r.stats.triangles.reflection).toBe(12);
    r.dispose();
  });
});

describe('the reflection\'s level of detail for a scaled mesh', () => {
  const gaussian = (scale: Vec3) => object({ kind: 'gaussian', resolution: 200 }, [0, 0.5, 0], scale, 2.9);
  async function reflectionTriangles(scale: Vec3): Promise<number> {
    const r = new Renderer(fakeGl().gl), scene = sceneOf(gaussian(scale)), state = { ...VIEW, view: 'final' as const, width: 320, height: 180 };
    await r.load(scene, state);
    r.render(scene, state);
    const n = r.stats.triangles.reflection;
    r.dispose();
    return n;
  }

  it('grows with the scale: a larger copy is drawn from a finer grid', async () => {
    const one = await reflectionTriangles([1, 1, 1]), three = await reflectionTriangles([3, 3, 3]);
    expect(three).toBeGreaterThan(one);
  });

  it('follows the largest side whichever axis it is on', async () => {
    const uniform = await reflectionTriangles([3, 3, 3]);
    for (const scale of [[3, 1, 1], [1, 3, 1], [1, 1, 3], [1, -3, 1]] as Vec3[]) expect(await reflectionTriangles(scale), scale.join(' ')).toBe(uniform);
  });
});
