// The prefiltered maps of an environment (docs/pbr.md#prefiltered-maps), read by math/environment-maps.ts: eight levels of
// roughness, each an equirectangular map as fine as its lobe needs, each texel the lobe's mean about its centre
// (prefiltered() of math/split-sum.ts). Made once per environment (frame/environment-light.ts); the code only a scene with an
// environment needs. Tied down by tests/unit/environment-maps.test.ts (widths by hand, texels against prefiltered()).
import type { EnvironmentMaps, EquirectMap } from './environment-maps';
import { prefiltered, type RadianceFn } from './split-sum';

/** Level k's roughness of `levels`: (k/(levels − 1))^gamma. */
export const levelRoughness = (k: number, levels: number, gamma: number): number => (k / (levels - 1)) ** gamma;

export interface EnvironmentMapOptions {
  /** Roughness levels, at least 2 (k/(levels − 1)). Default 8. */
  levels?: number;
  /** The finest level's width; a rough level is as wide as its lobe needs (levelWidth), at least `minWidth`. Default 256. */
  width?: number;
  /** The narrowest a level gets. Default 32. */
  minWidth?: number;
  /**
   * Hammersley points per level (level 0, the mirror, reads the environment once per texel): shared among its texels, so that a
   * small rough level takes many per texel. Default 2²⁰.
   */
  budget?: number;
  /** Roughness of level k is (k/(levels − 1))^gamma: levels closer together where lobes are narrow. Default 2. */
  gamma?: number;
}

/**
 * How wide level k's map is: a texel about a quarter of its lobe's width. The lobe of l about R spreads about 2α radians (h spreads
 * α, l twice), so 2π/w ≤ α/2 gives w ≥ 4π/α: the power of two at or above it, within [minWidth, width].
 */
export function levelWidth(roughness: number, width: number, minWidth: number): number {
  const alpha = roughness * roughness;
  // Stryker disable next-line ConditionalExpression: a shortcut: at α = 0, 4π/α is Infinity and the loop doubles w to `width` anyway
  if (alpha === 0) return width;
  let w = minWidth;
  // Stryker disable next-line ConditionalExpression,EqualityOperator: past `width` the min below takes it back; 4π/α a power of two exactly never happens
  while (w < width && w < (4 * Math.PI) / alpha) w *= 2;
  return Math.min(w, width);
}

/** out = the unit direction through the centre of texel (i, j) of a `width` × `height` map. */
export function texelDirection(out: Float64Array, i: number, j: number, width: number, height: number): Float64Array {
  // Stryker disable next-line ArithmeticOperator: + π is φ one whole turn on, the same direction
  const phi = ((i + 0.5) / width) * 2 * Math.PI - Math.PI, theta = ((j + 0.5) / height) * Math.PI;
  const s = Math.sin(theta);
  out[0] = s * Math.sin(phi); out[1] = Math.cos(theta); out[2] = s * Math.cos(phi);
  return out;
}

const dir = new Float64Array(3), rgb = new Float64Array(3);

/** The prefiltered maps of `env` (see EnvironmentMapOptions for the defaults), made at once. */
export function makeEnvironmentMaps(env: RadianceFn, options: EnvironmentMapOptions = {}): EnvironmentMaps {
  const steps = environmentMapSteps(env, options);
  for (;;) {
    const step = steps.next();
    if (step.done) return step.value;
  }
}

/** makeEnvironmentMaps a row at a time: each next() makes one row of one level; the last returns the maps (frame/environment-light.ts spreads them over a page's tasks). */
export function* environmentMapSteps(env: RadianceFn, options: EnvironmentMapOptions = {}): Generator<void, EnvironmentMaps, void> {
  const count = Math.max(2, options.levels ?? 8), top = options.width ?? 256, bottom = options.minWidth ?? 32;
  const budget = options.budget ?? 1 << 20, gamma = options.gamma ?? 2;
  const levels: EquirectMap[] = [];
  for (let k = 0; k < count; k++) {
    const r = levelRoughness(k, count, gamma), alpha = r * r;
    const width = levelWidth(r, top, bottom), height = width / 2;
    const samples = Math.max(16, Math.round(budget / (width * height)));
    const map: EquirectMap = { width, height, rgb: new Float32Array(width * height * 3) };
    for (let j = 0; j < height; j++) {
      for (let i = 0; i < width; i++) {
        texelDirection(dir, i, j, width, height);
        // Stryker disable next-line ConditionalExpression: a shortcut: at α = 0 every point's normal is the texel's direction, so the lobe's mean is its light, read `samples` times
        if (alpha === 0) env(rgb, dir[0], dir[1], dir[2]);
        else prefiltered(rgb, env, dir, r, samples);
        map.rgb.set(rgb, 3 * (j * width + i));
      }
      yield;
    }
    levels.push(map);
  }
  return { levels, gamma };
}

