// An environment's light in WebGL (docs/pbr.md#the-environment), in a chunk of its own (`environment`): the shader part
// (shaders/environment.glsl), and the textures it reads — the prefiltered maps as a 2D array (each level brought to the
// finest level's size, one layer a level) and the split-sum table — made from the maps of frame/environment-light.ts,
// which are made once per page. Loaded the first time a frame has a glTF material and an environment (ENVIRONMENT_LIGHT,
// render/parts.ts).
import source from '../../shaders/environment.glsl?raw';
import { prepareEnvironment, prepareEnvironmentSliced } from '../frame/environment-light';
import { sampleEquirect, type EquirectMap } from '../math/environment-maps';
import { texelDirection } from '../math/prefilter';
import { environmentKey, type Environment } from '../scene/scene';
import type { Program } from './gl/program';
import type { ResourceCounter } from './gl/resource-counter';
import { DFG_SIZE } from '../math/dfg';

/** shaders/environment.glsl: standard.frag's ENVIRONMENT variant takes it before pbr.glsl. */
export const ENVIRONMENT_SOURCE: string = source;

/** The studio's maps made, a row at a time so that the page answers meanwhile: what the chunk's load waits for (ENVIRONMENT_LIGHT). */
export const studioReady = (): Promise<unknown> => prepareEnvironmentSliced({ kind: 'studio', intensity: 1 });

/** The texture units the maps and the table are bound to (the object's own texture is unit 0). */
const MAPS_UNIT = 3, TABLE_UNIT = 4;

/** `map` brought to `width` × `width`/2 texels: each texel its bilinear read toward the texel's centre (the finest level itself). */
function atWidth(map: EquirectMap, width: number): Float32Array {
  if (map.width === width) return map.rgb;
  const height = width / 2, out = new Float32Array(width * height * 3), d = new Float64Array(3), c = new Float64Array(3);
  for (let j = 0; j < height; j++) {
    for (let i = 0; i < width; i++) {
      texelDirection(d, i, j, width, height);
      sampleEquirect(c, map, d[0], d[1], d[2]);
      out.set(c, 3 * (j * width + i));
    }
  }
  return out;
}

/** The textures of one environment for one context; the renderer's (ctx.environment), disposed with it. */
export class EnvironmentGl {
  private maps: WebGLTexture | null = null;
  private table: WebGLTexture | null = null;
  /** Whose textures these are (environmentKey). */
  private key: string | null = null;

  constructor(private readonly gl: WebGL2RenderingContext, private readonly counter: ResourceCounter) {}

  /**
   * Makes the textures of `environment` the first time it is asked (the maps themselves once per page: the element makes an
   * image's before its scene names it, the part's load the studio's); true.
   */
  use(environment: Environment): boolean {
    if (this.key === environmentKey(environment)) return true;
    this.release();
    const gl = this.gl, prepared = prepareEnvironment(environment), levels = prepared.maps.levels;
    const width = levels[0].width, height = width / 2;
    const maps = gl.createTexture()!, table = gl.createTexture()!;
    this.counter.add('textures', 2);
    gl.bindTexture(gl.TEXTURE_2D_ARRAY, maps);
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
    gl.texImage3D(gl.TEXTURE_2D_ARRAY, 0, gl.RGB16F, width, height, levels.length, 0, gl.RGB, gl.FLOAT, null);
    levels.forEach((level, k) => gl.texSubImage3D(gl.TEXTURE_2D_ARRAY, 0, 0, 0, k, width, height, 1, gl.RGB, gl.FLOAT, atWidth(level, width)));
    // Across: REPEAT (the seam at azimuth ±π); down: CLAMP_TO_EDGE (held at the poles' rows), as sampleEquirect reads.
    gl.texParameteri(gl.TEXTURE_2D_ARRAY, gl.TEXTURE_WRAP_S, gl.REPEAT);
    gl.texParameteri(gl.TEXTURE_2D_ARRAY, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
    gl.texParameteri(gl.TEXTURE_2D_ARRAY, gl.TEXTURE_MIN_FILTER, gl.LINEAR);
    gl.texParameteri(gl.TEXTURE_2D_ARRAY, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
    gl.bindTexture(gl.TEXTURE_2D_ARRAY, null);
    gl.bindTexture(gl.TEXTURE_2D, table);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RG16F, DFG_SIZE, DFG_SIZE, 0, gl.RG, gl.FLOAT, prepared.dfg);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
    gl.bindTexture(gl.TEXTURE_2D, null);
    this.maps = maps;
    this.table = table;
    this.key = environmentKey(environment);
    return true;
  }

  /** Binds the textures and sets the ENVIRONMENT variant's uniforms on `program` (in use); the active unit is 0 after. */
  bind(program: Program, intensity: number): void {
    const gl = this.gl;
    gl.activeTexture(gl.TEXTURE0 + MAPS_UNIT);
    gl.bindTexture(gl.TEXTURE_2D_ARRAY, this.maps);
    gl.activeTexture(gl.TEXTURE0 + TABLE_UNIT);
    gl.bindTexture(gl.TEXTURE_2D, this.table);
    gl.activeTexture(gl.TEXTURE0);
    gl.uniform1i(program.location('uEnvironment'), MAPS_UNIT);
    gl.uniform1i(program.location('uDfg'), TABLE_UNIT);
    gl.uniform1f(program.location('uEnvironmentIntensity'), intensity);
  }

  dispose(): void {
    this.release();
  }

  private release(): void {
    if (this.maps === null) return;
    this.gl.deleteTexture(this.maps);
    this.gl.deleteTexture(this.table);
    this.counter.add('textures', -2);
    this.maps = this.table = null;
    this.key = null;
  }
}
