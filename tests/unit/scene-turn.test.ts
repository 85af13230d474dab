// The trackball's turn travels in the frame state (FrameState.turn), not in a new scene value
// (a turn builds nothing): the frame setup that both renderers share composes it as one matrix before each
// model matrix (turnMatrix). It must give what the turned scene value gives (rotateScene: each
// object's position and Euler rotation rewritten, as the page's `scene` and the reference see it)
// to rounding, in matrices, light vectors, the course camera's depth range, and pixels.
import { describe, expect, it } from 'vitest';
import { quat } from 'gl-matrix';
import { FrameSetup } from '../../src/frame/frame-setup';
import { CourseProjection } from '../../src/frame/course-projection';
import type { FrameState } from '../../src/frame/types';
import { SoftwareRenderer } from '../../src/software';
import { courseBasis, type CourseCamera } from '../../src/math/course-camera';
import { courseSceneRange } from '../../src/scene/course-depth';
import { defaultScene } from '../../src/scene/default-scene';
import { boundsCenter, rotateScene } from '../../src/scene/group-rotation';
import type { SceneTurn } from '../../src/scene/turn';
import type { Light, Scene } from '../../src/scene/scene';
import { expectClose } from './helpers/math';
import { defaultFrameState } from './helpers/frame-state';
import { differingPixels } from './helpers/pixel-diff';

const STATE: FrameState = defaultFrameState({ width: 48, height: 27, time: 0.7, colorSpace: 'none', samples: 0 });

/** The default scene (a spinning cube before the glass, a sphere behind it), both turned, with a point light after the directional one. */
function content(): Scene {
  const base = defaultScene(0.75, 0.8);
  const point: Light = { kind: 'point', vector: [1, 3, 2], ambient: [0.1, 0.1, 0.1], diffuse: [0.6, 0.5, 0.4], specular: [0.3, 0.3, 0.3] };
  // Rotations of their own, so that the turn composes with them.
  const rotations: [number, number, number][] = [[20, -35, 50], [5, 80, -120]];
  const objects = base.objects.map((o, i) => ({ ...o, transform: { ...o.transform, rotation: rotations[i] } }));
  return { ...base, objects, lights: [base.lights[0], point] };
}

const q64 = (axis: [number, number, number], deg: number) => {
  const q = new Float64Array([0, 0, 0, 1]) as unknown as quat;
  const n = Math.hypot(...axis);
  return quat.setAxisAngle(q, [axis[0] / n, axis[1] / n, axis[2] / n], (deg * Math.PI) / 180);
};
const NONE = new Float64Array([0, 0, 0, 1]) as unknown as quat;
const CENTER = boundsCenter(content().objects, [0, 0, 0]);

const TURNS: [string, SceneTurn][] = [
  ['objects only', { objects: q64([0.3, 1, -0.2], 37), light: NONE, center: CENTER }],
  ['the light only', { objects: NONE, light: q64([1, 0.5, 0], -64), center: CENTER }],
  ['both', { objects: q64([-1, 0.2, 0.4], 121), light: q64([0, 1, 1], 23), center: CENTER }],
];

function setupOf(state: FrameState, scene: Scene): FrameSetup {
  const s = new FrameSetup(new CourseProjection());
  s.update(state, scene);
  return s;
}

/** Near the objects, looking down −Z: near and far come from the objects, which the turn moves. */
function courseCamera(): CourseCamera {
  const basis = courseBasis([0, 0, -1], [0, 1, 0]);
  if (typeof basis === 'string') throw new Error(basis);
  return { c: [0, 1, 3], ...basis, d: 1, hx: 0.6, hy: 0.4 };
}

describe('FrameState.turn against the turned scene value', () => {
  for (const [name, turn] of TURNS) {
    it(`${name}: the frame setup's model matrices, bounds and light vectors agree to 1e-12`, () => {
      const scene = content();
      const byState = setupOf({ ...STATE, turn }, scene);
      const byValue = setupOf(STATE, rotateScene(scene, turn.objects, turn.light));
      const unturned = setupOf(STATE, scene);
      let moved = 0;
      for (let i = 0; i < scene.objects.length; i++) {
        expectClose(byState.objects[i].model, byValue.objects[i].model);
        expectClose(byState.objects[i].center, byValue.objects[i].center);
        expect(byState.objects[i].radius).toBe(byValue.objects[i].radius);
        moved += Math.max(...byState.objects[i].model.map((x, k) => Math.abs(x - unturned.objects[i].model[k])));
      }
      expectClose(byState.lightWorld, byValue.lightWorld);
      expectClose(byState.lightsMirrored.vectors, byValue.lightsMirrored.vectors, 1e-6); // float32
      moved += Math.max(...byState.lightWorld.map((x, k) => Math.abs(x - unturned.lightWorld[k])));
      expect(moved, 'the turn moved something').toBeGreaterThan(0.1);
    });
  }

  it('the CPU renderer draws the same pixels, to rounding, in every view', () => {
    const scene = content();
    const [, turn] = TURNS[2];
    const renderer = new SoftwareRenderer();
    for (const view of ['final', 'reflection', 'scene'] as const) {
      // Copies: the renderer draws every frame into the same buffer.
      const byState = renderer.render(scene, { ...STATE, view, turn }).slice();
      const byValue = renderer.render(rotateScene(scene, turn.objects, turn.light), { ...STATE, view }).slice();
      const plain = renderer.render(scene, { ...STATE, view }).slice();
      const differing = differingPixels(byState, byValue), unturned = differingPixels(byState, plain);
      // Measured: no pixel differs in any view (48×27). A float32 entry rounding the other way
      // could flip one pixel by a level; none does here, and the bound says so.
      expect(differing, `${view}: pixels that differ`).toBe(0);
      // Measured: the turn changes 296 (final), 50 (reflection) and 264 (scene) pixels.
      expect(unturned, `${view}: pixels the turn changed`).toBeGreaterThan(40);
    }
  });

  it('a course camera: the depth range with the turn is the turned value\'s, and a new turn is not served from the cache', () => {
    const scene = content();
    const cam = courseCamera();
    const [, a] = TURNS[0], [, b] = TURNS[2];
    const range = (turn: SceneTurn | null) => { const r = courseSceneRange(cam, scene, 0.7, turn); return [r.near, r.far, Number(r.behind)]; };
    for (const turn of [a, b]) {
      const v = courseSceneRange(cam, rotateScene(scene, turn.objects, turn.light), 0.7);
      // The model matrices there are float32 (mat4.create()): rounding at 1e-7 of the depths.
      expectClose(range(turn), [v.near, v.far, Number(v.behind)], 1e-6);
    }
    // One setup, the same scene and clock, the turn changed in place (as the trackball does).
    const live = { objects: Float64Array.from(a.objects) as unknown as quat, light: NONE, center: CENTER };
    const setup = new FrameSetup(new CourseProjection());
    setup.update({ ...STATE, courseCamera: cam, turn: live }, scene);
    const first = { ...setup.courseRange! };
    quat.copy(live.objects, b.objects);
    setup.update({ ...STATE, courseCamera: cam, turn: live }, scene);
    expect([first.near, first.far, Number(first.behind)]).toEqual(range(a));
    expect([setup.courseRange!.near, setup.courseRange!.far, Number(setup.courseRange!.behind)]).toEqual(range(b));
    expect(Math.abs(first.near - setup.courseRange!.near), 'the two turns give different ranges').toBeGreaterThan(0.1);
  });
});
