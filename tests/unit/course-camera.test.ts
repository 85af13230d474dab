// The course's camera (docs/course-files.md#camera-cfg): the .cfg loader, the pixel projection against hand-computed
// values, and the 4×4 matrix against the pixel formula.
import { describe, expect, it } from 'vitest';
import { parseCameraCfg } from '../../src/loaders/course/camera-cfg';
import {
  courseBasis, courseDepthRange, courseProject, courseView, courseViewProjection, type CourseCamera, type Vec3,
} from '../../src/math/course-camera';
import { cross } from './helpers/obj';
import { expectLoadError, sample } from './helpers/course';

const R2 = Math.SQRT1_2;

function closeTo(actual: ArrayLike<number>, want: ArrayLike<number>, digits = 12): void {
  expect(actual.length).toBe(want.length);
  for (let k = 0; k < want.length; k++) expect(actual[k], `component ${k}`).toBeCloseTo(want[k], digits);
}

/** An oblique camera at (1, 2, 3) looking along (1, 1, 0) with z up: U = (1, −1, 0)/√2. */
function oblique(d = 1, hx = 1, hy = 1): CourseCamera {
  const basis = courseBasis([1, 1, 0], [0, 0, 3]);
  if (typeof basis === 'string') throw new Error(basis);
  return { c: [1, 2, 3], ...basis, d, hx, hy };
}

describe('parseCameraCfg', () => {
  it('normalises N, makes V orthogonal to N (Gram-Schmidt) and unit, and sets U = N × V', () => {
    const cam = parseCameraCfg(sample('camera.cfg'), { url: 'camera.cfg' });
    expect(cam.c).toEqual([0, 0, 10]);
    expect(cam.n).toEqual([0, 0, -1]);
    expect(cam.v).toEqual([0, 1, 0]); // (0, 1, 1) less its part along N
    expect(cam.u).toEqual([1, 0, 0]);
    expect([cam.d, cam.hx, cam.hy]).toEqual([2, 1, 0.5]);
    expect(cam.warnings).toEqual([]);
  });

  it('keeps the sign of a negative half-size; reads CRLF, a BOM, blank lines, no final newline', () => {
    const cam = parseCameraCfg(sample('camera-negative-hx.cfg'), { url: 'neg.cfg' });
    expect([cam.d, cam.hx, cam.hy]).toEqual([2, -1, 0.5]);
    expect(cam.u).toEqual([1, 0, 0]);
  });

  it('gives a left-handed (U, V, N): U × V = −N, all unit and orthogonal', () => {
    const cam = parseCameraCfg('5 -1 2\n0.3 -2 0.7\n1 1 1\n1 1 1\n');
    for (const a of [cam.u, cam.v, cam.n]) expect(Math.hypot(...a)).toBeCloseTo(1, 14);
    expect(cam.u[0] * cam.v[0] + cam.u[1] * cam.v[1] + cam.u[2] * cam.v[2]).toBeCloseTo(0, 14);
    expect(cam.n[0] * cam.v[0] + cam.n[1] * cam.v[1] + cam.n[2] * cam.v[2]).toBeCloseTo(0, 14);
    closeTo(cross(cam.u as Vec3, cam.v as Vec3), cam.n.map((x) => -x), 14);
  });

  it('warns about values and lines past the four', () => {
    const cam = parseCameraCfg('0 0 10\n0 0 -1 7\n0 1 0\n1 1 1\n\n1 2 3\n', { url: 'x.cfg' });
    expect(cam.warnings.map((w) => w.line)).toEqual([2, 6]);
  });

  it('is a load error, with its line, for a missing line, a bad token, N = 0, V ∥ N, or a 0 in d hx hy', () => {
    expectLoadError(() => parseCameraCfg(sample('camera-truncated.cfg'), { url: 't.cfg' }), 't.cfg', 3, /ends here, no line for d hx hy/);
    expectLoadError(() => parseCameraCfg(sample('camera-zero-hy.cfg'), { url: 'z.cfg' }), 'z.cfg', 4, /hy is 0/);
    expectLoadError(() => parseCameraCfg('0 0 0\n0 0 0\n0 1 0\n1 1 1\n', { url: 'n.cfg' }), 'n.cfg', 2, /N is the zero vector/);
    expectLoadError(() => parseCameraCfg(sample('camera-parallel-v.cfg'), { url: 'p.cfg' }), 'p.cfg', 3, /V is parallel to N/);
    expectLoadError(() => parseCameraCfg('0 0 10\n0 0 -1\n0 1 0\n1 1 O.5\n', { url: 'o.cfg' }), 'o.cfg', 4, /"O\.5" is not a number/);
    expectLoadError(() => parseCameraCfg('0 0 10\n0 0\n0 1 0\n1 1 1\n', { url: 'o.cfg' }), 'o.cfg', 2, /needs 3 numbers/);
  });
});

describe('courseProject', () => {
  it('projects as the course does: view coordinates, x\' = (d/hx)·x/z, pixel ((x\'+1)·W/2, (1−y\')·H/2)', () => {
    const cam = parseCameraCfg(sample('camera.cfg'));
    // P − C = (1, 2, −10): x = 1, y = 2, z = 10; x' = 2·1/10 = 0.2, y' = (2/0.5)·2/10 = 0.8.
    expect(courseView(cam, [1, 2, 0])).toEqual([1, 2, 10]);
    expect(courseProject(cam, [1, 2, 0], 200, 100)).toEqual({ x: 120, y: expect.closeTo(10, 12), z: 10 });
    // Straight ahead is the centre of the canvas.
    expect(courseProject(cam, [0, 0, -5], 640, 480)).toEqual({ x: 320, y: 240, z: 15 });
  });

  it('mirrors the x axis with a negative hx', () => {
    const cam = parseCameraCfg(sample('camera-negative-hx.cfg'));
    expect(courseProject(cam, [1, 2, 0], 200, 100)).toEqual({ x: 80, y: expect.closeTo(10, 12), z: 10 });
  });

  it('projects for an oblique camera, window stretched when hx/hy ≠ W/H', () => {
    const cam = oblique(1, 1, 1);
    closeTo(cam.u, [R2, -R2, 0]);
    // P = C + 4N + 1U + 0.5V → view (1, 0.5, 4): x' = 0.25, y' = 0.125.
    const p = [1 + 4 * R2 + R2, 2 + 4 * R2 - R2, 3.5];
    closeTo(courseView(cam, p), [1, 0.5, 4]);
    const px = courseProject(cam, p, 100, 100);
    closeTo([px.x, px.y, px.z], [62.5, 43.75, 4]);
    const wide = courseProject(cam, p, 300, 100); // same window, wider canvas: stretched in x
    closeTo([wide.x, wide.y], [187.5, 43.75]);
  });

  it('applies the formula as it stands behind the camera (z < 0), reporting z', () => {
    const cam = oblique();
    const behind = courseProject(cam, [1 - 4 * R2 + R2, 2 - 4 * R2 - R2, 3.5], 100, 100);
    closeTo([behind.x, behind.y, behind.z], [37.5, 56.25, -4]);
  });
});

describe('courseViewProjection', () => {
  /** Window position from the matrix: clip → NDC → GL viewport, rows turned to count from the top. */
  function throughMatrix(m: ArrayLike<number>, p: ArrayLike<number>, w: number, h: number): { x: number; y: number; depth: number; clipW: number } {
    const clip = [0, 1, 2, 3].map((r) => m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r]);
    const [nx, ny, nz] = [clip[0] / clip[3], clip[1] / clip[3], clip[2] / clip[3]];
    const yFromBottom = ((ny + 1) * h) / 2;
    return { x: ((nx + 1) * w) / 2, y: h - yFromBottom, depth: nz, clipW: clip[3] };
  }

  function randomPoints(cam: CourseCamera, count: number, zSign: number): number[][] {
    let s = 99;
    const r = (): number => ((s = (Math.imul(s, 1664525) + 1013904223) >>> 0) / 2 ** 32) * 2 - 1;
    return Array.from({ length: count }, () => {
      const [x, y, z] = [r() * 3, r() * 2, zSign * (2 + 6 * Math.abs(r()))];
      return [0, 1, 2].map((c) => cam.c[c] + x * cam.u[c] + y * cam.v[c] + z * cam.n[c]);
    });
  }

  for (const [name, hx, hy] of [['hx, hy > 0', 1.2, 0.7], ['negative hx', -1.2, 0.7], ['negative hy', 1.2, -0.7]] as const) {
    it(`agrees with the pixel formula and keeps every vertex inside near..far (${name})`, () => {
      const cam = oblique(1.5, hx, hy);
      const points = randomPoints(cam, 50, 1);
      const range = courseDepthRange(cam, points.flat());
      expect(range.behind).toBe(false);
      const m = courseViewProjection(new Float64Array(16), cam, range);
      let nearest = Infinity, farthest = -Infinity;
      for (const p of points) {
        const want = courseProject(cam, p, 320, 180);
        const got = throughMatrix(m, p, 320, 180);
        expect(got.x).toBeCloseTo(want.x, 9);
        expect(got.y).toBeCloseTo(want.y, 9);
        expect(got.clipW).toBeGreaterThan(0);
        expect(Math.abs(got.depth)).toBeLessThan(1);
        nearest = Math.min(nearest, got.depth); farthest = Math.max(farthest, got.depth);
      }
      expect(nearest).toBeLessThan(-0.99); // the 0.1% margins, no more
      expect(farthest).toBeGreaterThan(0.99);
    });
  }

  it('draws a camera that looks away as the course did: the formula on negative z, nearest |z| in front', () => {
    const cam = oblique(1, 1, 1);
    const points = randomPoints(cam, 30, -1);
    const range = courseDepthRange(cam, points.flat());
    expect(range.behind).toBe(true);
    const m = courseViewProjection(new Float64Array(16), cam, range);
    const byDepth = points.map((p) => ({ z: courseProject(cam, p, 100, 100).z, got: throughMatrix(m, p, 100, 100), want: courseProject(cam, p, 100, 100) }));
    for (const { got, want } of byDepth) {
      expect(got.clipW).toBeGreaterThan(0);
      expect(got.x).toBeCloseTo(want.x, 9);
      expect(got.y).toBeCloseTo(want.y, 9);
      expect(Math.abs(got.depth)).toBeLessThan(1);
    }
    byDepth.sort((a, b) => Math.abs(a.z) - Math.abs(b.z));
    for (let k = 1; k < byDepth.length; k++) expect(byDepth[k].got.depth).toBeGreaterThan(byDepth[k - 1].got.depth);
  });

  it('keeps counter-clockwise as seen from the eye counter-clockwise in NDC, mirrored by one negative half-size', () => {
    const ndcArea = (cam: CourseCamera): number => {
      // A triangle facing the eye, counter-clockwise seen from it: U then V from C + 5N.
      const tri = [[0, 0], [1, 0], [0, 1]].map(([a, b]) => [0, 1, 2].map((c) => cam.c[c] + 5 * cam.n[c] + a * cam.u[c] + b * cam.v[c]));
      const m = courseViewProjection(new Float64Array(16), cam, courseDepthRange(cam, tri.flat()));
      const ndc = tri.map((p) => {
        const clip = [0, 1, 3].map((r) => m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r]);
        return [clip[0] / clip[2], clip[1] / clip[2]];
      });
      return (ndc[1][0] - ndc[0][0]) * (ndc[2][1] - ndc[0][1]) - (ndc[1][1] - ndc[0][1]) * (ndc[2][0] - ndc[0][0]);
    };
    expect(ndcArea(oblique(1, 1, 1))).toBeGreaterThan(0);
    expect(ndcArea(oblique(1, -1, 1))).toBeLessThan(0);
    // "U, then V" from the eye of a camera looking down −z with +y up is a CCW triangle seen
    // from +z: the course's U really is the right-hand side.
    const down = parseCameraCfg('0 0 0\n0 0 -1\n0 1 0\n1 1 1\n');
    expect(down.u).toEqual([1, 0, 0]);
  });

  it('chooses near and far from the vertices used, and a near above 0 when they straddle the eye', () => {
    const cam = parseCameraCfg(sample('camera.cfg')); // z = 10 − world z
    const r = courseDepthRange(cam, [0, 0, 8, 0, 0, 5, 0, 0, -90, 0, 0, 100], [0, 1]);
    expect(r).toEqual({ near: expect.closeTo(2 * 0.999, 12), far: expect.closeTo(5 * 1.001, 12), behind: false });
    const straddle = courseDepthRange(cam, [0, 0, 9.99999, 0, 0, 11, 0, 0, -990]);
    expect(straddle.behind).toBe(false);
    expect(straddle.near).toBeCloseTo(1000 * 1e-4 * 0.999, 9);
    expect(straddle.far).toBeCloseTo(1000 * 1.001, 9);
  });

  // A camera at the origin looking along +z: a vertex's view depth is its z.
  const alongZ: CourseCamera = { c: [0, 0, 0], n: [0, 0, 1], v: [0, 1, 0], u: [-1, 0, 0], d: 1, hx: 1, hy: 1 };
  const at = (...zs: number[]) => zs.flatMap((z) => [0, 0, z]);
  const range = (near: number, far: number, behind: boolean) =>
    ({ near: expect.closeTo(near * 0.999, 12), far: expect.closeTo(far * 1.001, 12), behind });

  it('all in front, or all behind: the nearest vertex, however close, is the near plane', () => {
    expect(courseDepthRange(alongZ, at(0.001, 100))).toEqual(range(0.001, 100, false));
    expect(courseDepthRange(alongZ, at(-0.001, -100))).toEqual(range(0.001, 100, true));
  });

  it('a vertex on the eye\'s plane (z = 0) counts on neither side', () => {
    expect(courseDepthRange(alongZ, at(0, 2, 5))).toEqual(range(2, 5, false));
    expect(courseDepthRange(alongZ, at(0, -2, -5))).toEqual(range(2, 5, true));
  });

  it('nothing off the eye\'s plane, or no vertex: the default 0.01..100', () => {
    expect(courseDepthRange(alongZ, at(0, 0))).toEqual({ near: 0.01, far: 100, behind: false });
    expect(courseDepthRange(alongZ, [])).toEqual({ near: 0.01, far: 100, behind: false });
  });
});

describe('courseBasis', () => {
  it('V within 10⁻⁹ of N\'s direction, relative to its length, is parallel; a zero V too', () => {
    // V = (10⁻⁷, 0, 1000): 10⁻¹⁰ of its length off N, at any scale.
    expect(courseBasis([0, 0, 1], [1e-7, 0, 1000])).toBe('V parallel to N');
    expect(courseBasis([0, 0, 1], [1e-3, 0, 1000])).not.toBe('V parallel to N'); // 10⁻⁶ off
    expect(courseBasis([0, 0, 1], [0, 0, 0])).toBe('V parallel to N');
  });

  it('gives no −0 component for a camera written with round numbers', () => {
    // N = −x, V = −z: U = N × V = (0·(−1) − 0·0, 0·0 − (−1)·(−1), (−1)·0 − 0·0) = (−0, −1, −0) before cleaning.
    const b = courseBasis([-1, 0, 0], [0, 0, -1]);
    expect(b).toEqual({ n: [-1, 0, 0], v: [0, 0, -1], u: [0, -1, 0] });
    if (typeof b === 'string') return;
    for (const x of [...b.n, ...b.v, ...b.u]) expect(Object.is(x, -0)).toBe(false);
  });
});
