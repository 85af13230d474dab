// The per-pixel region map: what a pixel shows, or the edge band where its error is dominated by edges.
import type { Scene } from '../scene/scene';
import { KEY_BASE } from './sample-tracer';
import type { SurfaceCodes } from './surface-codes';

export const REGION_BACKGROUND = 0;
export const REGION_CUBE = 1;
export const REGION_SPHERE = 2;
export const REGION_GLASS = 3;
export const REGION_EDGE = 4;

export type Region = 0 | 1 | 2 | 3 | 4;

/** The default scene's codes (SurfaceCodes of the default scene, docs/default-scene.md): cube faces 1..6, sphere 7, glass 8. */
const SURFACE_SPHERE = 7;
const SURFACE_GLASS = 8;
const isCube = (surface: number): boolean => surface >= 1 && surface <= 6;

/** The region of the first visible surface named by a sample key of the default scene. */
export function regionOfKey(key: number): Region {
  const primary = key % KEY_BASE;
  if (isCube(primary)) return REGION_CUBE;
  if (primary === SURFACE_SPHERE) return REGION_SPHERE;
  if (primary === SURFACE_GLASS) return REGION_GLASS;
  return REGION_BACKGROUND;
}

/**
 * Region per pixel from one key per pixel and a flag for pixels whose samples disagreed.
 * A pixel is on a boundary when it is mixed or an 8-neighbour's key differs (the key names
 * the cube face, what lies behind the glass and what the glass reflects, so creases,
 * silhouettes seen through the glass and in the mirror count too, and it flags samples whose
 * texture footprint was singular: grazing incidence, the sphere's poles). The edge band is the
 * boundary pixels grown by one pixel: every pixel within about 1.5 px of a boundary.
 */
/**
 * regionOfKey for any scene: boxes count as the cube region, every other object as the sphere
 * region (both are 'objects' to the metrics), the glass as glass. For the default scene it is
 * regionOfKey.
 */
export function regionOfCodes(scene: Scene, codes: SurfaceCodes): (key: number) => Region {
  return (key) => {
    const primary = key % codes.base;
    if (primary === codes.glass) return REGION_GLASS;
    const object = codes.objectOfCode(primary);
    if (object < 0) return REGION_BACKGROUND;
    return scene.objects[object].geometry.kind === 'box' ? REGION_CUBE : REGION_SPHERE;
  };
}

export function regionMap(
  keys: Int32Array, mixed: Uint8Array, width: number, height: number, regionOf: (key: number) => Region = regionOfKey,
): Uint8Array {
  const boundary = new Uint8Array(width * height);
  // Stryker disable next-line EqualityOperator: a row y = height only reads keys in range and writes boundary past its end: dropped
  for (let y = 0; y < height; y++) {
    // Stryker disable next-line EqualityOperator: x = width writes the next row's first pixel, written again (or past the end)
    for (let x = 0; x < width; x++) {
      const i = y * width + x;
      boundary[i] = mixed[i] || differsFromNeighbour(keys, width, height, x, y) ? 1 : 0;
    }
  }
  const regions = new Uint8Array(width * height);
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      const i = y * width + x;
      regions[i] = anyNear(boundary, width, height, x, y) ? REGION_EDGE : regionOf(keys[i]);
    }
  }
  return regions;
}

function differsFromNeighbour(keys: Int32Array, width: number, height: number, x: number, y: number): boolean {
  const k = keys[y * width + x];
  for (let dy = -1; dy <= 1; dy++) {
    for (let dx = -1; dx <= 1; dx++) {
      // Stryker disable next-line ArithmeticOperator: dx and dy run over −1..1, so x − dx and y − dy visit the same neighbours
      const nx = x + dx, ny = y + dy;
      if (nx >= 0 && ny >= 0 && nx < width && ny < height && keys[ny * width + nx] !== k) return true;
    }
  }
  return false;
}

function anyNear(flags: Uint8Array, width: number, height: number, x: number, y: number): boolean {
  for (let dy = -1; dy <= 1; dy++) {
    for (let dx = -1; dx <= 1; dx++) {
      // Stryker disable next-line ArithmeticOperator: dx and dy run over −1..1, so x − dx and y − dy visit the same neighbours
      const nx = x + dx, ny = y + dy;
      if (nx >= 0 && ny >= 0 && nx < width && ny < height && flags[ny * width + nx]) return true;
    }
  }
  return false;
}

/**
 * Is this a pixel where the glass reflects the cube? Read from a sample key of the default
 * scene (the geometry the sample's rays hit), never from colours: primary surface the glass,
 * mirrored ray on the cube. For any scene: glassReflectsObject.
 */
export function glassReflectsCube(key: number): boolean {
  return key % KEY_BASE === SURFACE_GLASS && isCube(Math.floor(key / (KEY_BASE * KEY_BASE)) % KEY_BASE);
}

/** Is this a pixel where the glass reflects object `index` of the scene the codes were made for? */
export function glassReflectsObject(key: number, codes: SurfaceCodes, index: number): boolean {
  const [primary, , reflected] = codes.digits(key);
  return primary === codes.glass && codes.objectOfCode(reflected) === index;
}
