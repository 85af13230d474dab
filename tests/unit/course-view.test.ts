// A course camera (docs/course-files.md#camera-cfg, `camera-src`) in the frame setup that both renderers use, and in
// the float64 reference: the projection is the course's pixel formula, near and far hold the
// scene, a mirroring camera swaps the front face, and the software image matches the reference.
import { describe, expect, it } from 'vitest';
import { courseBasis, courseProject, type CourseCamera, type Vec3 } from '../../src/math/course-camera';
import { reflectPoint } from '../../src/math/mirror';
import { compareImages, renderScene } from '../../src/reference';
import { FrameSetup } from '../../src/frame/frame-setup';
import { CourseProjection } from '../../src/frame/course-projection';
import type { FrameState } from '../../src/frame/types';
import { defaultFrameState } from './helpers/frame-state';
import { courseSceneRange } from '../../src/scene/course-depth';
import { BACKGROUND, DEFAULT_LIGHT, defaultScene } from '../../src/scene/default-scene';
import type { Scene } from '../../src/scene/scene';
import { SoftwareRenderer } from '../../src/software';

const W = 160, H = 90;

function camera(c: Vec3, look: Vec3, up: Vec3, d: number, hx: number, hy: number): CourseCamera {
  const basis = courseBasis([look[0] - c[0], look[1] - c[1], look[2] - c[2]], up);
  if (typeof basis === 'string') throw new Error(basis);
  return { c, ...basis, d, hx, hy };
}

/** Looking at the glass centre from the cube's side, a window stretched against 160×90. */
const OBLIQUE = camera([3.6, 2.4, 4], [0, 1, 0], [0, 1, 0], 1, 0.6, 0.5);

function state(cam: CourseCamera | null, over: Partial<FrameState> = {}): FrameState {
  return defaultFrameState({
    width: W, height: H, time: 1.25, cameraPosition: [9, 9, 9], yaw: 0, pitch: 0, colorSpace: 'none', samples: 0, courseCamera: cam, ...over,
  });
}

/** The pixel a world point lands on through setup.viewProjection (eye-relative), rows from the top. */
function pixelOf(setup: FrameSetup, p: Vec3): { x: number; y: number; depth: number } {
  const m = setup.viewProjection, e = setup.eye;
  const r = [p[0] - e[0], p[1] - e[1], p[2] - e[2], 1];
  const clip = [0, 1, 2, 3].map((row) => m[row] * r[0] + m[4 + row] * r[1] + m[8 + row] * r[2] + m[12 + row] * r[3]);
  return { x: ((clip[0] / clip[3] + 1) * W) / 2, y: ((1 - clip[1] / clip[3]) * H) / 2, depth: clip[2] / clip[3] };
}

const POINTS: Vec3[] = [[-1, 1, 0.75], [1, 1, -1.5], [-4, -1, 0], [4, 3, 0], [0.3, 2.2, 1.1]];

describe('frame setup with a course camera', () => {
  it('projects every point where courseProject puts it, with the eye at C, whatever cameraPosition says', () => {
    for (const cam of [OBLIQUE, { ...OBLIQUE, hx: -0.6 }, { ...OBLIQUE, hy: -0.5, d: 2 }]) {
      const setup = new FrameSetup(new CourseProjection());
      setup.update(state(cam), defaultScene(0.75, 0.8));
      expect([...setup.eye]).toEqual(cam.c);
      for (const p of POINTS) {
        const want = courseProject(cam, p, W, H);
        const got = pixelOf(setup, p);
        expect(got.x).toBeCloseTo(want.x, 9);
        expect(got.y).toBeCloseTo(want.y, 9);
      }
    }
  });

  it('puts every vertex of the scene between near and far (depth within −1..1)', () => {
    const setup = new FrameSetup(new CourseProjection());
    const scene = defaultScene(0.75, 0.8);
    setup.update(state(OBLIQUE), scene);
    const range = setup.courseRange!;
    expect(range.behind).toBe(false);
    // The glass corners and the cube's corners at this time are the extremes here.
    for (const p of [[-4, -1, 0], [4, -1, 0], [4, 3, 0], [-4, 3, 0]] as Vec3[]) {
      const depth = pixelOf(setup, p).depth;
      expect(depth).toBeGreaterThan(-1);
      expect(depth).toBeLessThan(1);
    }
    // Tight: the nearest and farthest glass corners lie within 0.2% of near and far... or inside.
    const zs = [[-4, -1, 0], [4, -1, 0], [4, 3, 0], [-4, 3, 0]].map((p) => (p[0] - 3.6) * OBLIQUE.n[0] + (p[1] - 2.4) * OBLIQUE.n[1] + (p[2] - 4) * OBLIQUE.n[2]);
    expect(range.near).toBeLessThanOrEqual(Math.min(...zs));
    expect(range.far).toBeGreaterThanOrEqual(Math.max(...zs));
    expect(range.far).toBeLessThan(2 * Math.max(...zs));
  });

  it('far covers what the reflection pass draws: the scene mirrored across the glass', () => {
    const scene = defaultScene(0.75, 0);
    const range = courseSceneRange(OBLIQUE, scene, 0);
    const mirrored = new Float64Array(3);
    reflectPoint(mirrored, [-1.5, 1.5, 1.25], [0, 0, 1, 0]); // the cube's far corner, mirrored
    const z = (mirrored[0] - 3.6) * OBLIQUE.n[0] + (mirrored[1] - 2.4) * OBLIQUE.n[1] + (mirrored[2] - 4) * OBLIQUE.n[2];
    expect(range.far).toBeGreaterThanOrEqual(z);
  });

  it('flags a mirrored picture: one negative half-size, or a camera that looks away; not two', () => {
    const scene = defaultScene(0.75, 0.8);
    const flags = [
      OBLIQUE, { ...OBLIQUE, hx: -0.6 }, { ...OBLIQUE, hy: -0.5 }, { ...OBLIQUE, hx: -0.6, hy: -0.5 },
      { ...OBLIQUE, d: -1 },
    ].map((cam) => {
      const setup = new FrameSetup(new CourseProjection());
      setup.update(state(cam), scene);
      return setup.mirrorsWinding;
    });
    expect(flags).toEqual([false, true, true, false, false]);
    const away = camera([3.6, 2.4, 4], [7.2, 3.8, 8], [0, 1, 0], 1, 0.6, 0.5);
    const setup = new FrameSetup(new CourseProjection());
    setup.update(state(away), scene);
    expect(setup.courseRange!.behind).toBe(true);
    expect(setup.mirrorsWinding).toBe(true);
    // The formula as it stands for z < 0: the same pixels courseProject gives.
    for (const p of POINTS) {
      const want = courseProject(away, p, W, H);
      expect(pixelOf(setup, p).x).toBeCloseTo(want.x, 9);
      expect(pixelOf(setup, p).y).toBeCloseTo(want.y, 9);
    }
  });

  it('the flyby camera is untouched when courseCamera is null', () => {
    const a = new FrameSetup(new CourseProjection()), b = new FrameSetup(new CourseProjection());
    const scene = defaultScene(0.75, 0.8);
    a.update(state(null, { cameraPosition: [3.6, 2.4, 0.2], yaw: -169, pitch: -23.6 }), scene);
    const s = state(null, { cameraPosition: [3.6, 2.4, 0.2], yaw: -169, pitch: -23.6 });
    delete s.courseCamera;
    b.update(s, scene);
    expect([...a.viewProjection]).toEqual([...b.viewProjection]);
    expect(a.mirrorsWinding).toBe(false);
    expect(a.courseRange).toBeNull();
  });

  it('a setup without the course projection (its chunk not loaded) draws from the camera attributes', () => {
    const bare = new FrameSetup(), flyby = new FrameSetup(new CourseProjection());
    const scene = defaultScene(0.75, 0.8);
    const pose: Partial<FrameState> = { cameraPosition: [3.6, 2.4, 0.2], yaw: -169, pitch: -23.6 };
    bare.update(state(OBLIQUE, pose), scene);
    flyby.update(state(null, pose), scene);
    expect([...bare.viewProjection]).toEqual([...flyby.viewProjection]);
    expect([...bare.eye]).toEqual([3.6, 2.4, 0.2]);
    expect(bare.courseRange).toBeNull();
    bare.course = new CourseProjection();
    bare.update(state(OBLIQUE, pose), scene);
    expect(bare.courseRange).not.toBeNull();
    expect([...bare.viewProjection]).not.toEqual([...flyby.viewProjection]);
  });
});

describe(`software renderer against the reference with course cameras (${W}×${H}, 4×4 samples)`, () => {
  const renderer = new SoftwareRenderer({ samplesPerAxis: 4 });
  const plain: Scene = { ...defaultScene(0.75, 0.8), glass: null, lights: [DEFAULT_LIGHT], background: BACKGROUND };
  /** Each bound is the figure measured less this (both renderers are deterministic; see software-reference.test.ts). */
  const MARGIN_DB = 2;
  // [name, camera, scene, PSNR measured over the whole image and over the objects, in dB]
  const cases: [string, CourseCamera, Scene, number, number][] = [
    ['oblique, stretched window, glass', OBLIQUE, defaultScene(0.75, 0.8), 54.1, 56.3],
    ['negative hx (mirrored; culled cube and sphere)', { ...OBLIQUE, hx: -0.6 }, defaultScene(0.75, 0.8), 54.1, 56.3],
    ['negative hy, no glass', { ...OBLIQUE, hy: -0.5 }, plain, 50.2, 44.3],
    ['looking away (behind), no glass', camera([3.6, 2.4, 4], [7.2, 3.8, 8], [0, 1, 0], 1, 0.6, 0.5), plain, 50.2, 44.3],
  ];
  for (const [name, cam, scene, all, objects] of cases) {
    it(`${name}: within ${MARGIN_DB} dB of ${all} dB (objects ${objects} dB)`, () => {
      const s = state(cam);
      const cmp = compareImages(renderScene(scene, s, null, { samplesPerAxis: 4 }), renderer.render(scene, s));
      const line = `course camera, ${name}: PSNR ${cmp.psnr.all.toFixed(1)} dB (objects ${cmp.psnr.objects.toFixed(1)}), max error ${cmp.maxError.toFixed(0)}`;
      console.log(line);
      expect(cmp.psnr.all, line).toBeGreaterThanOrEqual(all - MARGIN_DB);
      expect(cmp.psnr.objects, line).toBeGreaterThanOrEqual(objects - MARGIN_DB);
    });
  }
});
