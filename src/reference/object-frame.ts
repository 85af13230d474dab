// An object's transform at one instant, float64: world ↔ object space for points, directions, normals, gradients.
import { mat4 } from 'gl-matrix';
import type { Transform } from '../scene/scene';

const DEG = Math.PI / 180;

/**
 * model = T · Rz·Ry·Rx · R_y(spin·time) · S: `rotation` in degrees with X applied first, the
 * spin about the object's own Y applied before it, the scale last. `matrix` holds T · R (no S)
 * as gl-matrix composes it, so the rotation's columns are the object's axes in the world.
 */
export class ObjectFrame {
  /** T · R, column-major; its upper 3×3 is orthonormal. */
  readonly matrix = new Float64Array(16);
  readonly scale = new Float64Array(3);
  /** True when S = (1, 1, 1): R·n of a unit n is unit already (up to rounding) and is used as it is. */
  readonly unitScale: boolean;

  constructor(transform: Transform, time: number) {
    const m = this.matrix as unknown as mat4;
    mat4.identity(m);
    const [rx, ry, rz] = transform.rotation;
    mat4.rotateZ(m, m, rz * DEG);
    mat4.rotateY(m, m, ry * DEG);
    mat4.rotateX(m, m, rx * DEG);
    mat4.rotateY(m, m, transform.spin * time);
    const [px, py, pz] = transform.position;
    m[12] = px; m[13] = py; m[14] = pz;
    this.scale.set(transform.scale);
    this.unitScale = this.scale[0] === 1 && this.scale[1] === 1 && this.scale[2] === 1;
  }

  /** out = S⁻¹·Rᵀ·(p − T). */
  pointToObject(out: Float64Array, p: ArrayLike<number>): Float64Array {
    const m = this.matrix, s = this.scale;
    const px = p[0] - m[12], py = p[1] - m[13], pz = p[2] - m[14];
    for (let k = 0; k < 3; k++) {
      const c = 4 * k;
      out[k] = (m[c] * px + m[c + 1] * py + m[c + 2] * pz) / s[k];
    }
    return out;
  }

  /** out = S⁻¹·Rᵀ·d: a ray keeps its parameter t across the change of frame. */
  directionToObject(out: Float64Array, d: ArrayLike<number>): Float64Array {
    const m = this.matrix, s = this.scale;
    const dx = d[0], dy = d[1], dz = d[2];
    for (let k = 0; k < 3; k++) {
      const c = 4 * k;
      out[k] = (m[c] * dx + m[c + 1] * dy + m[c + 2] * dz) / s[k];
    }
    return out;
  }

  /**
   * out = R·S⁻¹·g: an object-space gradient (of a texture coordinate, or a normal, which is the
   * gradient of the surface's implicit function) as a world gradient. Not normalised.
   */
  gradientToWorld(out: Float64Array, g: ArrayLike<number>): Float64Array {
    const m = this.matrix, s = this.scale;
    const gx = g[0] / s[0], gy = g[1] / s[1], gz = g[2] / s[2];
    for (let k = 0; k < 3; k++) out[k] = m[k] * gx + m[4 + k] * gy + m[8 + k] * gz;
    return out;
  }

  /** out = R·S·d: an object-space direction along the surface (a tangent) in the world. Not normalised. */
  directionToWorld(out: Float64Array, d: ArrayLike<number>): Float64Array {
    const m = this.matrix, s = this.scale;
    const dx = d[0] * s[0], dy = d[1] * s[1], dz = d[2] * s[2];
    for (let k = 0; k < 3; k++) out[k] = m[k] * dx + m[4 + k] * dy + m[8 + k] * dz;
    return out;
  }

  /** out = normalize(R·S⁻¹·n): the world normal of an object-space normal. */
  normalToWorld(out: Float64Array, n: ArrayLike<number>): Float64Array {
    this.gradientToWorld(out, n);
    const len = Math.hypot(out[0], out[1], out[2]);
    if (len > 0) { out[0] /= len; out[1] /= len; out[2] /= len; }
    return out;
  }
}
