// An environment made ready for the renderers (docs/pbr.md#prefiltered-maps): the split sum's prefiltered light
// (math/split-sum.ts) stored as equirectangular maps, one per roughness level (made by math/prefilter.ts).
// The last level is roughness 1, which is also the irradiance: P(n, 1) = E(n)/π, so the diffuse lobe reads it too.
// Read here: a bilinear lookup in each of the two levels about a roughness, mixed; and the split sum from them.
// Tied down by tests/unit/environment-maps.test.ts (the read worked by hand, the split sum in a furnace and against splitSum()).
import { dfgLookup } from './dfg';
import { dominantDirection } from './split-sum';

/** One equirectangular map: `width` = 2·`height` texels, RGB, row 0 at the zenith (+y), column 0 at azimuth −π (φ = atan2(x, z)). */
export interface EquirectMap {
  width: number;
  height: number;
  rgb: Float32Array;
}

/** The prefiltered levels of one environment: level k at roughness (k/(levels.length − 1))^gamma. */
export interface EnvironmentMaps {
  levels: readonly EquirectMap[];
  gamma: number;
}

/**
 * out = the map's bilinear read toward the unit direction (x, y, z), at texel centres: wrapping in azimuth, the first and last rows
 * held beyond their centres (toward the poles). What a GPU's LINEAR filter with REPEAT in u and CLAMP_TO_EDGE in v reads.
 */
export function sampleEquirect(out: Float64Array, map: EquirectMap, x: number, y: number, z: number): Float64Array {
  const { width, height, rgb: t } = map;
  // Stryker disable next-line ArithmeticOperator: − π shifts u by one whole turn (width texels), which the wrap below takes back
  const u = ((Math.atan2(x, z) + Math.PI) / (2 * Math.PI)) * width - 0.5;
  // y held to [−1, 1] (a direction a rounding past unit length would make acos NaN).
  // Stryker disable next-line EqualityOperator: at y = ±1 the clamp returns y itself either way
  const v = (Math.acos(y < -1 ? -1 : y > 1 ? 1 : y) / Math.PI) * height - 0.5;
  const i0 = Math.floor(u), fu = u - i0;
  // Stryker disable next-line EqualityOperator: at 0 and at height − 1 the clamp returns v itself either way
  const vv = v < 0 ? 0 : v > height - 1 ? height - 1 : v;
  const j0 = Math.min(height - 2, Math.floor(vv)), fv = vv - j0;
  const a = ((i0 % width) + width) % width, b = (a + 1) % width;
  const r0 = j0 * width, r1 = r0 + width;
  // Stryker disable next-line EqualityOperator: c = 3 writes out[3], past the end of its 3 elements: dropped
  for (let c = 0; c < 3; c++) {
    const upper = t[3 * (r0 + a) + c] * (1 - fu) + t[3 * (r0 + b) + c] * fu;
    const lower = t[3 * (r1 + a) + c] * (1 - fu) + t[3 * (r1 + b) + c] * fu;
    out[c] = upper * (1 - fv) + lower * fv;
  }
  return out;
}

const lo = new Float64Array(3), hi = new Float64Array(3);

/**
 * out = the prefiltered light toward the unit direction (x, y, z) at roughness r (clamped to [0, 1]): the two levels about
 * r^(1/gamma)·(levels − 1), each read bilinearly, mixed linearly. At roughness 1 it is E/π, the irradiance over π.
 */
export function prefilteredAt(out: Float64Array, maps: EnvironmentMaps, x: number, y: number, z: number, roughness: number): Float64Array {
  // Stryker disable next-line EqualityOperator: at 0 and at 1 the clamp returns the roughness itself either way
  const n = maps.levels.length, p = (roughness < 0 ? 0 : roughness > 1 ? 1 : roughness) ** (1 / maps.gamma) * (n - 1);
  const k = Math.min(n - 2, Math.floor(p)), f = p - k;
  sampleEquirect(lo, maps.levels[k], x, y, z);
  sampleEquirect(hi, maps.levels[k + 1], x, y, z);
  // Stryker disable next-line EqualityOperator: c = 3 writes out[3], past the end of its 3 elements: dropped
  for (let c = 0; c < 3; c++) out[c] = lo[c] + (hi[c] - lo[c]) * f;
  return out;
}

const ab = new Float64Array(2), spec = new Float64Array(3), diff = new Float64Array(3), refl = new Float64Array(3), away = new Float64Array(3);

/**
 * out += intensity × the split sum of math/split-sum.ts read from the maps and the table: prefilteredAt(R, r)·(F0·A + B) +
 * c_diff·(1 − F0)·prefilteredAt(n, 1), R the lobe's dominant direction, (A, B) = dfgLookup(n·v, r); for unit n and v toward the
 * viewer. Seen from behind (n·v ≤ 0): nothing.
 */
export function addEnvironment(
  out: Float64Array, maps: EnvironmentMaps, table: ArrayLike<number>, intensity: number,
  base: ArrayLike<number>, metallic: number, roughness: number, n: ArrayLike<number>, v: ArrayLike<number>,
): void {
  const nv = n[0] * v[0] + n[1] * v[1] + n[2] * v[2];
  if (!(nv > 0)) return;
  away[0] = -v[0]; away[1] = -v[1]; away[2] = -v[2];
  dominantDirection(refl, away, n, roughness);
  prefilteredAt(spec, maps, refl[0], refl[1], refl[2], roughness);
  prefilteredAt(diff, maps, n[0], n[1], n[2], 1);
  dfgLookup(ab, table, nv, roughness);
  // Stryker disable next-line EqualityOperator: c = 3 adds to out[3], past the end of its 3 elements: dropped
  for (let c = 0; c < 3; c++) {
    // 0.04: a dielectric's F0 (DIELECTRIC_F0 of math/pbr.ts, not imported: this file goes into WebGL's environment chunk alone).
    const f0 = 0.04 * (1 - metallic) + base[c] * metallic;
    out[c] += intensity * (spec[c] * (f0 * ab[0] + ab[1]) + base[c] * (1 - metallic) * (1 - f0) * diff[c]);
  }
}
