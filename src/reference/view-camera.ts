// The GPU camera as rays: pixel (px, py), top row first, → a ray through NDC with its differentials.
import { projectionMatrix, rotationOnlyView } from '../math/camera';
import { CAMERA } from '../scene/default-scene';
import type { Ray } from './ray';
import type { ViewState } from './reference-state';

/**
 * Built from the same `rotationOnlyView` and `projectionMatrix` the renderer uploads, so
 * the basis, fov and aspect agree by construction. Ray directions are
 * forward + x·right/P[0] + y·up/P[5] for NDC (x, y): their forward component is 1.
 */
export class PinholeCamera {
  readonly eye = new Float64Array(3);
  readonly right = new Float64Array(3);
  readonly up = new Float64Array(3);
  readonly forward = new Float64Array(3);
  /** tan(fov/2)·aspect and tan(fov/2): NDC → view-plane units at depth 1. */
  private scaleX = 1;
  private scaleY = 1;
  private readonly view = new Float64Array(16);
  private readonly projection = new Float64Array(16);
  private readonly scratch = new Float64Array(3);

  constructor(state: ViewState) {
    const p = state.cameraPosition;
    this.eye[0] = p[0]; this.eye[1] = p[1]; this.eye[2] = p[2];
    const v = rotationOnlyView(this.view, state.yaw, state.pitch, this.scratch);
    // lookAt stores the camera axes as rows; the view looks down its −z row.
    for (let k = 0; k < 3; k++) {
      this.right[k] = v[k * 4];
      this.up[k] = v[k * 4 + 1];
      this.forward[k] = -v[k * 4 + 2];
    }
    // Same aspect rule as the renderer's frame setup.
    const m = projectionMatrix(this.projection, state.fov, state.width / Math.max(1, state.height), CAMERA.near, CAMERA.far);
    this.scaleX = 1 / m[0];
    this.scaleY = 1 / m[5];
  }

  /**
   * `ray` = the ray through NDC (x, y) from the eye; its differentials span a footprint of
   * `footprintX` × `footprintY` NDC units (one sample's share of the pixel).
   */
  rayThrough(ray: Ray, x: number, y: number, footprintX: number, footprintY: number): Ray {
    const { right: r, up: u, forward: f } = this;
    const sx = x * this.scaleX;
    const sy = y * this.scaleY;
    const fx = footprintX * this.scaleX;
    // NDC y grows upwards while rows grow downwards: ∂/∂row is −up.
    const fy = -footprintY * this.scaleY;
    const o = ray.origin, d = ray.direction, dx = ray.ddx, dy = ray.ddy;
    for (let k = 0; k < 3; k++) {
      o[k] = this.eye[k];
      d[k] = f[k] + sx * r[k] + sy * u[k];
      dx[k] = fx * r[k];
      dy[k] = fy * u[k];
    }
    return ray;
  }
}
