// The built-in shapes of <glass-object> as scene geometry with object-space bounding spheres.
import { GAUSSIAN_EXTENT, gaussianHeight } from '../../scene/geometry/gaussian';
import type { Bounds, Geometry } from '../../scene/scene';
import type { Shape } from './object-attributes';

export const CUBE_EDGE = 1;
export const SPHERE_RADIUS = 0.5;

export function builtinShape(shape: Shape, resolution: number): { geometry: Geometry; bounds: Bounds } {
  switch (shape) {
    case 'sphere':
      return { geometry: { kind: 'sphere', radius: SPHERE_RADIUS }, bounds: { center: [0, 0, 0], radius: SPHERE_RADIUS } };
    case 'gaussian': {
      // x, z ∈ [−E, E], y between the corner height and the peak at the origin.
      const e = GAUSSIAN_EXTENT;
      const low = gaussianHeight(e, e);
      const mid = (1 + low) / 2;
      return {
        geometry: { kind: 'gaussian', resolution },
        bounds: { center: [0, mid, 0], radius: Math.hypot(e, 1 - mid, e) },
      };
    }
    default:
      return {
        geometry: { kind: 'box', size: CUBE_EDGE },
        bounds: { center: [0, 0, 0], radius: (Math.sqrt(3) * CUBE_EDGE) / 2 },
      };
  }
}
