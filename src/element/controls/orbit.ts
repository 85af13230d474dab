// The orbit camera (docs/interaction.md#orbit): turns about a target at a fixed distance, dollies along its view
// and pans with the target. Reads and writes the element's camera pose; no DOM.
import { clampPitch, forwardFromYawPitch, tanHalfFov, wrapYaw, type CameraPose } from '../../math/camera';

/** Degrees the camera turns per CSS pixel of drag. */
export const ORBIT_DEG_PER_PX = 0.4;
/** Orbit keeps the camera off the poles by this much more than the flyby's pitch limit. */
const ORBIT_PITCH_LIMIT = 89;
const MIN_DISTANCE = 1e-3, MAX_DISTANCE = 1e6;

export class OrbitCamera {
  readonly target = new Float64Array(3);
  distance = 1;
  private readonly f = new Float64Array(3);

  /**
   * Takes the pose as it is, without turning it: the orbit's centre is the point on the view
   * axis at `target`'s depth (the target itself when the camera looks at it, as with
   * `camera-target`), so a gesture never starts with a jump.
   */
  begin(pose: CameraPose, target: ArrayLike<number>): void {
    const f = forwardFromYawPitch(this.f, pose.yaw, pose.pitch);
    const p = pose.position;
    const dx = target[0] - p[0], dy = target[1] - p[1], dz = target[2] - p[2];
    let depth = dx * f[0] + dy * f[1] + dz * f[2];
    if (!(depth > MIN_DISTANCE)) depth = Math.hypot(dx, dy, dz) || 1; // behind the camera: keep its distance
    this.distance = Math.max(MIN_DISTANCE, Math.min(MAX_DISTANCE, depth));
    for (let i = 0; i < 3; i++) this.target[i] = p[i] + f[i] * this.distance;
  }

  /** Turns by degrees (yaw right, pitch up of the view) about the target. */
  rotate(pose: CameraPose, dYaw: number, dPitch: number): void {
    pose.yaw = wrapYaw(pose.yaw + dYaw);
    pose.pitch = Math.max(-ORBIT_PITCH_LIMIT, Math.min(ORBIT_PITCH_LIMIT, clampPitch(pose.pitch + dPitch)));
    this.place(pose);
  }

  /** Distance × `factor` (clamped), towards or away from the target. */
  dolly(pose: CameraPose, factor: number): void {
    if (!(factor > 0) || !Number.isFinite(factor)) return;
    this.distance = Math.max(MIN_DISTANCE, Math.min(MAX_DISTANCE, this.distance * factor));
    this.place(pose);
  }

  /**
   * Moves target and camera across the view by a drag of (`dx`, `dy`) CSS pixels over a view
   * `height` pixels tall with vertical field of view `fov`: the point under the pointer at the
   * target's depth stays under it.
   */
  pan(pose: CameraPose, dx: number, dy: number, height: number, fov: number): void {
    const f = forwardFromYawPitch(this.f, pose.yaw, pose.pitch);
    const unitsPerPx = (2 * this.distance * tanHalfFov(fov)) / Math.max(1, height);
    // right = normalize(f × +Y) = (−fz, 0, fx)/|…|, up = right × f.
    const h = Math.hypot(f[0], f[2]) || 1;
    const rx = -f[2] / h, rz = f[0] / h;
    const ux = -rz * f[1], uy = rz * f[0] - rx * f[2], uz = rx * f[1];
    const sx = -dx * unitsPerPx, sy = dy * unitsPerPx;
    this.target[0] += rx * sx + ux * sy;
    this.target[1] += uy * sy;
    this.target[2] += rz * sx + uz * sy;
    this.place(pose);
  }

  private place(pose: CameraPose): void {
    const f = forwardFromYawPitch(this.f, pose.yaw, pose.pitch);
    for (let i = 0; i < 3; i++) pose.position[i] = this.target[i] - f[i] * this.distance;
  }
}
