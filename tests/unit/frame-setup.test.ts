// FrameSetup (src/frame/frame-setup.ts), the per-frame numbers both renderers upload, against
// values worked out by hand: each object's model matrix (T·Rz·Ry·Rx·Ry(spin·t)·S), its world
// bounds and side of the glass, the light vectors from each eye, the lights' colours and point
// mask, the trackball's turn of the objects and of the first light only, eye-relative matrices,
// the mirrored eye and its clip plane, and a scene's glass changing between frames.
import { describe, expect, it } from 'vitest';
import { FrameSetup } from '../../src/frame/frame-setup';
import { orthographicView } from '../../src/frame/orthographic-view';
import { orthoHalfHeight } from '../../src/math/orthographic';
import { MIRROR_CONTACT } from '../../src/math/mirror';
import { defaultMaterial } from '../../src/scene/default-scene';
import type { Glass, Light, Scene, SceneObject, Vec3 } from '../../src/scene/scene';
import type { SceneTurn } from '../../src/scene/turn';
import { defaultFrameState } from './helpers/frame-state';
import { expectClose } from './helpers/math';

const object = (position: Vec3, rotation: Vec3 = [0, 0, 0], scale: Vec3 = [1, 1, 1], spin = 0, center: Vec3 = [0, 0, 0], radius = 1): SceneObject => ({
  geometry: { kind: 'box', size: 1 },
  transform: { position, rotation, scale, spin },
  material: defaultMaterial([0.5, 0.5, 0.5]),
  bounds: { center, radius },
});
const light = (kind: Light['kind'], vector: Vec3, c = 1): Light =>
  ({ kind, vector, ambient: [c, c + 0.1, c + 0.2], diffuse: [c + 0.3, c + 0.4, c + 0.5], specular: [c + 0.6, c + 0.7, c + 0.8] });
const GLASS: Glass = { center: [0, 1, 0], normal: [0, 0, 1], size: [8, 4] };
const scene = (objects: SceneObject[], lights: Light[] = [], glass: Glass | null = GLASS): Scene =>
  ({ glass, objects, lights, background: [0, 0, 0] });
// The camera at (0, 0, 5) looking down −Z (yaw −90°, pitch 0): the viewer's side is +Z.
const STATE = defaultFrameState({ width: 200, height: 100, cameraPosition: [0, 0, 5], yaw: -90, pitch: 0, time: 2 });

/** Column-major 4×4 times a point. */
const apply = (m: ArrayLike<number>, p: Vec3) =>
  [0, 1, 2].map((r) => m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r]);

describe('FrameSetup: objects', () => {
  it('the model matrix is T · Rz · Ry · Rx · Ry(spin·t) · S, applied to a point by hand', () => {
    const f = new FrameSetup();
    // Rx 90° then Ry 90° then Rz 90° of (1, 2, 3) scaled by (2, 1, 1) = (2, 2, 3):
    // Rx(90°): (x, y, z) → (x, −z, y) = (2, −3, 2); Ry(90°): (x, y, z) → (z, y, −x) = (2, −3, −2);
    // Rz(90°): (x, y, z) → (−y, x, z) = (3, 2, −2); + (10, 20, 30).
    f.update(STATE, scene([object([10, 20, 30], [90, 90, 90], [2, 1, 1])]));
    expectClose(apply(f.objects[0].model, [1, 2, 3]), [13, 22, 28], 1e-12);
    // Spin π/4 rad/s for 2 s: Ry(π/2) of (1, 0, 0) = (0, 0, −1), before the rotation (none here).
    f.update(STATE, scene([object([0, 0, 0], [0, 0, 0], [1, 1, 1], Math.PI / 4)]));
    expectClose(apply(f.objects[0].model, [1, 0, 0]), [0, 0, -1], 1e-12);
    // A spin whose angle overflows (1e308 · 2 = ∞) turns by 0, never by NaN.
    f.update({ ...STATE, time: 2 }, scene([object([1, 2, 3], [0, 0, 0], [1, 1, 1], 1e308)]));
    expectClose(Array.from(f.objects[0].model), [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 2, 3, 1]);
  });

  it('each rotation axis on its own (a mutant dropping one is seen)', () => {
    const f = new FrameSetup();
    const at = (rotation: Vec3, p: Vec3) => {
      f.update(STATE, scene([object([0, 0, 0], rotation)]));
      return apply(f.objects[0].model, p);
    };
    expectClose(at([90, 0, 0], [0, 1, 0]), [0, 0, 1], 1e-12);
    expectClose(at([0, 90, 0], [0, 0, 1]), [1, 0, 0], 1e-12);
    expectClose(at([0, 0, 90], [1, 0, 0]), [0, 1, 0], 1e-12);
    expectClose(at([0, 0, 0], [4, 5, 6]), [4, 5, 6], 0);
  });

  it('world bounds: the centre through the model matrix, the radius by the largest |scale|, the side of the glass', () => {
    const f = new FrameSetup();
    f.update(STATE, scene([
      object([1, 2, 3], [0, 0, 90], [1, -3, 2], 0, [1, 0, 0], 0.5),
      object([0, 0, -2], [0, 0, 0], [-4, 1, 1], 0, [0, 0, 0], 2),
    ]));
    // Centre (1, 0, 0) scaled (1, 0, 0), Rz 90° → (0, 1, 0), + (1, 2, 3).
    expectClose(Array.from(f.objects[0].center), [1, 3, 3], 1e-12);
    expect(f.objects[0].radius).toBe(1.5);
    expect(f.objects[0].viewerDistance).toBeCloseTo(3, 12);
    expect(f.objects[1].radius).toBe(8);
    // Behind the glass: negative, as seen from +Z.
    expect(f.objects[1].viewerDistance).toBeCloseTo(-2, 12);
    // Seen from −Z the signs swap.
    f.update({ ...STATE, cameraPosition: [0, 0, -5], yaw: 90 }, scene([object([0, 0, -2])]));
    expect(f.side).toBe(-1);
    expect(f.objects[0].viewerDistance).toBeCloseTo(2, 12);
  });

  it('matrices are relative to each eye: the model\'s translation minus the eye, the mirrored eye across the glass', () => {
    const f = new FrameSetup();
    f.update({ ...STATE, cameraPosition: [1, 2, 5] }, scene([object([3, 4, -1])]));
    expectClose(Array.from(f.eye), [1, 2, 5]);
    expectClose(Array.from(f.mirroredEye), [1, 2, -5]);
    expect(f.eyeDistance).toBe(5);
    const main = f.objects[0].main.modelRelative, mirrored = f.objects[0].mirrored.modelRelative;
    expectClose([main[12], main[13], main[14]], [2, 2, -6]);
    expectClose([mirrored[12], mirrored[13], mirrored[14]], [2, 2, 4]);
    // The glass is built in world coordinates: its model is the identity, eye-relative.
    expectClose(Array.from(f.glassMain.modelRelative), [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -1, -2, -5, 1]);
    expectClose(Array.from(f.glassMirrored.modelRelative), [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -1, -2, 5, 1]);
    expectClose(Array.from(f.glassMain.normal), [1, 0, 0, 0, 1, 0, 0, 0, 1]);
    expect(Array.from(f.reflectionViewProjection)).toEqual(Array.from(f.glassMirrored.modelViewProjection));
    // The normal matrix: inverse transpose of a scale (2, 4, 1) is diag(1/2, 1/4, 1).
    f.update(STATE, scene([object([0, 0, 0], [0, 0, 0], [2, 4, 1])]));
    expectClose(Array.from(f.objects[0].main.normal), [0.5, 0, 0, 0, 0.25, 0, 0, 0, 1]);
    expectClose(Array.from(f.objects[0].mirrored.normal), [0.5, 0, 0, 0, 0.25, 0, 0, 0, 1]);
  });

  it('clip space: the object\'s centre straight ahead lands at the screen\'s centre, its mirror image too', () => {
    const f = new FrameSetup();
    f.update(STATE, scene([object([0, 0, -3])]));
    const clip = (m: Float32Array) => [0, 1, 3].map((r) => m[12 + r]);
    const [x, y, w] = clip(f.objects[0].main.modelViewProjection);
    expect(Math.abs(x / w)).toBeLessThan(1e-7);
    expect(Math.abs(y / w)).toBeLessThan(1e-7);
    expect(w).toBeCloseTo(8, 5); // 8 ahead of the eye
    // The mirrored eye (0, 0, −5) is 2 from the object; the plane's reflection turns that offset to the view's −Z: w = 2.
    const [mx, my, mw] = clip(f.objects[0].mirrored.modelViewProjection);
    expect(Math.abs(mx / mw)).toBeLessThan(1e-7);
    expect(Math.abs(my / mw)).toBeLessThan(1e-7);
    expect(mw).toBeCloseTo(2, 5);
  });

  it('the clip plane keeps the viewer\'s side, MIRROR_CONTACT in from the glass', () => {
    const f = new FrameSetup();
    f.update(STATE, scene([]));
    // side·(n·(rel + e′) + d) − contact with n = +Z, e′ = (0, 0, −5), d = 0: (0, 0, 1, −5 − contact).
    expectClose(Array.from(f.mirroredClip), [0, 0, 1, -5 - MIRROR_CONTACT], 1e-12);
    expectClose(Array.from(f.clipPlane), [0, 0, 1, -5 - MIRROR_CONTACT], 1e-6);
    expect(f.viewDot).toBeCloseTo(-1, 12);
  });
});

describe('FrameSetup: lights', () => {
  it('directional: the unit vector towards it (w 0); point: its position from each eye (w 1); the colours; the point mask', () => {
    const f = new FrameSetup();
    f.update({ ...STATE, cameraPosition: [1, 2, 5] }, scene([], [light('directional', [0, 3, 4], 0), light('point', [4, 6, 2], 1)]));
    expect(f.lightCount).toBe(2);
    expect(f.pointMask).toBe(0b10);
    expectClose(Array.from(f.lightsMain.vectors.slice(0, 8)), [0, 0.6, 0.8, 0, 3, 4, -3, 1], 1e-7);
    // The mirrored eye (1, 2, −5): a direction is the same, a point's offset is from it.
    expectClose(Array.from(f.lightsMirrored.vectors.slice(0, 8)), [0, 0.6, 0.8, 0, 3, 4, 7, 1], 1e-7);
    expect(Array.from(f.lightsMain.vectors.slice(8))).toEqual(new Array(8).fill(0));
    expectClose(Array.from(f.lightAmbient.slice(0, 6)), [0, 0.1, 0.2, 1, 1.1, 1.2], 1e-6);
    expectClose(Array.from(f.lightDiffuse.slice(0, 6)), [0.3, 0.4, 0.5, 1.3, 1.4, 1.5], 1e-6);
    expectClose(Array.from(f.lightSpecular.slice(0, 6)), [0.6, 0.7, 0.8, 1.6, 1.7, 1.8], 1e-6);
    expectClose(Array.from(f.lightWorld.slice(0, 6)), [0, 3, 4, 4, 6, 2]);
  });

  it('a zero direction stays zero (no NaN); fewer lights next frame clear the old vectors and mask', () => {
    const f = new FrameSetup();
    f.update(STATE, scene([], [light('point', [1, 1, 1]), light('point', [2, 2, 2]), light('point', [0, 0, 9])]));
    expect(f.pointMask).toBe(0b111);
    f.update(STATE, scene([], [light('directional', [0, 0, 0])]));
    expect(f.lightCount).toBe(1);
    expect(f.pointMask).toBe(0);
    expect(Array.from(f.lightsMain.vectors)).toEqual(new Array(16).fill(0));
  });

  it('the trackball\'s turn: objects about the centre, the first light only (a point about the centre, a direction by the rotation)', () => {
    const f = new FrameSetup();
    const s = Math.SQRT1_2;
    // 90° about +Y: (x, y, z) → (z, y, −x).
    const turn: SceneTurn = { objects: [0, s, 0, s], light: [0, s, 0, s], center: [1, 0, 0] };
    f.update({ ...STATE, turn }, scene(
      [object([2, 0, 0])],
      [light('point', [1, 0, 3]), light('point', [1, 0, 3]), light('directional', [1, 0, 0])],
    ));
    // The object at (2, 0, 0): 1 from the centre along +X → (1, 0, −1).
    expectClose(Array.from(f.objects[0].center), [1, 0, -1], 1e-12);
    // The first (point) light: (0, 0, 3) from the centre → (3, 0, 0) → (4, 0, 0). The others stay.
    expectClose(Array.from(f.lightWorld.slice(0, 9)), [4, 0, 0, 1, 0, 3, 1, 0, 0], 1e-12);
    // A directional first light turns without the centre: (1, 0, 0) → (0, 0, −1).
    f.update({ ...STATE, turn }, scene([], [light('directional', [1, 0, 0])]));
    expectClose(Array.from(f.lightWorld.slice(0, 3)), [0, 0, -1], 1e-12);
    // The objects' and the light's turns are separate: turning only the light leaves the objects.
    f.update({ ...STATE, turn: { objects: [0, 0, 0, 1], light: [0, s, 0, s], center: [1, 0, 0] } },
      scene([object([2, 0, 0])], [light('directional', [1, 0, 0])]));
    expectClose(Array.from(f.objects[0].center), [2, 0, 0], 1e-12);
    expectClose(Array.from(f.lightWorld.slice(0, 3)), [0, 0, -1], 1e-12);
    f.update({ ...STATE, turn: { objects: [0, s, 0, s], light: [0, 0, 0, 1], center: [1, 0, 0] } },
      scene([object([2, 0, 0])], [light('directional', [1, 0, 0])]));
    expectClose(Array.from(f.objects[0].center), [1, 0, -1], 1e-12);
    expectClose(Array.from(f.lightWorld.slice(0, 3)), [1, 0, 0], 1e-12);
  });
});

describe('FrameSetup: the glass', () => {
  it('follows the scene\'s glass when it changes, and keeps the default frame (hasGlass false) without one', () => {
    const f = new FrameSetup();
    f.update(STATE, scene([]));
    expect(f.hasGlass).toBe(true);
    expectClose(Array.from(f.glass.plane), [0, 0, 1, 0]);
    f.update(STATE, scene([], [], { center: [0, 0, -2], normal: [0, 0, 1], size: [2, 2] }));
    expectClose(Array.from(f.glass.plane), [0, 0, 1, 2]);
    expect(f.eyeDistance).toBe(7);
    expectClose(Array.from(f.mirroredEye), [0, 0, -9]);
    f.update(STATE, scene([], [], null));
    expect(f.hasGlass).toBe(false);
    // The default glass's plane (z = 0) still places the mirrored eye.
    expectClose(Array.from(f.glass.plane), [0, 0, 1, 0]);
    expectClose(Array.from(f.mirroredEye), [0, 0, -5]);
    f.update(STATE, scene([]));
    expect(f.hasGlass).toBe(true);
  });

  it('perspective: half-height 0 and both view vectors (0, 0, 0, 1); the aspect from width/height', () => {
    const f = new FrameSetup();
    f.update({ ...STATE, fov: 90 }, scene([]));
    expect(f.orthographic).toBe(false);
    expect(f.halfHeight).toBe(0);
    expect(Array.from(f.viewVectorMain)).toEqual([0, 0, 0, 1]);
    expect(Array.from(f.viewVectorMirrored)).toEqual([0, 0, 0, 1]);
    // fov 90°: 1/tan(45°) = 1 vertically, 1/aspect = 0.5 horizontally.
    expect(f.projection[5]).toBeCloseTo(1, 12);
    expect(f.projection[0]).toBeCloseTo(0.5, 12);
    // A zero height counts as one pixel.
    f.update({ ...STATE, fov: 90, width: 3, height: 0 }, scene([]));
    expect(f.projection[0]).toBeCloseTo(1 / 3, 12);
    expect(f.mirrorsWinding).toBe(false);
    expect(f.courseRange).toBeNull();
  });
});

describe('FrameSetup: more by hand', () => {
  it('the first light turned about a centre off every axis: a point light through all of the turn\'s matrix', () => {
    // 120° about (1, 1, 1)/√3, q = (½, ½, ½, ½): (x, y, z) → (z, x, y). Centre c = (1, 3, 7):
    // R c = (7, 1, 3), so the turn is R p + (−6, 2, 4). The point light at (2, 0, 0) → (−6, 4, 4).
    const f = new FrameSetup();
    const turn: SceneTurn = { objects: [0, 0, 0, 1], light: [0.5, 0.5, 0.5, 0.5], center: [1, 3, 7] };
    f.update({ ...STATE, turn }, scene([], [light('point', [2, 0, 0])]));
    expectClose(Array.from(f.lightWorld.slice(0, 3)), [-6, 4, 4], 1e-12);
  });

  it('the third light\'s slots: 4·2 = 8 onwards, a direction normalized by its length', () => {
    const f = new FrameSetup();
    f.update(STATE, scene([], [light('directional', [0, 0, 1]), light('directional', [0, 1, 0]), light('point', [1, 2, 3]), light('directional', [3, 0, 4])]));
    // From the eye (0, 0, 5): the point light at (1, 2, −2); the fourth's (3, 0, 4)/5.
    expectClose(Array.from(f.lightsMain.vectors), [0, 0, 1, 0, 0, 1, 0, 0, 1, 2, -2, 1, 0.6, 0, 0.8, 0], 1e-7);
    expect(f.pointMask).toBe(0b100);
  });

  it('a scale along y alone, or z alone, is applied; the bounds\' centre through every entry of the model', () => {
    const f = new FrameSetup();
    f.update(STATE, scene([object([0, 0, 0], [0, 0, 0], [1, 2, 1]), object([0, 0, 0], [0, 0, 0], [1, 1, 3])]));
    expectClose(apply(f.objects[0].model, [1, 1, 1]), [1, 2, 1], 1e-12);
    expectClose(apply(f.objects[1].model, [1, 1, 1]), [1, 1, 3], 1e-12);
    // Bounds centre (1, 2, 3) through 120° about (1, 1, 1) (Rz 90°·Rx 90° is that turn: (x, y, z) → (z, x, y))
    // and T (10, 20, 30): (3, 1, 2) + T.
    f.update(STATE, scene([object([10, 20, 30], [90, 0, 90], [1, 1, 1], 0, [1, 2, 3], 1)]));
    expectClose(Array.from(f.objects[0].center), [13, 21, 32], 1e-12);
    // Through a turn with no zero entry: the centre is the model matrix applied to it.
    f.update(STATE, scene([object([1, -2, 3], [30, 45, 60], [1, 2, 3], 0, [0.5, -1.5, 2], 1)]));
    expectClose(Array.from(f.objects[0].center), apply(f.objects[0].model, [0.5, -1.5, 2]), 1e-12);
  });

  it('viewDot is the glass normal · the view direction, every component', () => {
    const f = new FrameSetup();
    // yaw −45°, pitch 30°: forward (cos30·cos45, sin30, −cos30·sin45); n = (0.48, 0.6, 0.64).
    f.update({ ...STATE, yaw: -45, pitch: 30 }, scene([], [], { center: [0, 1, 0], normal: [0.48, 0.6, 0.64], size: [8, 4] }));
    const c30 = Math.cos(Math.PI / 6), s45 = Math.SQRT1_2;
    expect(f.viewDot).toBeCloseTo(0.48 * c30 * s45 + 0.6 * 0.5 - 0.64 * c30 * s45, 12);
  });

  it('orthographic only with its part loaded and no course camera: (−forward, 0) as the view vector, its mirror image for the mirrored eye', () => {
    const ortho = { ...STATE, projection: 'orthographic' as const, yaw: -45, pitch: 30 };
    const without = new FrameSetup();
    without.update(ortho, scene([]));
    expect(without.orthographic).toBe(false);
    const f = new FrameSetup(null, orthographicView);
    f.update(ortho, scene([]));
    expect(f.orthographic).toBe(true);
    const c30 = Math.cos(Math.PI / 6), s45 = Math.SQRT1_2;
    const forward = [c30 * s45, 0.5, -c30 * s45];
    expectClose(Array.from(f.viewVectorMain), [-forward[0], -forward[1], -forward[2], 0], 1e-7);
    // Mirrored in z = 0: the z component flips.
    expectClose(Array.from(f.viewVectorMirrored), [-forward[0], -forward[1], forward[2], 0], 1e-7);
    // Sized at the glass's centre (0, 1, 0) when there is no target; with no glass, at the origin.
    expect(f.halfHeight).toBeCloseTo(orthoHalfHeight(ortho, [0, 1, 0]), 12);
    f.update(ortho, scene([], [], null));
    expect(f.halfHeight).toBeCloseTo(orthoHalfHeight(ortho, null), 12);
    expect(f.halfHeight).not.toBeCloseTo(orthoHalfHeight(ortho, [0, 1, 0]), 6);
  });
});
