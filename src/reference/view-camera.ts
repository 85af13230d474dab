// The GPU camera as rays: pixel (px, py), top row first, → a ray through NDC with its differentials.
// Perspective: rays from the eye through the view plane; orthographic: parallel rays along forward
// from origins spread over the view rectangle (docs/interaction.md#orthographic-size).
import { projectionMatrix, rotationOnlyView } from '../math/camera';
import { orthoHalfHeight, orthographicMatrix } from '../math/orthographic';
import type { ReadonlyVec3 } from 'gl-matrix';
import { CAMERA } from '../scene/default-scene';
import type { Ray } from './ray';
import type { ViewState } from './reference-state';
import type { CourseDepthRange } from '../scene/course-depth';

/**
 * Built from the same `rotationOnlyView` and projection matrices the renderer uploads (and the
 * same `orthoHalfHeight`), so the basis, fov, size and aspect agree by construction. Ray
 * directions have forward component 1 either way: perspective forward + x·right/P[0] + y·up/P[5]
 * for NDC (x, y) from the eye; orthographic forward from eye + x·right/P[0] + y·up/P[5]. So t
 * is the view depth the GPU clips against in both.
 */
export class ViewCamera {
  readonly eye = new Float64Array(3);
  readonly right = new Float64Array(3);
  readonly up = new Float64Array(3);
  readonly forward = new Float64Array(3);
  readonly orthographic: boolean;
  /**
   * NDC → view-plane units: at depth 1 in perspective (tan(fov/2)·aspect, tan(fov/2)), world
   * units on the view rectangle in orthographic (half-width, half-height).
   */
  private scaleX = 1;
  private scaleY = 1;
  private readonly view = new Float64Array(16);
  private readonly projection = new Float64Array(16);
  private readonly scratch = new Float64Array(3);

  /** `glassCenter`: the scene's glass centre (or null), which sizes an orthographic view without a target. */
  constructor(state: ViewState, glassCenter: ReadonlyVec3 | null = null, courseRange: CourseDepthRange | null = null) {
    const cam = state.courseCamera;
    if (cam) {
      // The course's projection (docs/course-files.md#the-course-camera): NDC (x, y) = ((d/hx)·x/z, (d/hy)·y/z) along
      // N + x·(hx/d)·U + y·(hy/d)·V, t = z. Looking away (`behind`), the same NDC along the
      // opposite direction, t = −z: the nearest to the eye wins, as the GPU's depth says.
      const s = courseRange?.behind ? -1 : 1;
      this.orthographic = false;
      // Stryker disable next-line EqualityOperator: k = 3 writes past the end of three-element Float64Arrays: dropped
      for (let k = 0; k < 3; k++) {
        this.eye[k] = cam.c[k];
        this.forward[k] = s * cam.n[k];
        this.right[k] = (s * cam.hx * cam.u[k]) / cam.d;
        this.up[k] = (s * cam.hy * cam.v[k]) / cam.d;
      }
      return;
    }
    const p = state.cameraPosition;
    this.eye[0] = p[0]; this.eye[1] = p[1]; this.eye[2] = p[2];
    const v = rotationOnlyView(this.view, state.yaw, state.pitch, this.scratch);
    // lookAt stores the camera axes as rows; the view looks down its −z row.
    // Stryker disable next-line EqualityOperator: k = 3 writes past the end of three-element Float64Arrays: dropped
    for (let k = 0; k < 3; k++) {
      this.right[k] = v[k * 4];
      this.up[k] = v[k * 4 + 1];
      this.forward[k] = -v[k * 4 + 2];
    }
    // Same aspect rule as the renderer's frame setup.
    const aspect = state.width / Math.max(1, state.height);
    this.orthographic = state.projection === 'orthographic';
    const m = this.orthographic
      ? orthographicMatrix(this.projection, orthoHalfHeight(state, glassCenter), aspect, CAMERA.near, CAMERA.far)
      : projectionMatrix(this.projection, state.fov, aspect, CAMERA.near, CAMERA.far);
    this.scaleX = 1 / m[0];
    this.scaleY = 1 / m[5];
  }

  /**
   * `ray` = the ray through NDC (x, y); its differentials span a footprint of
   * `footprintX` × `footprintY` NDC units (one sample's share of the pixel).
   */
  rayThrough(ray: Ray, x: number, y: number, footprintX: number, footprintY: number): Ray {
    const { right: r, up: u, forward: f } = this;
    const sx = x * this.scaleX;
    const sy = y * this.scaleY;
    const fx = footprintX * this.scaleX;
    // NDC y grows upwards while rows grow downwards: ∂/∂row is −up.
    const fy = -footprintY * this.scaleY;
    const o = ray.origin, d = ray.direction;
    // Perspective rays fan out from the eye (∂direction); orthographic ones move sideways (∂origin).
    const ortho = this.orthographic;
    const dx = ortho ? ray.odx : ray.ddx, dy = ortho ? ray.ody : ray.ddy;
    const zx = ortho ? ray.ddx : ray.odx, zy = ortho ? ray.ddy : ray.ody;
    // Stryker disable next-line EqualityOperator: k = 3 writes past the end of three-element Float64Arrays: dropped
    for (let k = 0; k < 3; k++) {
      const side = sx * r[k] + sy * u[k];
      o[k] = ortho ? this.eye[k] + side : this.eye[k];
      d[k] = ortho ? f[k] : f[k] + side;
      dx[k] = fx * r[k];
      dy[k] = fy * u[k];
      zx[k] = 0;
      zy[k] = 0;
    }
    return ray;
  }
}
