// Rough glass in the reference (src/reference/rough-glass.ts): which microfacet samples it traces, along which rays
// (directions reflected or refracted by hand for GGX normals at α = 1), and the means it leaves, with recorded paths.
import { describe, expect, it } from 'vitest';
import { refractThin } from '../../src/math/ggx';
import { ggxNormal, reflectAbout } from '../../src/math/ggx-sample';
import { Ray } from '../../src/reference/ray';
import { RoughGlass, type Microfacets, type RoughPaths } from '../../src/reference/rough-glass';
import { SurfaceHit } from '../../src/reference/surface-hit';
import type { Plane } from '../../src/math/mirror';
import { expectClose } from './helpers/math';

interface Call {
  pass: 'reflected' | 'transmitted'; origin: number[]; direction: number[]; eyeIsOrigin: boolean; diffs: number[][]; tMin?: number; level?: number;
}

/** Records every ray it is asked along and answers with the next of its colours. */
class Recorder implements RoughPaths {
  readonly calls: Call[] = [];
  constructor(private readonly reflected: number[][], private readonly transmitted: number[][]) {}

  private record(pass: Call['pass'], ray: Ray, eye: Float64Array, extra: Partial<Call>): void {
    const diffs = [ray.ddx, ray.ddy, ray.odx, ray.ody].map((a) => [...a]);
    this.calls.push({ pass, origin: [...ray.origin], direction: [...ray.direction], eyeIsOrigin: eye === ray.origin, diffs, ...extra });
  }

  reflectedAlong(ray: Ray, eye: Float64Array, out: Float64Array): void {
    this.record('reflected', ray, eye, {});
    out.set(this.reflected.shift()!);
  }

  transmittedAlong(ray: Ray, tMin: number, level: number, eye: Float64Array, out: Float64Array): void {
    this.record('transmitted', ray, eye, { tMin, level });
    out.set(this.transmitted.shift()!);
  }
}

const R50 = Math.sqrt(50);
const Z0: Plane = [0, 0, 1, 0];

/**
 * The primary ray along d = (1, 0, −1)/√2 scaled to length 2, hitting the glass z = 0 at P = (1, 2, 0) at t_g = 1.5;
 * the mirrored ray with differentials of its own. Microfacets (ξ1, ξ2) in slots 1..count, junk around them.
 */
function setUp(samples: [number, number][], side = 1) {
  const ray = new Ray(), mirrored = new Ray(), glass = new SurfaceHit();
  const s = side * Math.SQRT2; // |D| = 2
  ray.direction.set([Math.SQRT2, 0, -s]);
  ray.origin.set([1 - 1.5 * Math.SQRT2, 2, 1.5 * s]);
  ray.ddx.set([1, 2, 3]); ray.ddy.set([4, 5, 6]); ray.odx.set([7, 8, 9]); ray.ody.set([10, 11, 12]);
  mirrored.ddx.set([-1, -2, -3]); mirrored.ddy.set([-4, -5, -6]); mirrored.odx.set([-7, -8, -9]); mirrored.ody.set([-10, -11, -12]);
  glass.t = 1.5;
  glass.p.set([1, 2, 0]);
  const n = samples.length;
  const mf: Microfacets = {
    xi1: new Float64Array([9, ...samples.map((x) => x[0]), 9]), xi2: new Float64Array([9, ...samples.map((x) => x[1]), 9]), first: 1, count: n,
  };
  return { ray, mirrored, glass, mf, side };
}

/** What the smooth paths left: kept where no sample survives. */
const smooth = () => ({ reflection: new Float64Array([0.5, 0.6, 0.7]), behind: new Float64Array([0.1, 0.2, 0.3]) });

describe('RoughGlass.apply', () => {
  // At α = 1 and ξ1 = 0.2, tan θm = √(0.2/0.8) = ½: m = (cos φ, sin φ, 2)/√5 about n = +z (tangents +x, +y), φ = 2π·ξ2.
  // ξ1 = 0.8: tan θm = 2, m = (2 cos φ, 2 sin φ, 1)/√5.
  // d = (1, 0, −1)/√2 = (5, 0, −5)/√50. Reflected: d − 2(d·m)m.
  //   (0.2, 0.25): m = (0, 1, 2)/√5, d·m = −2/√10: (5, 4, 3)/√50, kept.
  //   (0.8, 0): m = (2, 0, 1)/√5, d·m = +1/√10: z = −5/√50 − 2/√50 < 0, into the far side: dropped; refraction too (d·m ≥ 0).
  //   (0.8, 0.5): m = (−2, 0, 1)/√5, d·m = −3/√10: (−7, 0, 1)/√50, kept; its refraction is totally reflected at the
  //   smooth face: dropped.
  // Refracted through (0, 1, 2)/√5 into index 1.5 (η = 2/3, c = d·m = −2/√10) and out of the face z = 0: x stays 1/√2,
  //   y = −1.5·s/√5 with s = η·c + √(1 − η²(1 − c²)), z = −√(1 − x² − y²).
  const s = (2 / 3) * (-2 / Math.sqrt(10)) + Math.sqrt(1 - (4 / 9) * 0.6);
  const ty = (-1.5 * s) / Math.sqrt(5);
  const transmitted = [Math.SQRT1_2, ty, -Math.sqrt(0.5 - ty * ty)];

  it('traces the kept samples only, each at length |D| from P − t_g·direction, and leaves their means', () => {
    const { ray, mirrored, glass, mf, side } = setUp([[0.2, 0.25], [0.8, 0], [0.8, 0.5]]);
    const paths = new Recorder([[10, 20, 30], [30, 40, 50]], [[1, 2, 3]]);
    const { reflection, behind } = smooth();
    new RoughGlass().apply(paths, ray, mirrored, glass, 3, side, Z0, 1, 1.5, mf, reflection, behind);
    expect(paths.calls.map((c) => c.pass)).toEqual(['reflected', 'reflected', 'transmitted']);
    const [r1, r2, t1] = paths.calls;
    expectClose(r1.direction, [10 / R50, 8 / R50, 6 / R50]);
    expectClose(r2.direction, [-14 / R50, 0, 2 / R50]);
    expectClose(t1.direction, transmitted.map((x) => 2 * x));
    for (const c of paths.calls) {
      expectClose(c.origin, [1 - 1.5 * c.direction[0], 2 - 1.5 * c.direction[1], -1.5 * c.direction[2]]);
      expect(c.eyeIsOrigin).toBe(true);
    }
    // The mirrored ray's footprint for R̃, the primary's for B̃.
    for (const c of [r1, r2]) expect(c.diffs).toEqual([[-1, -2, -3], [-4, -5, -6], [-7, -8, -9], [-10, -11, -12]]);
    expect(t1.diffs).toEqual([[1, 2, 3], [4, 5, 6], [7, 8, 9], [10, 11, 12]]);
    expect([t1.tMin, t1.level]).toEqual([1.5, 3]);
    expect([...reflection]).toEqual([20, 30, 40]);
    expect([...behind]).toEqual([1, 2, 3]);
  });

  it('a sample lost both ways leaves the smooth values as they were', () => {
    const { ray, mirrored, glass, mf, side } = setUp([[0.8, 0]]);
    const paths = new Recorder([], []);
    const { reflection, behind } = smooth();
    new RoughGlass().apply(paths, ray, mirrored, glass, 0, side, Z0, 1, 1.5, mf, reflection, behind);
    expect(paths.calls).toEqual([]);
    expect([...reflection]).toEqual([0.5, 0.6, 0.7]);
    expect([...behind]).toEqual([0.1, 0.2, 0.3]);
  });

  it('only the reflection kept: the transmission keeps its smooth value', () => {
    const { ray, mirrored, glass, mf, side } = setUp([[0.8, 0.5]]);
    const paths = new Recorder([[2, 4, 8]], []);
    const { reflection, behind } = smooth();
    new RoughGlass().apply(paths, ray, mirrored, glass, 0, side, Z0, 1, 1.5, mf, reflection, behind);
    expect(paths.calls.map((c) => c.pass)).toEqual(['reflected']);
    expect([...reflection]).toEqual([2, 4, 8]);
    expect([...behind]).toEqual([0.1, 0.2, 0.3]);
  });

  it('means over several kept samples of each path', () => {
    // (0.2, 0.25) and (0.2, 0.75) = m (0, ∓1, 2)/√5: both kept both ways, mirror images in y.
    const { ray, mirrored, glass, mf, side } = setUp([[0.2, 0.25], [0.2, 0.75]]);
    const paths = new Recorder([[1, 1, 1], [0, 2, 4]], [[3, 0, 0], [0, 0, 6]]);
    const { reflection, behind } = smooth();
    new RoughGlass().apply(paths, ray, mirrored, glass, 1, side, Z0, 1, 1.5, mf, reflection, behind);
    const dirs = paths.calls.map((c) => c.direction);
    expectClose(dirs[1], [10 / R50, -8 / R50, 6 / R50]);
    expectClose(dirs[3], [2 * transmitted[0], -2 * transmitted[1], 2 * transmitted[2]]);
    expect([...reflection]).toEqual([0.5, 1.5, 2.5]);
    expect([...behind]).toEqual([1.5, 0, 3]);
  });

  it('from the glass\'s other side (side −1) the normals are about −z', () => {
    // d = (1, 0, 1)/√2, n = −z: tangents (1, 0, 0) and (0, −1, 0), so (0.2, 0.25) gives m = (0, −1, −2)/√5 and the
    // reflection (5, −4, −3)/√50, on the eye's side (−z).
    const { ray, mirrored, glass, mf, side } = setUp([[0.2, 0.25]], -1);
    const paths = new Recorder([[1, 2, 3]], [[4, 5, 6]]);
    const { reflection, behind } = smooth();
    new RoughGlass().apply(paths, ray, mirrored, glass, 0, side, Z0, 1, 1.5, mf, reflection, behind);
    expect(paths.calls.map((c) => c.pass)).toEqual(['reflected', 'transmitted']);
    expectClose(paths.calls[0].direction, [10 / R50, -8 / R50, -6 / R50]);
    expectClose(paths.calls[1].direction, [2 * transmitted[0], -2 * transmitted[1], -2 * transmitted[2]]);
    expect([...reflection, ...behind]).toEqual([1, 2, 3, 4, 5, 6]);
  });

  it('a reflection exactly along the glass is dropped', () => {
    // α = 0.75, ξ = (0.5, 0): tan θm = 0.75, m = (0.6, 0, 0.8); d = (7, 0, −24)/25 (D twice that): d·m = (4.2 − 19.2)/25 = −0.6,
    // reflected d + 1.2·m = (0.28 + 0.72, 0, −0.96 + 0.96) = (1, 0, 0), in the plane (exactly, in float64 too).
    const ray = new Ray(), glass = new SurfaceHit();
    ray.direction.set([0.56, 0, -1.92]);
    glass.t = 1;
    const paths = new Recorder([], [[1, 1, 1]]);
    const { reflection, behind } = smooth();
    const mf: Microfacets = { xi1: new Float64Array([0.5]), xi2: new Float64Array([0]), first: 0, count: 1 };
    new RoughGlass().apply(paths, ray, new Ray(), glass, 0, 1, Z0, 0.75, 1.5, mf, reflection, behind);
    expect(paths.calls.map((c) => c.pass)).toEqual(['transmitted']);
    expect([...reflection]).toEqual([0.5, 0.6, 0.7]);
    expect([...behind]).toEqual([1, 1, 1]);
  });

  it('an oblique glass: exactly the samples whose reflection leaves on the eye\'s side, and whose refraction gets through', () => {
    // The plane 0.48x + 0.6y + 0.64z = 1 seen from its + side, D = (1, −2, −3)/2, α = 0.8, ior 1.3, a 12×12 grid of ξ.
    // What each sample should do comes from the math of ggx.ts (tests/unit/ggx.test.ts), applied here to each normal.
    const plane: Plane = [0.48, 0.6, 0.64, -1];
    const ray = new Ray(), mirrored = new Ray(), glass = new SurfaceHit();
    ray.direction.set([0.5, -1, -1.5]);
    glass.t = 1.25;
    glass.p.set([0.5, 1, 0.25]);
    const xi1: number[] = [], xi2: number[] = [];
    for (let i = 0; i < 12; i++) for (let j = 0; j < 12; j++) { xi1.push((i + 0.5) / 12); xi2.push((j + 0.5) / 12); }
    const len = Math.hypot(0.5, -1, -1.5), d = [0.5 / len, -1 / len, -1.5 / len], n = [0.48, 0.6, 0.64];
    const reflected: number[][] = [], transmitted: number[][] = [];
    for (let i = 0; i < xi1.length; i++) {
      const m = ggxNormal([0, 0, 0], 0.8, xi1[i], xi2[i], n);
      const r = [0, 0, 0];
      reflectAbout(r, d, m);
      if (r[0] * n[0] + r[1] * n[1] + r[2] * n[2] > 0) reflected.push(r.map((x) => x * len));
      const t = [0, 0, 0];
      if (refractThin(t, d, m, n, 1.3)) transmitted.push(t.map((x) => x * len));
    }
    // Both kinds of sample are there: some lost each way.
    expect(reflected.length).toBeGreaterThan(20);
    expect(reflected.length).toBeLessThan(144);
    expect(transmitted.length).toBeGreaterThan(20);
    expect(transmitted.length).toBeLessThan(144);
    const paths = new Recorder(reflected.map((_, i) => [i, 1, 0]), transmitted.map((_, i) => [0, 2, i]));
    // Four-element colours: only the first three are written.
    const reflection = new Float64Array([0, 0, 0, 7]), behind = new Float64Array([0, 0, 0, 7]);
    const mf: Microfacets = { xi1: new Float64Array(xi1), xi2: new Float64Array(xi2), first: 0, count: 144 };
    new RoughGlass().apply(paths, ray, mirrored, glass, 0, 1, plane, 0.8, 1.3, mf, reflection, behind);
    const got = (pass: Call['pass']) => paths.calls.filter((c) => c.pass === pass).map((c) => c.direction);
    expect(got('reflected').length).toBe(reflected.length);
    got('reflected').forEach((dir, i) => expectClose(dir, reflected[i], 1e-12));
    expect(got('transmitted').length).toBe(transmitted.length);
    got('transmitted').forEach((dir, i) => expectClose(dir, transmitted[i], 1e-12));
    // Means of 0..k−1: (k − 1)/2.
    expectClose(reflection, [(reflected.length - 1) / 2, 1, 0, 7]);
    expectClose(behind, [0, 2, (transmitted.length - 1) / 2, 7]);
  });
});
