// The triangle mesh each scene object is drawn with: the GL path's choice (frame/mesh-choice.ts),
// per face when flat; built once per content and kept.
import { flatMesh } from '../scene/geometry/flat';
import { gaussianMesh } from '../scene/geometry/gaussian';
import type { MeshData } from '../scene/geometry/mesh-data';
import type { Geometry } from '../scene/scene';
import { buildMesh, meshKey, sphereSegments } from '../frame/mesh-choice';
import type { FrameState } from '../frame/types';

/** Built meshes kept at most (spheres at many tessellations, boxes, Gaussians). */
const MAX_CACHED = 32;

export class SoftwareMeshes {
  private readonly byKey = new Map<string, MeshData>();
  private readonly flat = new WeakMap<MeshData, MeshData>();

  /**
   * The mesh of `g` this frame. A sphere with tessellation 'auto' gets the GL path's rule applied
   * to the grid it is drawn on (`pixelScale` = samples per pixel along an axis): silhouette error
   * under a quarter of a sample, so supersampling does not see the polygon. `orthoHalfHeight`:
   * the orthographic view's half-height, 0 in perspective.
   */
  get(g: Geometry, state: FrameState, worldCentre: ArrayLike<number>, worldRadius: number, orthoHalfHeight: number, pixelScale: number): MeshData {
    const data = this.base(g, state, worldCentre, worldRadius, orthoHalfHeight, pixelScale);
    if (state.shading !== 'flat') return data;
    let f = this.flat.get(data);
    if (f === undefined) this.flat.set(data, (f = flatMesh(data)));
    return f;
  }

  private base(g: Geometry, state: FrameState, centre: ArrayLike<number>, radius: number, orthoHalfHeight: number, pixelScale: number): MeshData {
    if (g.kind === 'mesh') return g.data;
    const segments = g.kind === 'sphere' ? sphereSegments(state, centre, radius, orthoHalfHeight, pixelScale) : 0;
    return this.cached(meshKey(g, segments), () => buildMesh(g, segments, gaussianMesh));
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
