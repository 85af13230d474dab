// Texture-coordinate mappings (docs/scene-model.md#texture-mappings), written once: object-space position and normal in, UV out.
// The reference renderer calls these; the GPU shader mirrors them formula for formula.
// Shared by the reference (reference/surface-texture.ts) and the software renderer
// (software/object-shader.ts), the triplanar projections' axes and scale included (both take
// their texture derivatives from them): tied down by tests/unit/mapping.test.ts's hand-computed
// UVs and weights (k = 4 written out there, as shaders/standard.frag has it).
import type { Bounds } from './scene';

type V3 = ArrayLike<number>;
type Out = Float64Array | Float32Array | number[];

/**
 * Triplanar blend sharpness k: weight_i = |n_i|^k / Σ|n_j|^k. 4 keeps a visible but short
 * blend zone at 45° (k = 1 smears the three projections over most of the surface).
 */
export const TRIPLANAR_SHARPNESS = 4;

const TWO_PI = 2 * Math.PI;

/** The bounds' radius, or 1 for an empty/degenerate one, so the scales below stay finite. */
export const boundsScale = (bounds: Bounds): number => (bounds.radius > 0 ? bounds.radius : 1);

/** Object units to the triplanar projections' UV units, 1/2r: also their UVs' constant derivatives. */
export const triplanarScale = (bounds: Bounds): number => 1 / (2 * boundsScale(bounds));

/**
 * The object axes triplanar projection i reads as u and v: along X (z, y), along Y (x, z),
 * along Z (x, y). Projection i's u is ½ + (q[TRIPLANAR_U[i]] − c)·s, its v likewise.
 */
export const TRIPLANAR_U: readonly number[] = [2, 0, 0];
export const TRIPLANAR_V: readonly number[] = [1, 2, 1];

/**
 * Cylindrical, about the axis through the bounds' centre c parallel to object +Y (r = the
 * bounds' radius):
 *   u = ½ + atan2(x − c.x, z − c.z) / 2π      (u = ½ facing +Z, growing towards +X; the seam at −Z)
 *   v = ½ + (y − c.y) / 2r                    (v = 0 at the bottom of the bounds, 1 at the top)
 * On the axis itself atan2(0, 0) = 0 gives u = ½.
 */
export function cylindricalUV(out: Out, q: V3, bounds: Bounds): Out {
  const c = bounds.center;
  out[0] = 0.5 + Math.atan2(q[0] - c[0], q[2] - c[2]) / TWO_PI;
  out[1] = 0.5 + (q[1] - c[1]) / (2 * boundsScale(bounds));
  return out;
}

/**
 * Spherical: the default sphere's UV (docs/default-scene.md#texture-coordinates) applied to the unit direction d = (q − c)/|q − c| from the
 * bounds' centre c:
 *   u = ½ + atan2(d.x, d.z) / 2π,   v = acos(−d.y) / π   (v = 0 at the bottom pole)
 * A built-in sphere centred on the origin gets exactly its own UVs. At q = c, d = (0, 0, 0)
 * gives u = ½, v = ½.
 */
export function sphericalUV(out: Out, q: V3, bounds: Bounds): Out {
  const c = bounds.center;
  const dx = q[0] - c[0], dy = q[1] - c[1], dz = q[2] - c[2];
  const len = Math.hypot(dx, dy, dz);
  const ny = len > 0 ? dy / len : 0;
  out[0] = 0.5 + Math.atan2(dx, dz) / TWO_PI;
  out[1] = Math.acos(Math.max(-1, Math.min(1, -ny))) / Math.PI;
  return out;
}

/**
 * Triplanar: three planar projections of the bounds' cube [c − r, c + r]³ onto [0, 1]²,
 * blended by the object-space unit normal n:
 *   weights w_i = |n_i|^k / (|n_x|^k + |n_y|^k + |n_z|^k), k = TRIPLANAR_SHARPNESS
 *   along X (uvs[0], uvs[1]) = (½ + (z − c.z)/2r, ½ + (y − c.y)/2r)
 *   along Y (uvs[2], uvs[3]) = (½ + (x − c.x)/2r, ½ + (z − c.z)/2r)
 *   along Z (uvs[4], uvs[5]) = (½ + (x − c.x)/2r, ½ + (y − c.y)/2r)
 * (the axes are TRIPLANAR_U, TRIPLANAR_V), texture = Σ w_i · tex(uv_i). No sign flips per side:
 * the +X and −X faces show the same, mirrored-looking image, which a checker does not reveal and
 * keeps the formula short.
 * A zero normal gives equal weights.
 */
export function triplanarUV(weights: Out, uvs: Out, q: V3, n: V3, bounds: Bounds): void {
  const c = bounds.center;
  const s = triplanarScale(bounds);
  const k = TRIPLANAR_SHARPNESS;
  const wx = Math.abs(n[0]) ** k, wy = Math.abs(n[1]) ** k, wz = Math.abs(n[2]) ** k;
  const sum = wx + wy + wz;
  if (sum > 0) {
    weights[0] = wx / sum; weights[1] = wy / sum; weights[2] = wz / sum;
  } else {
    weights[0] = weights[1] = weights[2] = 1 / 3;
  }
  for (let i = 0; i < 3; i++) {
    const a = TRIPLANAR_U[i], b = TRIPLANAR_V[i];
    uvs[2 * i] = 0.5 + (q[a] - c[a]) * s;
    uvs[2 * i + 1] = 0.5 + (q[b] - c[b]) * s;
  }
}
