// Small hand-checkable scenes for the renderer tests (software-srgb, software-msaa, glass-tie,
// software-pixels, software-raster, software-anisotropic): 17×17 pixels, vertical fov 90°, the eye
// at (0, 0, 2) looking down −Z — a point (x, y, 0) lands on pixel column 8.5·(1 + x/2), row
// 8.5·(1 − y/2) — flat quads facing +Z, ambient light only.
import type { FrameState } from '../../../src/frame/types';
import { defaultFrameState } from './frame-state';
import type { Light, Material, SceneObject, TextureSource } from '../../../src/scene/scene';

export const N = 17;

export const STATE: FrameState = defaultFrameState({
  width: N, height: N, spin: 0, cubeDistance: 0, fov: 90, cameraPosition: [0, 0, 2], yaw: -90, pitch: 0, samples: 0,
});

/** Ambient light only: an object's colour is Ka ⊙ tex, nothing else. */
export const AMBIENT: Light = { kind: 'directional', vector: [0, 0, 1], ambient: [1, 1, 1], diffuse: [0, 0, 0], specular: [0, 0, 0] };

export function material(ambient: [number, number, number], texture: TextureSource, opacity = 1): Material {
  return { ambient, diffuse: [0, 0, 0], specular: [0, 0, 0], shininess: 1, opacity, texture, mapping: 'uv' };
}

/**
 * A quad facing +Z at depth z from (x0, y0) to (x1, y1), UVs 0..uv across it; its bounds'
 * centre in the middle of the quad, or at depth `centreZ` when given (which side of a glass it
 * counts as being on).
 */
export function quad(x0: number, y0: number, x1: number, y1: number, z: number, m: Material, uv = 1, centreZ = z): SceneObject {
  return quadObject(
    `quad ${x0} ${y0} ${x1} ${y1} ${z} ${uv}`, [x0, y0, x1, y1, z], [0, 0, uv, 0, uv, uv, 0, uv], m,
    { center: [(x0 + x1) / 2, (y0 + y1) / 2, centreZ], radius: Math.hypot(x1 - x0, y1 - y0) / 2 },
  );
}

/**
 * The 2×2 quad x, y ∈ [−1, 1] on z = 0 facing +Z (pixels 4.25..12.75 of the 17×17 frame), with
 * `uvs` at its corners (lower left, lower right, upper right, upper left; all 0 unless given), its
 * bounds a radius of 1.5 about the origin.
 */
export function unitQuad(m: Material, uvs: readonly number[] = [0, 0, 0, 0, 0, 0, 0, 0], key = 'quad'): SceneObject {
  return quadObject(key, [-1, -1, 1, 1, 0], uvs, m, { center: [0, 0, 0], radius: 1.5 });
}

/** Two triangles over the rectangle (x0, y0)..(x1, y1) at depth z, facing +Z, in the world's frame. */
function quadObject(
  key: string, [x0, y0, x1, y1, z]: readonly number[], uvs: readonly number[], m: Material, bounds: SceneObject['bounds'],
): SceneObject {
  return {
    geometry: {
      kind: 'mesh', key,
      data: {
        positions: new Float32Array([x0, y0, z, x1, y0, z, x1, y1, z, x0, y1, z]),
        normals: new Float32Array([0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1]),
        uvs: new Float32Array(uvs),
        indices: new Uint16Array([0, 1, 2, 0, 2, 3]),
      },
    },
    transform: { position: [0, 0, 0], rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0 },
    material: m,
    bounds,
  };
}

/** A 1×1 white image, named `white`. */
export const WHITE = new Map([['white', { width: 1, height: 1, data: new Uint8Array([255, 255, 255, 255]) }]]);
