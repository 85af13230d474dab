// An environment made ready once per page (or worker) for the renderers (docs/pbr.md#prefiltered-maps): its prefiltered maps
// (math/prefilter.ts) and the split-sum table, made the first time it is asked for and kept (frame/environment-cache.ts) for
// every element and frame after. The code only a scene with an environment needs.
import { dfgTable } from '../math/dfg';
import { makeEnvironmentMaps } from '../math/prefilter';
import { addEnvironment } from '../math/environment-maps';
import { studioRadiance } from '../math/studio';
import type { Environment } from '../scene/scene';
import { keepPrepared, preparedFor, type PreparedEnvironment } from './environment-cache';

/** The maps and table of `environment` (its kind; the intensity is applied when shading): kept ones, or made now and kept. */
export function prepareEnvironment(environment: Environment): PreparedEnvironment {
  const kept = preparedFor(environment);
  if (kept !== null) return kept;
  // One kind so far: the studio.
  const maps = makeEnvironmentMaps((out, x, y, z) => { out[0] = out[1] = out[2] = studioRadiance(x, y, z); }), dfg = dfgTable();
  const made: PreparedEnvironment = {
    maps, dfg,
    add: (out, intensity, base, metallic, roughness, n, v) => addEnvironment(out, maps, dfg, intensity, base, metallic, roughness, n, v),
  };
  keepPrepared(environment, made);
  return made;
}
