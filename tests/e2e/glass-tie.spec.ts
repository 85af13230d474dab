// A face lying in the glass plane ("a picture behind a glass wall"): the cube at
// cube-distance −0.5 with spin 0 has its front face exactly in the glass plane. The glass covers
// it — WebGL pulls the glass forward a hair (objects on the viewer's side further) and leaves
// what touches the glass out of the reflection — as the float64 reference draws it.
import { test, expect, mount, openPage, capture, type Attrs } from './fixtures';
import { renderReference, renderScene } from '../../src/reference';
import { defaultMaterial, defaultScene } from '../../src/scene/default-scene';
import type { Scene, SceneObject } from '../../src/scene/scene';
import { drawScene, openRendererPage } from './helpers/scene-json';
import type { FrameState } from '../../src/frame/types';
import { defaultFrameState } from '../unit/helpers/frame-state';
import { cameraAttrs } from './helpers/stability';

const SIZE = { width: 160, height: 90 };
// Head-on at the cube's front face (x ∈ [−1.5, −0.5], y ∈ [0.5, 1.5], z = 0) from 2.5 in front.
const EYE: [number, number, number] = [-1, 1, 2.5];
const ATTRS: Attrs = {
  time: 0, spin: 0, 'cube-distance': -0.5, samples: 0, 'reflection-scale': 1, shading: 'phong', 'color-space': 'none',
  ...cameraAttrs(EYE, -90, 0),
};

test('a face in the glass plane is seen through the glass, as the reference draws it', async ({ page }) => {
  await openPage(page);
  const { selector } = await mount(page, ATTRS, SIZE);
  const image = await capture(page, undefined, selector);
  const state = (view: FrameState['view']) => defaultFrameState({
    width: SIZE.width, height: SIZE.height, spin: 0, cubeDistance: -0.5, cameraPosition: EYE, yaw: -90, pitch: 0, colorSpace: 'none', view,
  });
  const ref = renderReference(state('final'), { samplesPerAxis: 2 });
  const bare = renderReference(state('scene'), { samplesPerAxis: 2 });
  // The face's middle: a 24 × 24 block about the screen centre (the face spans ±0.5 at 2.5 away:
  // about ±39 px), away from its edges.
  let toRef = 0, toBare = 0, n = 0;
  for (let y = 33; y < 57; y++) {
    for (let x = 68; x < 92; x++) {
      for (let k = 0; k < 3; k++) {
        const i = 4 * (y * SIZE.width + x) + k;
        toRef += Math.abs(image.data[i] - ref.rgba[i]);
        toBare += Math.abs(image.data[i] - bare.rgba[i]);
        n++;
      }
    }
  }
  const line = `cube face in the glass plane: mean |WebGL − reference| ${(toRef / n).toFixed(2)} levels; |WebGL − the face without glass| ${(toBare / n).toFixed(2)}`;
  console.log(line);
  // Measured 0.48 and 13.47: the glass is there, drawn as the reference draws it.
  expect(toRef / n, line).toBeLessThan(1);
  expect(toBare / n, line).toBeGreaterThan(11);
});

test('a face in the glass plane of an object on the viewer\'s side stays in front of the glass, as the reference draws it', async ({ page }) => {
  // A two-sided mesh of two quads: one in the glass plane (x ∈ [−1.5, −0.5], y ∈ [0.5, 1.5], z = 0),
  // one 2 nearer the eye and off to the side, so that the object's centre lies on the viewer's side.
  const quad = (x0: number, x1: number, y0: number, y1: number, z: number) => [x0, y0, z, x1, y0, z, x1, y1, z, x0, y1, z];
  const positions = new Float32Array([...quad(-1.5, -0.5, 0.5, 1.5, 0), ...quad(1.5, 2.5, 0.5, 1.5, 2)]);
  const normals = new Float32Array(24).map((_, i) => (i % 3 === 2 ? 1 : 0));
  const mesh: SceneObject = {
    geometry: { kind: 'mesh', key: 'tie', data: { positions, normals, uvs: new Float32Array(16), indices: new Uint16Array([0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7]) } },
    transform: { position: [0, 0, 0], rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0 },
    material: { ...defaultMaterial([0.9, 0.5, 0.2]), texture: { kind: 'none' } },
    bounds: { center: [0.5, 1, 1], radius: 2.3 },
  };
  const scene: Scene = { ...defaultScene(-0.5, 0), objects: [mesh] };
  const state = (view: FrameState['view']) => defaultFrameState({
    width: SIZE.width, height: SIZE.height, spin: 0, cameraPosition: [-0.2, 1.5, 2.4], yaw: -105, pitch: -12, colorSpace: 'none', view, samples: 0,
  });
  await openRendererPage(page);
  const image = await drawScene(page, state('final'), scene);
  const ref = renderScene(scene, state('final'), null, { samplesPerAxis: 2 });
  const glassed = renderScene({ ...scene, objects: [{ ...mesh, transform: { ...mesh.transform, position: [0, 0, -1e-3] } }] }, state('final'), null, { samplesPerAxis: 2 });
  // Pixels off by more than 8 levels in a channel: against the reference, and against the same
  // face 0.001 behind the glass (the picture if the glass covered it).
  const off = (a: ArrayLike<number>, b: ArrayLike<number>) => {
    let n = 0;
    for (let i = 0; i < a.length; i += 4) if (Math.max(...[0, 1, 2].map((k) => Math.abs(a[i + k] - b[i + k]))) > 8) n++;
    return n;
  };
  const line = `pixels off the reference: ${off(image.data, ref.rgba)}; off the face behind the glass: ${off(image.data, glassed.rgba)}`;
  console.log(line);
  // Measured 89 (the edges: no multisampling here, 2×2 in the reference; 505 while the reference
  // let the glass win a tie by a rounding) and 910 (the face's pixels).
  expect(off(image.data, ref.rgba), line).toBeLessThan(120);
  expect(off(image.data, glassed.rgba), line).toBeGreaterThan(800);
});
