// docs/rough-glass.md#reference-monte-carlo in the reference: at a glass hit, R̃ and B̃ as means over the sample's microfacet
// normals of what arrives at P along each reflected and each transmitted direction.
import { refractThin } from '../math/ggx';
import { ggxNormal, reflectAbout } from '../math/ggx-sample';
import type { Plane } from '../math/mirror';
import { Ray } from './ray';
import type { SurfaceHit } from './surface-hit';

/** The microfacet normals of one sample: (xi1[i], xi2[i]) for i in [first, first + count). */
export interface Microfacets {
  xi1: Float64Array;
  xi2: Float64Array;
  first: number;
  count: number;
}

/** The two paths the sample tracer traces for a rough sample. */
export interface RoughPaths {
  /** What pass 1 sees along `ray` (the eye's side, clipped at the plane), shaded towards `eye`. */
  reflectedAlong(ray: Ray, eye: Float64Array, out: Float64Array): void;
  /** What lies past depth `tMin` along `ray` (the far side), shaded towards `eye`. */
  transmittedAlong(ray: Ray, tMin: number, level: number, eye: Float64Array, out: Float64Array): void;
}

export class RoughGlass {
  private readonly ray = new Ray();
  private readonly d = new Float64Array(3);
  private readonly n = new Float64Array(3);
  private readonly m = new Float64Array(3);
  private readonly sum = new Float64Array(3);
  private readonly one = new Float64Array(3);

  /**
   * Overwrites `reflection` and `behind` (the smooth R and B of `glass`, hit by `ray`) with R̃
   * and B̃. A reflected direction into the far side and a transmitted sample that is lost
   * (refractThin) are dropped; when none is left the smooth value stays. Each sample ray starts
   * t_g·|D| back from P along its direction, so its t is on the primary ray's scale (near and
   * far apply as to the mirror ray), and shading sees V = −direction. Footprints (texture
   * filtering) are the smooth paths': the mirrored ray's for R̃, the primary's for B̃.
   */
  apply(
    paths: RoughPaths, ray: Ray, mirrored: Ray, glass: SurfaceHit, level: number, side: number, plane: Plane,
    alpha: number, ior: number, mf: Microfacets, reflection: Float64Array, behind: Float64Array,
  ): void {
    const D = ray.direction, len = Math.hypot(D[0], D[1], D[2]), d = this.d, n = this.n;
    // Stryker disable next-line EqualityOperator: k = 3 writes past the end of d and n (Float64Array(3)): dropped
    for (let k = 0; k < 3; k++) { d[k] = D[k] / len; n[k] = side * plane[k]; }
    const m = this.m, r = this.ray, sum = this.sum, one = this.one, tg = glass.t;
    for (let pass = 0; pass < 2; pass++) {
      sum.fill(0);
      let kept = 0;
      const src = pass === 0 ? mirrored : ray;
      for (let i = mf.first; i < mf.first + mf.count; i++) {
        ggxNormal(m, alpha, mf.xi1[i], mf.xi2[i], n);
        const dir = r.direction;
        if (pass === 0) {
          reflectAbout(dir, d, m);
          if (dir[0] * n[0] + dir[1] * n[1] + dir[2] * n[2] <= 0) continue;
        } else if (!refractThin(dir, d, m, n, ior)) continue;
        // Stryker disable next-line EqualityOperator: k = 3 writes past the end of the sample ray's three-element arrays: dropped
        for (let k = 0; k < 3; k++) {
          dir[k] *= len;
          r.origin[k] = glass.p[k] - tg * dir[k];
          r.ddx[k] = src.ddx[k]; r.ddy[k] = src.ddy[k]; r.odx[k] = src.odx[k]; r.ody[k] = src.ody[k];
        }
        if (pass === 0) paths.reflectedAlong(r, r.origin, one);
        else paths.transmittedAlong(r, tg, level, r.origin, one);
        sum[0] += one[0]; sum[1] += one[1]; sum[2] += one[2];
        kept++;
      }
      if (kept === 0) continue;
      const out = pass === 0 ? reflection : behind;
      for (let k = 0; k < 3; k++) out[k] = sum[k] / kept;
    }
  }
}
