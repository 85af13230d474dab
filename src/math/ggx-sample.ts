// GGX microfacet normals drawn by their density, and reflection about one (docs/rough-glass.md#ggx-microfacets): what the
// environment's prefiltered maps (math/prefilter.ts) and the float64 reference draw with. A module of its own so that
// the renderers' rough glass, which reads only the rest of math/ggx.ts, does not carry it. Tied down by tests/unit/ggx.test.ts.

type Out3 = Float64Array | number[];
type In3 = ArrayLike<number>;

/**
 * out = the microfacet normal for (ξ1, ξ2) ∈ [0, 1)², drawn with density D(m)·cosθm about the
 * unit normal `n` (the viewer's side): θm = atan(α·√(ξ1/(1 − ξ1))), φm = 2π·ξ2, measured from
 * a tangent frame of `n` (any orthonormal one: the density is symmetric about `n`).
 */
export function ggxNormal(out: Out3, alpha: number, xi1: number, xi2: number, n: In3): Out3 {
  const tan = alpha * Math.sqrt(xi1 / (1 - xi1));
  const cos = 1 / Math.sqrt(1 + tan * tan), sin = tan * cos;
  const phi = 2 * Math.PI * xi2;
  const cx = sin * Math.cos(phi), cy = sin * Math.sin(phi);
  // Tangent frame (Duff et al. 2017, "Building an orthonormal basis, revisited").
  const nx = n[0], ny = n[1], nz = n[2];
  // Stryker disable next-line EqualityOperator: at nz = 0 either sign gives an orthonormal frame (any one will do)
  const sign = nz >= 0 ? 1 : -1;
  const a = -1 / (sign + nz), b = nx * ny * a;
  const tx = 1 + sign * nx * nx * a, ty = sign * b, tz = -sign * nx;
  const bx = b, by = sign + ny * ny * a, bz = -ny;
  out[0] = cx * tx + cy * bx + cos * nx;
  out[1] = cx * ty + cy * by + cos * ny;
  out[2] = cx * tz + cy * bz + cos * nz;
  return out;
}

/** out = d − 2(d·m)m: the unit direction `d` reflected about the unit normal `m`. `out` may alias `d`. */
export function reflectAbout(out: Out3, d: In3, m: In3): Out3 {
  const k = 2 * (d[0] * m[0] + d[1] * m[1] + d[2] * m[2]);
  out[0] = d[0] - k * m[0];
  out[1] = d[1] - k * m[1];
  out[2] = d[2] - k * m[2];
  return out;
}
