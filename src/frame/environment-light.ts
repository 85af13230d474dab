// An environment made ready once per page (or worker) for the renderers (docs/pbr.md#prefiltered-maps): its prefiltered maps
// (math/prefilter.ts) and the split-sum table, made the first time it is asked for and kept (frame/environment-cache.ts) for
// every element and frame after. The code only a scene with an environment needs.
import { dfgTableSteps } from '../math/dfg';
import { environmentMapSteps } from '../math/prefilter';
import { addEnvironment, type EnvironmentMaps } from '../math/environment-maps';
import { studioRadiance } from '../math/studio';
import { imageRadiance } from '../math/environment-image';
import type { RadianceFn } from '../math/split-sum';
import { environmentKey, type Environment } from '../scene/scene';
import type { PreparedEnvironment } from './environment-cache';

// The table frame/environment-cache.ts reads, under the same registered symbol (not imported: see there).
type Table = Map<string, PreparedEnvironment>;
const table = (): Table => ((globalThis as Record<symbol, Table>)[Symbol.for('glass-plane-scene.environments')] ??= new Map());
const preparedFor = (environment: Environment): PreparedEnvironment | null => table().get(environmentKey(environment)) ?? null;

const studio: RadianceFn = (out, x, y, z) => { out[0] = out[1] = out[2] = studioRadiance(x, y, z); };
/** The light the maps are made from: the studio's, or an image's lookup (docs/pbr.md#an-image). */
const radianceOf = (environment: Environment): RadianceFn => (environment.kind === 'image' ? imageRadiance(environment.image) : studio);

function keep(environment: Environment, maps: EnvironmentMaps, dfg: Float32Array): PreparedEnvironment {
  const made: PreparedEnvironment = {
    maps, dfg,
    add: (out, intensity, base, metallic, roughness, n, v) => addEnvironment(out, maps, dfg, intensity, base, metallic, roughness, n, v),
  };
  table().set(environmentKey(environment), made);
  return made;
}

/** Runs `steps` to the end at once. */
function runAll<T>(steps: Generator<void, T, void>): T {
  for (;;) {
    const step = steps.next();
    if (step.done) return step.value;
  }
}

/** The maps and table of `environment` (the intensity is applied when shading): kept ones, or made now and kept. */
export function prepareEnvironment(environment: Environment): PreparedEnvironment {
  return preparedFor(environment) ?? keep(environment, runAll(environmentMapSteps(radianceOf(environment))), table().values().next().value?.dfg ?? runAll(dfgTableSteps()));
}

/** Runs `steps` in slices of about `sliceMs`, each in a task of its own: the page answers between them. */
async function runSliced<T>(steps: Generator<void, T, void>, sliceMs: number): Promise<T> {
  let start = performance.now();
  for (;;) {
    const step = steps.next();
    if (step.done) return step.value;
    if (performance.now() - start >= sliceMs) {
      await new Promise((resolve) => setTimeout(resolve, 0));
      start = performance.now();
    }
  }
}

/** The makings under way, by environmentKey. */
const making = new Map<string, Promise<PreparedEnvironment>>();

/**
 * prepareEnvironment on a page's main thread: the maps and table made a row at a time, in tasks of about `sliceMs` (the making
 * takes a second or more here, which one task would hold the page for). One making per environment, shared by whoever asks.
 */
export function prepareEnvironmentSliced(environment: Environment, sliceMs = 8): Promise<PreparedEnvironment> {
  const kept = preparedFor(environment);
  if (kept !== null) return Promise.resolve(kept);
  const key = environmentKey(environment);
  let p = making.get(key);
  if (!p) {
    p = (async () => {
      const maps = await runSliced(environmentMapSteps(radianceOf(environment)), sliceMs);
      // The table is the same for every environment: made once.
      const dfg = table().values().next().value?.dfg ?? (await runSliced(dfgTableSteps(), sliceMs));
      return keep(environment, maps, dfg);
    })().finally(() => making.delete(key));
    making.set(key, p);
  }
  return p;
}
