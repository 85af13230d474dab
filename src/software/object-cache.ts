// An opaque object's shaded colour per pixel kept from one frame to the next (docs/software-renderer.md#frame-to-frame-caches). Drawn
// exactly as in the last frame — the same mesh, matrices, eye, clip plane, lights, material,
// texture and grid — an object shades each of its pixels to the same colour, bit for bit (the
// same vertices give the same clipped triangles and barycentrics): the default scene's sphere while the cube
// turns. One cache per target grid (the scene's, the reflection's); an entry is read back only by
// the draw and the triangle that wrote it, in a later frame with that draw's key unchanged. A draw
// whose key changed since the last frame neither reads nor keeps entries (the turning cube pays
// nothing); from its next unchanged frame on, it does.
import { sameNumber } from './glass-cache';

/** Objects (by index in the scene) a cache follows; those past it are shaded every frame. */
export const MAX_CACHED_OBJECTS = 64;
/** Values a draw's key holds at most (ObjectShader.cacheKey). */
export const OBJECT_KEY_LENGTH = 160;
/** Pixels a cache covers at most (1280×720): past it, frames are too slow to be interactive anyway. */
export const MAX_CACHED_PIXELS = 1280 * 720;

export class ObjectCache {
  /** Per pixel: the clamped colour as the Float32 target holds it (opaque draws only). */
  rgb = new Float32Array(0);
  /** The draw version and triangle (Rasterizer.face) that wrote each entry; version 0: none. */
  private version = new Uint32Array(0);
  private face = new Uint32Array(0);
  private readonly keys: Float64Array[] = [];
  private readonly objects: unknown[][] = [];
  private readonly versions = new Uint32Array(MAX_CACHED_OBJECTS);
  private nextVersion = 1;
  /** The version of the draw being shaded; 0: its fragments are neither read nor kept. */
  current = 0;

  /**
   * Before object `index` is drawn on a grid of `pixels`: when `values` and `objects` are exactly
   * its last draw's (Object.is), its entries are read and kept (`current` is its version); else it
   * takes a new version and this draw is not cached (`current` 0).
   */
  begin(index: number, values: Float64Array, objects: readonly unknown[], pixels: number): void {
    this.current = 0;
    if (index >= MAX_CACHED_OBJECTS || pixels > MAX_CACHED_PIXELS) return;
    if (this.version.length < pixels) this.resize(pixels);
    const key = (this.keys[index] ??= new Float64Array(OBJECT_KEY_LENGTH)), last = (this.objects[index] ??= []);
    let same = this.versions[index] !== 0 && objects.length === last.length;
    for (let i = 0; same && i < objects.length; i++) same = objects[i] === last[i];
    for (let i = 0; same && i < OBJECT_KEY_LENGTH; i++) same = sameNumber(values[i], key[i]);
    if (!same) {
      key.set(values);
      last.length = 0;
      last.push(...objects);
      if (this.nextVersion === 0xffffffff) this.resize(this.version.length);
      this.versions[index] = this.nextVersion++;
      return;
    }
    this.current = this.versions[index];
  }

  /** Whether pixel `i` holds the current draw's colour for triangle `face`. */
  has(i: number, face: number): boolean {
    return this.current !== 0 && this.version[i] === this.current && this.face[i] === face;
  }

  set(i: number, face: number, r: number, g: number, b: number): void {
    const o = 3 * i;
    this.rgb[o] = r; this.rgb[o + 1] = g; this.rgb[o + 2] = b;
    this.version[i] = this.current;
    this.face[i] = face;
  }

  /** New, empty arrays; every version forgotten. */
  private resize(pixels: number): void {
    this.rgb = new Float32Array(3 * pixels);
    this.version = new Uint32Array(pixels);
    this.face = new Uint32Array(pixels);
    this.versions.fill(0);
    this.nextVersion = 1;
    this.current = 0;
  }
}
