// The glass's per-pixel F and texel kept from one frame to the next (docs/software-renderer.md#frame-to-frame-caches). With the camera
// and the glass still — the element spinning its objects — each glass pixel shades to the same
// two doubles as in the frame before, bit for bit (the same vertices, snapped the same way, give
// the same barycentrics), so they are read back instead of computed again: Fresnel and the
// anisotropic texture read were about half of a 1-sample frame. When anything they depend on
// differs from the last frame's, a new generation starts and every entry is stale; that frame
// neither reads nor keeps any (a camera in motion pays nothing), the next still one keeps them.

/** Doubles that decide a glass pixel's F and texel, besides the shader's objects (model, texture, mode). */
export const GLASS_KEY_LENGTH = 64;

export class GlassCache {
  /** Per pixel: F and the texel, as the entry's generation computed them. */
  f = new Float64Array(0);
  texel = new Float64Array(0);
  /** The generation that wrote each entry (0: never), and which sample of its pixel was shaded. */
  private stamp = new Uint32Array(0);
  private slot = new Uint8Array(0);
  private generation = 1;
  /** The last frame's key: `values` (GLASS_KEY_LENGTH, unused slots 0) and the objects. */
  private readonly values = new Float64Array(GLASS_KEY_LENGTH);
  private readonly objects: unknown[] = [];
  /** Whether this frame's key is the last frame's: entries are read and kept only then. */
  active = false;

  /**
   * Sizes the cache for `pixels` and keeps its entries only when `values` and `objects` are
   * exactly the last call's (Object.is: −0 is not 0, NaN never keeps anything).
   */
  begin(values: Float64Array, objects: readonly unknown[], pixels: number): void {
    let same = this.f.length >= pixels && objects.length === this.objects.length;
    for (let i = 0; same && i < objects.length; i++) same = objects[i] === this.objects[i];
    for (let i = 0; same && i < GLASS_KEY_LENGTH; i++) same = sameNumber(values[i], this.values[i]);
    this.active = same;
    if (same) return;
    this.values.set(values);
    this.objects.length = 0;
    this.objects.push(...objects);
    if (this.f.length < pixels) {
      this.f = new Float64Array(pixels);
      this.texel = new Float64Array(pixels);
      this.stamp = new Uint32Array(pixels);
      this.slot = new Uint8Array(pixels);
    }
    this.generation++;
    if (this.generation === 0xffffffff) {
      this.stamp.fill(0);
      this.generation = 1;
    }
  }

  /** Forgets every entry (a frame whose key cannot be told, as the rough glass's). */
  clear(): void {
    this.values[0] = NaN;
    this.active = false;
  }

  /** Whether pixel `i` holds this generation's values, written at sample `slot`. */
  has(i: number, slot: number): boolean {
    return this.stamp[i] === this.generation && this.slot[i] === slot;
  }

  set(i: number, slot: number, f: number, texel: number): void {
    this.f[i] = f;
    this.texel[i] = texel;
    this.stamp[i] = this.generation;
    this.slot[i] = slot;
  }
}

/** Object.is for numbers: −0 is not 0, NaN is never kept (a key with one never matches). */
export const sameNumber = (a: number, b: number): boolean => a === b && (a !== 0 || 1 / a === 1 / b);
