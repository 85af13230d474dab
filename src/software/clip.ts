// Clipping of the software rasterizer's triangles (raster.ts): the planes as distances that
// are ≥ 0 inside, each vertex's inside bits for the trivial accept and reject.
/**
 * Vertex layout in the buffers drawn: clip x, y, z, w, then a user clip distance (kept where
 * ≥ 0; used when `userClip` is set), then the shader's varyings. Clipping interpolates them all.
 */
export const CLIP_W = 3;
export const CLIP_DISTANCE = 4;
export const VARYINGS = 5;

/**
 * Guard band: x and y are clipped to ±GUARD·w (NDC ±4), so snapped coordinates stay below
 * 2^23 for grids up to 8192 px and every edge-function product is an exact integer in a double.
 */
export const GUARD = 4;

// Clip planes, as distances that are ≥ 0 inside: near z + w, far w − z, the guard band
// G·w ± x and G·w ± y, and the user clip distance.
export const PLANES = 7;
export const USER = 6;
const ALL_FRUSTUM = (1 << USER) - 1;
export const ALL = (1 << PLANES) - 1;

export function planeDistance(v: Float64Array, o: number, plane: number): number {
  const w = v[o + CLIP_W];
  switch (plane) {
    case 0: return v[o + 2] + w;
    case 1: return w - v[o + 2];
    case 2: return GUARD * w + v[o];
    case 3: return GUARD * w - v[o];
    case 4: return GUARD * w + v[o + 1];
    case 5: return GUARD * w - v[o + 1];
    default: return v[o + CLIP_DISTANCE];
  }
}

/** Bit p set: the vertex is inside plane p (the user bit is set when `user` is off). */
export function inside(v: Float64Array, o: number, user: boolean): number {
  let bits = user ? (v[o + CLIP_DISTANCE] >= 0 ? 1 << USER : 0) : 1 << USER;
  const x = v[o], y = v[o + 1], z = v[o + 2], w = v[o + CLIP_W], g = GUARD * w;
  if (z + w >= 0) bits |= 1;
  if (w - z >= 0) bits |= 2;
  if (g + x >= 0) bits |= 4;
  if (g - x >= 0) bits |= 8;
  if (g + y >= 0) bits |= 16;
  if (g - y >= 0) bits |= 32;
  return bits & (ALL_FRUSTUM | (1 << USER));
}

export function copyVertex(src: Float64Array, from: number, dst: Float64Array, to: number, n: number): void {
  for (let k = 0; k < n; k++) dst[to + k] = src[from + k];
}

/**
 * Whether triangle (a, b, c), in front of the eye (w > 0 at each vertex), lies wholly above NDC
 * y = `hi` or wholly below `lo`: a half-space holds the clipped polygon too, so it cannot reach
 * a band of rows between them (Rasterizer.top; the caller leaves a row's margin for rounding).
 */
export function outsideRows(v: Float64Array, a: number, b: number, c: number, hi: number, lo: number): boolean {
  const wa = v[a + CLIP_W], wb = v[b + CLIP_W], wc = v[c + CLIP_W];
  if (!(wa > 0 && wb > 0 && wc > 0)) return false;
  const ya = v[a + 1], yb = v[b + 1], yc = v[c + 1];
  return (ya > hi * wa && yb > hi * wb && yc > hi * wc) || (ya < lo * wa && yb < lo * wb && yc < lo * wc);
}
