// Which mesh a scene object draws with this frame, for both renderers alike: built-ins from their
// generators, a sphere at the segments its size on screen needs (in either projection), loaded
// meshes as given. The WebGL renderer uploads and shares what this names; the software renderer
// keeps it as it is. No GL here.
import { boxMesh } from '../scene/geometry/box';
import type { MeshData } from '../scene/geometry/mesh-data';
import { segmentsForScreenRadius, sphereMesh } from '../scene/geometry/sphere';
import type { Geometry, SceneObject } from '../scene/scene';
import { AUTO_SILHOUETTE_ERROR_PX, sphereScreenRadius } from './sphere-screen';
import type { FrameState } from './types';
import { refinementScale } from './refinement';

/** Built-ins are closed and wound outwards (back faces culled); meshes from files are neither. */
export const isTwoSided = (g: Geometry): boolean => g.kind === 'mesh' || g.kind === 'gaussian';

/**
 * Drawn from both sides, its normal turned to the viewer (docs/scene-model.md#two-sided-lighting): as its geometry is, but a
 * glTF material says for its mesh — single-sided unless `doubleSided` (docs/gltf.md#drawing): back faces culled, as glTF winds them.
 */
export const drawnTwoSided = (o: SceneObject): boolean => isTwoSided(o.geometry) && o.material.pbr?.doubleSided !== false;

/**
 * Segments of a sphere whose world bounds are `centre`, `worldRadius`: the tessellation asked
 * for, or with 'auto' enough that its silhouette error r(1 − cos(π/N)) stays under
 * AUTO_SILHOUETTE_ERROR_PX of the grid it is drawn on (`pixelScale` samples per pixel along an
 * axis, times a refinement frame's scale: supersampling must not see the polygon either). `orthoHalfHeight`: the orthographic
 * view's half-height, 0 in perspective (sphereScreenRadius). `current` > 0: the segments of the
 * mesh in hand, kept while it is at most twice what is needed, so a camera moving back and forth
 * does not rebuild it every frame.
 */
export function sphereSegments(
  state: FrameState, centre: ArrayLike<number>, worldRadius: number, orthoHalfHeight: number, pixelScale = 1, current = 0,
): number {
  if (state.tessellation !== 'auto') return state.tessellation;
  const screen = sphereScreenRadius(state, centre, worldRadius, orthoHalfHeight) * pixelScale * refinementScale(state);
  const wanted = segmentsForScreenRadius(Math.min(screen, 1e6), AUTO_SILHOUETTE_ERROR_PX);
  // Stryker disable next-line EqualityOperator: at current = wanted both answers are the same number
  return current >= wanted && current <= 2 * wanted ? current : wanted;
}

/** A name for the content of `g`'s mesh (a sphere's at `segments`): objects whose names are equal share one mesh. */
export function meshKey(g: Geometry, segments = 0): string {
  switch (g.kind) {
    case 'box': return `box:${g.size}`;
    case 'gaussian': return `gaussian:${g.resolution}`;
    case 'mesh': return `mesh:${g.key}`;
    case 'sphere': return `sphere:${g.radius}:${segments}`;
  }
}

/**
 * The triangles of `g` (a sphere at `segments`), before flat shading splits them per face.
 * `gaussian`: the Gaussian's generator (scene/geometry/gaussian.ts), which the core leaves out.
 */
export function buildMesh(g: Geometry, segments = 0, gaussian?: (resolution: number) => MeshData): MeshData {
  switch (g.kind) {
    case 'box': return boxMesh(g.size);
    case 'gaussian':
      if (!gaussian) throw new Error('buildMesh: a Gaussian needs its generator');
      return gaussian(g.resolution);
    case 'mesh': return g.data;
    case 'sphere': return sphereMesh(g.radius, segments);
  }
}
