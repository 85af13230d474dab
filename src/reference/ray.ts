// A ray with its screen-space differentials: the one mutable value every reference stage passes along.
import { reflectDirection, reflectPoint, type Plane } from '../math/mirror';

/**
 * origin + t·direction. `direction` is not normalised: the camera scales it so that
 * direction · forward = 1, which makes t the view depth the GPU clips against (near/far).
 * The mirrored ray keeps the same t: pass 1 draws with view × reflection, so a mirrored hit's
 * depth is that of its mirror image along the primary ray. `ddx`, `ddy` are ∂direction/∂x and
 * ∂direction/∂y across one sample's footprint: with the hit's normal they give the
 * footprint on the surface (ray differentials, Igehy 1999). `odx`, `ody` are ∂origin/∂x and
 * ∂origin/∂y: zero for a perspective eye, the only differentials of an orthographic one
 * (parallel rays from origins spread over the view rectangle).
 */
export class Ray {
  readonly origin = new Float64Array(3);
  readonly direction = new Float64Array([0, 0, -1]);
  readonly ddx = new Float64Array(3);
  readonly ddy = new Float64Array(3);
  readonly odx = new Float64Array(3);
  readonly ody = new Float64Array(3);

  /** this = `r` mirrored across the (glass) plane: origin, direction and differentials (the mirrored camera). */
  mirrorOf(r: Ray, plane: Plane): this {
    reflectPoint(this.origin, r.origin, plane);
    reflectDirection(this.direction, r.direction, plane);
    reflectDirection(this.ddx, r.ddx, plane);
    reflectDirection(this.ddy, r.ddy, plane);
    reflectDirection(this.odx, r.odx, plane);
    reflectDirection(this.ody, r.ody, plane);
    return this;
  }
}
