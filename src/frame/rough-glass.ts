// Rough glass (docs/rough-glass.md#the-gather) as both renderers approximate it: R̃ and B̃ at a glass pixel gathered
// from the sharp reflection (and the frame beyond the glass) around the pixel, each neighbour
// weighted by the share of the pixel's GGX lobe that lands on it at that neighbour's own distance
// from the glass ("scatter as gather"). The neighbours lie on rings doubling in radius, each ring
// read from the mip level its spacing leaves; the lobe's image on screen is an ellipse (stretched
// along the view's slope across the glass: the streaks of a wet road). Only numbers live here:
// the GLSL (shaders/glass.frag) and the software renderer (software/rough-gather.ts) each apply them.

export type RoughnessQuality = 'low' | 'medium' | 'high';

export const ROUGHNESS_QUALITIES: readonly RoughnessQuality[] = ['low', 'medium', 'high'];

export interface RoughGatherSettings {
  /** Neighbours on each ring. */
  angles: number;
  /** Added to each ring's mip level (negative: sharper reads than the ring's spacing). */
  lodBias: number;
}

/** Measured on the bench's rough floor (bench/rough-scene.ts); see BENCH.md. */
export const ROUGH_GATHER: Readonly<Record<RoughnessQuality, RoughGatherSettings>> = {
  low: { angles: 4, lodBias: -0.5 },
  medium: { angles: 8, lodBias: -1 },
  high: { angles: 16, lodBias: -2 },
};

/** The innermost ring's outer radius (texels); the centre sample stands for the disc of half that. */
export const ROUGH_FIRST_RING = 1;

/** The rings reach this many α along the lobe's longer axis (P(|slope| < 8α) = 64/65) at the background's scale. */
export const ROUGH_REACH = 8;

/** No more rings than this, however wide the lobe (a ring doubles the reach). */
export const ROUGH_MAX_RINGS = 12;

/** Rings for a lobe whose longer axis spans `texelsPerSlope` texels per unit of microfacet slope. */
export function roughRings(alpha: number, texelsPerSlope: number): number {
  // Stryker disable next-line ArithmeticOperator: ROUGH_FIRST_RING is 1 (frame-rules.test.ts pins it)
  const reach = (ROUGH_REACH * alpha * texelsPerSlope) / ROUGH_FIRST_RING;
  // Stryker disable next-line EqualityOperator: at reach 1 both give one ring (⌈log2 1⌉ + 1 = 1)
  const rings = reach > 1 ? Math.ceil(Math.log2(reach)) + 1 : 1;
  // Stryker disable next-line EqualityOperator: equal, both are the same number
  return rings < ROUGH_MAX_RINGS ? rings : ROUGH_MAX_RINGS;
}

/**
 * A surface's distance h ≥ 0 from the glass, stored in [0, 1] so that it survives 8-bit
 * storage and box-filtered mips: u = h / (1 + h); 1 = nothing there (the background).
 */
export function distanceCode(h: number): number {
  // Stryker disable next-line EqualityOperator: h = 0 gives 0 / 1 = 0 either way
  return h > 0 ? (Number.isFinite(h) ? h / (1 + h) : 1) : 0;
}
