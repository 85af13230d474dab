// Shoemake's arcball with Bell's hyperbolic sheet (docs/interaction.md#trackball): a pointer position maps to a point
// on a unit sphere where it is near the centre (r² ≤ ½) and on the sheet z = ½/r outside, which
// meets the sphere smoothly at r² = ½, so a drag past the rim keeps turning instead of sticking.
// The rotation of a drag takes the first point to the second: about their cross product, by the
// angle between them. Pure math, no DOM.
import { quat, vec3 } from 'gl-matrix';

/**
 * The arcball point of pointer (`px`, `py`) in CSS pixels over a `width` × `height` box (origin
 * top-left, y down): x right and y up, in units of half the smaller side; unit length.
 */
export function arcballPoint(out: vec3, px: number, py: number, width: number, height: number): vec3 {
  const r = Math.max(1, Math.min(width, height)) / 2;
  const x = (px - width / 2) / r;
  const y = (height / 2 - py) / r;
  const r2 = x * x + y * y;
  const z = r2 <= 0.5 ? Math.sqrt(1 - r2) : 0.5 / Math.sqrt(r2);
  vec3.set(out, x, y, z);
  return vec3.normalize(out, out);
}

/** The angle in radians the arcball turns for a drag from (x0, y0) to (x1, y1) (CSS pixels). */
export function arcballAngle(x0: number, y0: number, x1: number, y1: number, width: number, height: number): number {
  const a = arcballPoint((new Float64Array(3) as unknown as vec3), x0, y0, width, height);
  const b = arcballPoint((new Float64Array(3) as unknown as vec3), x1, y1, width, height);
  return Math.acos(Math.max(-1, Math.min(1, vec3.dot(a, b))));
}

/** The rotation (view space) taking arcball point `a` to `b`; identity when they coincide. */
export function arcballRotation(out: quat, a: vec3, b: vec3): quat {
  return quat.rotationTo(out, a, b);
}
