// The environments made ready on this page (or in this worker), by environmentKey (the kind, and an image's URL) (docs/pbr.md#prefiltered-maps): what a renderer reads when
// it lights a glTF material from the scene's environment. Filled by frame/environment-light.ts (the maker, loaded only by a
// scene with an environment); a renderer that finds nothing here draws without the environment. The table lives on the global
// object under a registered symbol, so that the maker and the CPU renderer, each in a chunk of its own, share it without
// sharing a module (a shared module would be a third chunk, one more request before the CPU renderer's first frame).
import type { EnvironmentMaps } from '../math/environment-maps';
import { environmentKey, type Environment } from '../scene/scene';

export interface PreparedEnvironment {
  maps: EnvironmentMaps;
  /** dfgTable() of math/dfg.ts: (A, B) by n·v and roughness. */
  dfg: Float32Array;
  /**
   * out += intensity × the split sum from these maps and table (addEnvironment of math/environment-maps.ts), for a surface of linear
   * `base`, `metallic`, `roughness`, unit normal n and unit v toward the viewer. It comes with the maps, so that a renderer's own
   * code holds none of it (a CPU renderer without an environment loads none).
   */
  add(out: Float64Array, intensity: number, base: ArrayLike<number>, metallic: number, roughness: number, n: ArrayLike<number>, v: ArrayLike<number>): void;
}

/** The global object's key for the table (frame/environment-light.ts writes under the same one). */
export const ENVIRONMENTS_KEY = 'glass-plane-scene.environments';

type Table = Map<string, PreparedEnvironment>;

/** The table of this page or worker. */
export const preparedTable = (): Table => ((globalThis as Record<symbol, Table>)[Symbol.for(ENVIRONMENTS_KEY)] ??= new Map());

/** The maps and table of `environment` if they were made here, else null. Reads; allocates nothing once the table is. */
export const preparedFor = (environment: Environment): PreparedEnvironment | null => preparedTable().get(environmentKey(environment)) ?? null;
