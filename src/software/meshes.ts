// The triangle mesh each scene object is drawn with: the same builders as the GL path (box,
// UV sphere, Gaussian, loaded meshes), per face when flat; built once per content and kept.
import { boxMesh } from '../scene/geometry/box';
import { flatMesh } from '../scene/geometry/flat';
import { gaussianMesh } from '../scene/geometry/gaussian';
import type { MeshData } from '../scene/geometry/mesh-data';
import { segmentsForScreenRadius, sphereMesh } from '../scene/geometry/sphere';
import type { Geometry } from '../scene/scene';
import { AUTO_SILHOUETTE_ERROR_PX, sphereScreenRadius } from '../frame/sphere-screen';
import type { FrameState } from '../frame/types';

/** Built-ins are closed and wound outwards (back faces culled); meshes from files are neither. */
export const isTwoSided = (g: Geometry): boolean => g.kind === 'mesh' || g.kind === 'gaussian';

/** Built meshes kept at most (spheres at many tessellations, boxes, Gaussians). */
const MAX_CACHED = 32;

export class SoftwareMeshes {
  private readonly byKey = new Map<string, MeshData>();
  private readonly flat = new WeakMap<MeshData, MeshData>();

  /**
   * The mesh of `g` this frame. A sphere with tessellation 'auto' gets the GL path's rule applied
   * to the grid it is drawn on (`pixelScale` = samples per pixel along an axis): silhouette error
   * under a quarter of a sample, so supersampling does not see the polygon.
   */
  get(g: Geometry, state: FrameState, worldCentre: ArrayLike<number>, worldRadius: number, pixelScale: number): MeshData {
    const data = this.base(g, state, worldCentre, worldRadius, pixelScale);
    if (state.shading !== 'flat') return data;
    let f = this.flat.get(data);
    if (f === undefined) this.flat.set(data, (f = flatMesh(data)));
    return f;
  }

  private base(g: Geometry, state: FrameState, centre: ArrayLike<number>, radius: number, pixelScale: number): MeshData {
    switch (g.kind) {
      case 'mesh': return g.data;
      case 'box': return this.cached(`box:${g.size}`, () => boxMesh(g.size));
      case 'gaussian': return this.cached(`gaussian:${g.resolution}`, () => gaussianMesh(g.resolution));
      case 'sphere': {
        const segments = state.tessellation === 'auto'
          ? segmentsForScreenRadius(Math.min(sphereScreenRadius(state, centre, radius) * pixelScale, 1e6), AUTO_SILHOUETTE_ERROR_PX)
          : state.tessellation;
        return this.cached(`sphere:${g.radius}:${segments}`, () => sphereMesh(g.radius, segments));
      }
    }
  }

  private cached(key: string, build: () => MeshData): MeshData {
    let m = this.byKey.get(key);
    if (m === undefined) {
      // A sphere whose size on screen keeps changing would add a tessellation per frame.
      if (this.byKey.size >= MAX_CACHED) this.byKey.clear();
      this.byKey.set(key, (m = build()));
    }
    return m;
  }
}
