// Rough glass in WebGL (docs/rough-glass.md#roughness) in a chunk of its own: its passes, targets and shaders load
// the first time a frame's glass is rough (the lazy part ROUGH_GLASS, render/parts.ts), so a
// polished scene never downloads them.
import gather from '../../shaders/rough-glass.glsl?raw';
import distance from '../../shaders/distance.frag?raw';
import { ROUGH_FIRST_RING, ROUGH_MAX_RINGS, ROUGH_REACH } from '../frame/rough-glass';
import type { RoughSources } from './programs';

export { RoughTargets } from './rough-targets';

/** A number as a GLSL float literal. */
const glslFloat = (x: number): string => (Number.isInteger(x) ? x.toFixed(1) : String(x));

/** The gather, the distance codes, and frame/rough-glass.ts's constants (the software renderer reads the same). */
export const ROUGH_SOURCES: RoughSources = {
  gather,
  distance,
  defines: [
    '#define ROUGH', `#define ROUGH_FIRST_RING ${glslFloat(ROUGH_FIRST_RING)}`, `#define ROUGH_REACH ${glslFloat(ROUGH_REACH)}`,
    `#define ROUGH_MAX_RINGS ${ROUGH_MAX_RINGS}`,
  ],
};
