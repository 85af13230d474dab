// A sphere's GL mesh at the segments frame/mesh-choice.ts chooses (the tessellation asked for,
// or at 'auto' enough that the silhouette error stays under a quarter pixel), rebuilt only when
// they change.
import { Mesh } from './gl/mesh';
import type { ResourceCounter } from './gl/resource-counter';
import { sphereMesh } from '../scene/geometry/sphere';
import type { MeshData } from '../scene/geometry/mesh-data';
import type { FrameState } from '../frame/types';
import { sphereSegments } from '../frame/mesh-choice';

export class SphereLod {
  mesh: Mesh | null = null;
  segments = 0;
  /** Whether `mesh` is the per-face mesh of flat shading. */
  private flat = false;
  private radius = 0;

  constructor(private readonly gl: WebGL2RenderingContext, private readonly counter: ResourceCounter) {}

  /**
   * The mesh to draw this frame for a sphere of `radius` (its own frame) whose world bounds are
   * `centre`, `worldRadius` (`orthoHalfHeight` as for sphereScreenRadius); rebuilt only when the segment count, radius or shading must change.
   */
  update(
    state: FrameState, centre: ArrayLike<number>, worldRadius: number, radius: number, orthoHalfHeight: number,
    flatten: ((data: MeshData) => MeshData) | null,
  ): Mesh {
    const wanted = sphereSegments(state, centre, worldRadius, orthoHalfHeight, 1, this.mesh ? this.segments : 0);
    const flat = state.shading === 'flat' && flatten !== null;
    if (!this.mesh || wanted !== this.segments || flat !== this.flat || radius !== this.radius) {
      this.mesh?.dispose();
      const data = sphereMesh(radius, wanted);
      this.mesh = new Mesh(this.gl, this.counter, flat ? flatten!(data) : data);
      this.segments = wanted;
      this.flat = flat;
      this.radius = radius;
    }
    return this.mesh;
  }

  dispose(): void {
    this.mesh?.dispose();
    this.mesh = null;
    this.segments = 0;
  }
}
