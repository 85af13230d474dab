// A sphere's mesh at the tessellation asked for, or at 'auto': enough segments that the
// silhouette error r(1 − cos(π/N)) stays under a quarter pixel at its current size on screen.
import { Mesh } from './gl/mesh';
import type { ResourceCounter } from './gl/resource-counter';
import { segmentsForScreenRadius, sphereMesh } from '../scene/geometry/sphere';
import { flatMesh } from '../scene/geometry/flat';
import type { FrameState } from '../frame/types';
import { AUTO_SILHOUETTE_ERROR_PX, sphereScreenRadius } from '../frame/sphere-screen';


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
  update(state: FrameState, centre: ArrayLike<number>, worldRadius: number, radius: number, orthoHalfHeight = 0): Mesh {
    let wanted: number;
    if (state.tessellation === 'auto') {
      const screen = sphereScreenRadius(state, centre, worldRadius, orthoHalfHeight);
      wanted = segmentsForScreenRadius(Math.min(screen, 1e6), AUTO_SILHOUETTE_ERROR_PX);
      // Hysteresis: keep a finer mesh until it is twice what is needed, so a camera moving
      // back and forth does not rebuild the mesh every frame.
      if (this.mesh && this.segments >= wanted && this.segments <= 2 * wanted) wanted = this.segments;
    } else {
      wanted = state.tessellation;
    }
    const flat = state.shading === 'flat';
    if (!this.mesh || wanted !== this.segments || flat !== this.flat || radius !== this.radius) {
      this.mesh?.dispose();
      const data = sphereMesh(radius, wanted);
      this.mesh = new Mesh(this.gl, this.counter, flat ? flatMesh(data) : data);
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
