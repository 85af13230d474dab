// `normalize` (docs/scene-model.md#glass-object), apart from the parser so the element can use it without loading it.
import type { ObjResult } from './obj/types';

/**
 * Centres the bounds on the origin and scales the longest side to 2 (the `normalize` attribute).
 * Returns a new result; only positions and bounds change (normals survive a uniform scale).
 */
export function normalizeObj(result: ObjResult): ObjResult {
  const { min, max } = result.bounds;
  const centre = [0, 1, 2].map((a) => (min[a] + max[a]) / 2);
  const longest = Math.max(max[0] - min[0], max[1] - min[1], max[2] - min[2]);
  const scale = longest > 0 ? 2 / longest : 1;
  const positions = new Float32Array(result.positions.length);
  for (let i = 0; i < positions.length; i++) positions[i] = (result.positions[i] - centre[i % 3]) * scale;
  const at = (a: number, v: number): number => (v - centre[a]) * scale;
  return {
    ...result,
    positions,
    bounds: {
      min: [at(0, min[0]), at(1, min[1]), at(2, min[2])],
      max: [at(0, max[0]), at(1, max[1]), at(2, max[2])],
    },
  };
}
