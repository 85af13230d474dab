// A scene ready for rays (src/reference/ray-scene.ts): a tracer of the right kind per object with its code and frame,
// the shared Gaussian meshes, each object's centre in the world, and the glass rectangle hit by hand.
import { describe, expect, it } from 'vitest';
import { BoxTracer, SphereTracer } from '../../src/reference/analytic-tracers';
import { MeshTracer } from '../../src/reference/mesh-tracer';
import { Ray } from '../../src/reference/ray';
import { RayScene } from '../../src/reference/ray-scene';
import { SurfaceHit } from '../../src/reference/surface-hit';
import type { MeshData } from '../../src/scene/geometry/mesh-data';
import type { Geometry, Glass, Scene, SceneObject, Transform } from '../../src/scene/scene';
import { expectClose } from './helpers/math';

const MATERIAL = {
  ambient: [0.2, 0.2, 0.2], diffuse: [0.8, 0.8, 0.8], specular: [0.5, 0.5, 0.5], shininess: 32, opacity: 1,
  texture: { kind: 'none' }, mapping: 'uv',
} as const;

function object(geometry: Geometry, transform: Partial<Transform> = {}, center: [number, number, number] = [0, 0, 0]): SceneObject {
  return {
    geometry, material: MATERIAL, bounds: { center, radius: 1 },
    transform: { position: [0, 0, 0], rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0, ...transform },
  };
}

const sceneOf = (objects: SceneObject[], glass: Glass | null = null): Scene => ({ glass, objects, lights: [], background: [0, 0, 0] });

/** One triangle in z = 0 over (0, 0), (2, 0), (0, 2). */
const TRIANGLE: MeshData = {
  positions: new Float32Array([0, 0, 0, 2, 0, 0, 0, 2, 0]), normals: new Float32Array([0, 0, 1, 0, 0, 1, 0, 0, 1]),
  uvs: new Float32Array(6), indices: new Uint16Array([0, 1, 2]),
};

function ray(o: [number, number, number], d: [number, number, number]): Ray {
  const r = new Ray();
  r.origin.set(o);
  r.direction.set(d);
  return r;
}

describe('RayScene: tracers', () => {
  // Built in each test (not once for the describe): what runs while tests are collected is not measured per test.
  const sceneOf4 = () => sceneOf([
    object({ kind: 'sphere', radius: 0.5 }, { position: [0, 0, -5] }),
    object({ kind: 'box', size: 1 }, { position: [3, 0, -5] }),
    object({ kind: 'mesh', key: 'triangle', data: TRIANGLE }, { position: [-3, 0, -5] }),
    object({ kind: 'gaussian', resolution: 5 }, { position: [0, -10, 0] }),
  ]);

  it('one of the right kind per object, in order, with the codes of SurfaceCodes', () => {
    const scene = sceneOf4();
    const rs = new RayScene(scene, 0);
    expect(rs.scene).toBe(scene);
    expect(rs.tracers.map((t) => t.constructor)).toEqual([SphereTracer, BoxTracer, MeshTracer, MeshTracer]);
    // sphere 1, box 2..7, mesh 8, gaussian 9, glass 10.
    expect([...rs.codes.first]).toEqual([1, 2, 8, 9]);
    expect(rs.codes.glass).toBe(10);
  });

  it('each tracer hits its own object with its index and code', () => {
    const rs = new RayScene(sceneOf4(), 0);
    const hit = new SurfaceHit();
    // The sphere's near pole from z = 0: t = 4.5.
    expect(rs.tracers[0].hit(ray([0, 0, 0], [0, 0, -1]), 0, 0, null, hit)).toBe(true);
    expect([hit.surface, hit.object, hit.t]).toEqual([1, 0, 4.5]);
    // The box's +z face (BOX_FACES 0): code 2, t = 4.5.
    expect(rs.tracers[1].hit(ray([3, 0, 0], [0, 0, -1]), 0, 0, null, hit)).toBe(true);
    expect([hit.surface, hit.object, hit.t]).toEqual([2, 1, 4.5]);
    // The triangle at z = −5, through (−2.5, 0.5): t = 5.
    expect(rs.tracers[2].hit(ray([-2.5, 0.5, 0], [0, 0, -1]), 0, 0, null, hit)).toBe(true);
    expect([hit.surface, hit.object]).toEqual([8, 2]);
    expect(hit.t).toBeCloseTo(5, 12);
    // The Gaussian's peak, a vertex of the 5×5 grid: (0, 1, 0) in the object, (0, −9, 0) in the world.
    expect(rs.tracers[3].hit(ray([0, 0, 0], [0, -1, 0]), 0, 0, null, hit)).toBe(true);
    expect([hit.surface, hit.object]).toEqual([9, 3]);
    expect(hit.t).toBeCloseTo(9, 6);
  });

  it("the Gaussian's mesh is made once per resolution, for every scene", () => {
    const rs = new RayScene(sceneOf4(), 0);
    const meshOf = (s: RayScene, i: number) => (s.tracers[i] as unknown as { mesh: MeshData }).mesh;
    const again = new RayScene(sceneOf([object({ kind: 'gaussian', resolution: 5 }), object({ kind: 'gaussian', resolution: 7 })]), 0);
    expect(meshOf(again, 0)).toBe(meshOf(rs, 3));
    expect(meshOf(again, 1)).not.toBe(meshOf(rs, 3));
    expect(meshOf(again, 0).positions.length).toBe(5 * 5 * 3);
    expect(meshOf(again, 1).positions.length).toBe(7 * 7 * 3);
    expect(meshOf(rs, 2)).toBe(TRIANGLE);
  });

  it('frames are taken at the given time (the spin turns them)', () => {
    // spin π/2 rad/s for 1 s: a quarter turn about y, object x → −z.
    const spun = new RayScene(sceneOf([object({ kind: 'box', size: 1 }, { spin: Math.PI / 2 })]), 1);
    const m = spun.tracers[0].frame.matrix;
    expectClose([m[0], m[1], m[2]], [0, 0, -1]);
    const still = new RayScene(sceneOf([object({ kind: 'box', size: 1 }, { spin: Math.PI / 2 })]), 0);
    expectClose([...still.tracers[0].frame.matrix].slice(0, 3), [1, 0, 0]);
  });

  it('centres: T + R·S·c of each object\'s bounds centre at the time', () => {
    const s = new RayScene(sceneOf([
      // c = (1, 0.5, 2), S = (2, 4, 0.5): (2, 2, 1); Rz(90°): (x, y, z) → (−y, x, z) = (−2, 2, 1); + T (1, 2, 3) = (−1, 4, 4).
      object({ kind: 'sphere', radius: 1 }, { position: [1, 2, 3], rotation: [0, 0, 90], scale: [2, 4, 0.5] }, [1, 0.5, 2]),
      // A quarter turn about y by the spin: (0, 0, 2) → (2, 0, 0).
      object({ kind: 'sphere', radius: 1 }, { position: [0, 0, 0], spin: Math.PI / 2 }, [0, 0, 2]),
      // No turn: T + S·c = (5, 6, 7) + (1, 2, 3).
      object({ kind: 'sphere', radius: 1 }, { position: [5, 6, 7] }, [1, 2, 3]),
      // Rx(90°): (x, y, z) → (x, −z, y); S·c = (1, 2, 6) → (1, −6, 2); + T (0, 1, 0).
      object({ kind: 'box', size: 1 }, { position: [0, 1, 0], rotation: [90, 0, 0], scale: [1, 1, 2] }, [1, 2, 3]),
    ]), 1);
    expectClose(s.centres[0], [-1, 4, 4]);
    expectClose(s.centres[1], [2, 0, 0]);
    expectClose(s.centres[2], [6, 8, 10]);
    expectClose(s.centres[3], [1, -5, 2]);
  });
});

describe('RayScene: the glass', () => {
  it('no glass: glass null, never hit', () => {
    const rs = new RayScene(sceneOf([]), 0);
    expect(rs.glass).toBeNull();
    const hit = new SurfaceHit();
    expect(rs.hitGlass(ray([0, 0, 5], [0, 0, -1]), hit)).toBe(false);
    expect(hit.t).toBe(Infinity);
  });

  // Normal +z at the origin, 4 wide (along a = +x) and 2 high (along b = +y): corner (−2, −1, 0).
  const flatScene = () => new RayScene(sceneOf([], { center: [0, 0, 0], normal: [0, 0, 1], size: [4, 2] }), 0);

  it('a hit: its code, no object, t along the ray, u along a and v along b from the corner, gradients a/w and b/h', () => {
    const flat = flatScene();
    expectClose(flat.glass!.plane, [0, 0, 1, 0]);
    const hit = new SurfaceHit();
    hit.object = 5;
    // From (1, 0.5, 4) along (0.25, −0.125, −2): t = 2, p = (1.5, 0.25, 0); s = 3.5, r = 1.25.
    expect(flat.hitGlass(ray([1, 0.5, 4], [0.25, -0.125, -2]), hit)).toBe(true);
    expect([hit.surface, hit.object, hit.frame, hit.t]).toEqual([flat.codes.glass, -1, null, 2]);
    expect([...hit.p]).toEqual([1.5, 0.25, 0]);
    expect([...hit.n]).toEqual([0, 0, 1]);
    expect([...hit.ng]).toEqual([0, 0, 1]);
    expect([hit.u, hit.v]).toEqual([0.875, 0.625]);
    expectClose(hit.gu, [0.25, 0, 0]);
    expectClose(hit.gv, [0, 0.5, 0]);
  });

  it('two-sided and at any t: from below, and behind the ray\'s origin', () => {
    const flat = flatScene();
    const hit = new SurfaceHit();
    expect(flat.hitGlass(ray([0, 0, -2], [0, 0, 1]), hit)).toBe(true);
    expect(hit.t).toBe(2);
    expect([...hit.n]).toEqual([0, 0, 1]);
    expect(flat.hitGlass(ray([0, 0, 2], [0, 0, 1]), hit)).toBe(true);
    expect(hit.t).toBe(-2);
  });

  it('the rectangle is closed: its edges are hit, a hair outside is not; a ray along the plane never is', () => {
    const flat = flatScene();
    const down = (x: number, y: number) => flat.hitGlass(ray([x, y, 1], [0, 0, -1]), new SurfaceHit());
    expect([down(-2, 0), down(2, 0), down(0, -1), down(0, 1), down(-2, -1), down(2, 1)]).toEqual([true, true, true, true, true, true]);
    expect([down(-2.001, 0), down(2.001, 0), down(0, -1.001), down(0, 1.001)]).toEqual([false, false, false, false]);
    expect(flat.hitGlass(ray([0, 0, 0], [1, 0, 0]), new SurfaceHit())).toBe(false);
  });

  it('an oblique glass off the origin: every component counts', () => {
    // n = (0.6, 0, 0.8), a = (0.8, 0, −0.6), b = n × a = (0, 1, 0), centre (1, 2, 3), 2 × 2: corner c − a − b = (0.2, 1, 3.6).
    // p = c + 0.5a + 0.25b = (1.4, 2.25, 2.7): s = 1.5, r = 1.25; reached from p + 2n along −n at t = 2.
    const rs = new RayScene(sceneOf([object({ kind: 'sphere', radius: 1 })], { center: [1, 2, 3], normal: [0.6, 0, 0.8], size: [2, 2] }), 0);
    const hit = new SurfaceHit();
    expect(rs.hitGlass(ray([2.6, 2.25, 4.3], [-0.6, 0, -0.8]), hit)).toBe(true);
    expect(hit.surface).toBe(2);
    expect(hit.t).toBeCloseTo(2, 12);
    expectClose(hit.p, [1.4, 2.25, 2.7]);
    expectClose(hit.n, [0.6, 0, 0.8]);
    expectClose(hit.ng, [0.6, 0, 0.8]);
    expect(hit.u).toBeCloseTo(0.75, 12);
    expect(hit.v).toBeCloseTo(0.625, 12);
    expectClose(hit.gu, [0.4, 0, -0.3]);
    expectClose(hit.gv, [0, 0.5, 0]);
    // Off the rectangle along a (s = 2.5) or b (r = −0.5): missed.
    expect(rs.hitGlass(ray([2.6 + 0.8, 2.25, 4.3 - 0.6], [-0.6, 0, -0.8]), hit)).toBe(false);
    expect(rs.hitGlass(ray([2.6, 0.25, 4.3], [-0.6, 0, -0.8]), hit)).toBe(false);
  });

  it('a glass turned about every axis', () => {
    // n = (0.48, 0.6, 0.64), a = (0.64, 0, −0.48)/0.8 = (0.8, 0, −0.6), b = n × a = (−0.36, 0.8, −0.48); centre (1, 2, 3), 2 × 2.
    // p = c + 0.5a + 0.25b = (1.31, 2.2, 2.58): s = 1.5, r = 1.25. The ray along −n + 0.3a = (−0.24, −0.6, −0.82) (n·d = −1)
    // from p + 2·(0.24, 0.6, 0.82) = (1.79, 3.4, 4.22): n·o − 3.6 = 0.8592 + 2.04 + 2.7008 − 3.6 = 2 = t.
    const rs = new RayScene(sceneOf([], { center: [1, 2, 3], normal: [0.48, 0.6, 0.64], size: [2, 2] }), 0);
    const hit = new SurfaceHit();
    expect(rs.hitGlass(ray([1.79, 3.4, 4.22], [-0.24, -0.6, -0.82]), hit)).toBe(true);
    expect(hit.t).toBeCloseTo(2, 12);
    expectClose(hit.p, [1.31, 2.2, 2.58]);
    expectClose(hit.n, [0.48, 0.6, 0.64]);
    expect(hit.u).toBeCloseTo(0.75, 12);
    expect(hit.v).toBeCloseTo(0.625, 12);
    expectClose(hit.gu, [0.4, 0, -0.3]);
    expectClose(hit.gv, [-0.18, 0.4, -0.24]);
  });
});
