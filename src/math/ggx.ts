// Rough glass (docs/rough-glass.md#ggx-microfacets): GGX's width and density, and the direction a view ray takes off a microfacet
// refracted through it into thin glass and out of a smooth face parallel to the plane (drawing a microfacet normal and
// reflecting about it: ggx-sample.ts). Shared by the float64 reference and the renderers' approximations: tied down by
// tests/unit/ggx.test.ts (the sampled density against D(m)·cosθm integrated by quadrature,
// Snell's law worked by hand).

type Out3 = Float64Array | number[];
type In3 = ArrayLike<number>;

/** α = roughness², clamped to [0, 1]: the GGX width of docs/rough-glass.md#ggx-microfacets. */
export function ggxAlpha(roughness: number): number {
  // Stryker disable next-line EqualityOperator: at 0 and at 1 both branches give the same value
  const r = roughness > 0 ? (roughness < 1 ? roughness : 1) : 0;
  return r * r;
}

/** GGX D(m) for a normal at θm from the macro normal: α² / (π·cos⁴θm·(α² + tan²θm)²). */
export function ggxD(alpha: number, cosTheta: number): number {
  if (cosTheta <= 0) return 0;
  const c2 = cosTheta * cosTheta, t2 = (1 - c2) / c2, a2 = alpha * alpha;
  const s = a2 + t2;
  return a2 / (Math.PI * c2 * c2 * s * s);
}

/**
 * Refraction of the unit direction `d` through a surface of unit normal `nf` facing against it
 * (d·nf < 0), from index 1 into index 1/eta·1 (eta = n₁/n₂): out, or false on total internal
 * reflection. `out` may alias `d`.
 */
function refract(out: Out3, d: In3, nf: In3, eta: number): boolean {
  const c = d[0] * nf[0] + d[1] * nf[1] + d[2] * nf[2];
  const k = 1 - eta * eta * (1 - c * c);
  // Stryker disable next-line EqualityOperator: k = 0 exactly is the critical angle: a ray along the surface, lost or grazing
  if (k < 0) return false;
  const s = eta * c + Math.sqrt(k);
  out[0] = eta * d[0] - s * nf[0];
  out[1] = eta * d[1] - s * nf[1];
  out[2] = eta * d[2] - s * nf[2];
  return true;
}

/**
 * The transmission direction through thin rough glass (docs/rough-glass.md#transmission): the unit view direction `d`
 * refracted into the glass (index `ior`) through the microfacet normal `m`, then out again
 * through a smooth face parallel to the plane (unit normal `n`, both on the viewer's side).
 * Returns false when the sample is lost: `m` faces away from `d` (d·m ≥ 0, the facet is not
 * seen), the ray turns back (it would not cross the glass), or it is totally reflected inside.
 * With m = n the result is d. `out` may alias `d`.
 */
export function refractThin(out: Out3, d: In3, m: In3, n: In3, ior: number): boolean {
  if (d[0] * m[0] + d[1] * m[1] + d[2] * m[2] >= 0) return false;
  // Stryker disable next-line BooleanLiteral: into the glass (eta = 1/ior ≤ 1; ior is 1..10) refraction is never total
  if (!refract(out, d, m, 1 / ior)) return false;
  // Stryker disable next-line EqualityOperator: out·n = 0 exactly is a ray along the glass: totally reflected at ior > 1, grazing at 1
  if (out[0] * n[0] + out[1] * n[1] + out[2] * n[2] >= 0) return false;
  return refract(out, out, n, ior);
}
