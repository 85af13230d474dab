// Tone mapping, once, in linear light before the sRGB encode (docs/pbr.md#tone-mapping): Khronos
// PBR Neutral (its specification's constants), and ACES as Stephen Hill's fit of the RRT and ODT
// (the glTF Sample Viewer's "ACES Hill"; three.js's ACESFilmic is the same fit after an exposure of
// 1/0.6). Shared by the float64 reference and the software renderer; the GLSL writes the same.
// Tied down by tests/unit/tone-map.test.ts (points worked by hand).

export type ToneMapping = 'neutral' | 'aces' | 'none';
export const TONE_MAPPINGS: readonly ToneMapping[] = ['neutral', 'aces', 'none'];

/** Khronos PBR Neutral: where the brightest channel passes 0.76 it is compressed toward 1, and the colour toward white. */
const START_COMPRESSION = 0.8 - 0.04;
const DESATURATION = 0.15;

/** out = PBR Neutral of the linear colour (r, g, b). */
export function toneMapNeutral(out: Float64Array | number[], r: number, g: number, b: number): Float64Array | number[] {
  const x = Math.min(r, g, b);
  // Stryker disable next-line EqualityOperator: at x = 0.08 both give 0.04 (the curve is continuous there)
  const offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
  r -= offset; g -= offset; b -= offset;
  const peak = Math.max(r, g, b);
  // Stryker disable next-line EqualityOperator: at the start exactly the compression gives the colour itself (new peak 0.76, mix 0)
  if (peak < START_COMPRESSION) {
    out[0] = r; out[1] = g; out[2] = b;
    return out;
  }
  const d = 1 - START_COMPRESSION;
  const newPeak = 1 - (d * d) / (peak + d - START_COMPRESSION);
  const k = newPeak / peak;
  const t = 1 - 1 / (DESATURATION * (peak - newPeak) + 1);
  out[0] = r * k * (1 - t) + newPeak * t;
  out[1] = g * k * (1 - t) + newPeak * t;
  out[2] = b * k * (1 - t) + newPeak * t;
  return out;
}

// Hill's fit: linear sRGB into the RRT's space (rows), the fitted curve, back out, clamped to [0, 1].
const ACES_IN = [0.59719, 0.35458, 0.04823, 0.07600, 0.90834, 0.01566, 0.02840, 0.13383, 0.83777];
const ACES_OUT = [1.60475, -0.53108, -0.07367, -0.10208, 1.10813, -0.00605, -0.00327, -0.07276, 1.07602];

/** The RRT + ODT fit of one channel: (v(v + 0.0245786) − 0.000090537) / (v(0.983729v + 0.4329510) + 0.238081). */
export function acesCurve(v: number): number {
  return (v * (v + 0.0245786) - 0.000090537) / (v * (0.983729 * v + 0.432951) + 0.238081);
}

export function toneMapAces(out: Float64Array | number[], r: number, g: number, b: number): Float64Array | number[] {
  const u0 = acesCurve(ACES_IN[0] * r + ACES_IN[1] * g + ACES_IN[2] * b);
  const u1 = acesCurve(ACES_IN[3] * r + ACES_IN[4] * g + ACES_IN[5] * b);
  const u2 = acesCurve(ACES_IN[6] * r + ACES_IN[7] * g + ACES_IN[8] * b);
  for (let c = 0; c < 3; c++) {
    const v = ACES_OUT[3 * c] * u0 + ACES_OUT[3 * c + 1] * u1 + ACES_OUT[3 * c + 2] * u2;
    // Stryker disable next-line EqualityOperator: at 0 and 1 the clamp returns v itself either way
    out[c] = v < 0 ? 0 : v > 1 ? 1 : v;
  }
  return out;
}

export function toneMap(mode: ToneMapping, out: Float64Array | number[], r: number, g: number, b: number): Float64Array | number[] {
  if (mode === 'neutral') return toneMapNeutral(out, r, g, b);
  if (mode === 'aces') return toneMapAces(out, r, g, b);
  out[0] = r; out[1] = g; out[2] = b;
  return out;
}
