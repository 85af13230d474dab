// The course's camera (docs/course-files.md#the-course-camera): its basis, its pixel projection exactly as the
// course's programs compute it, and the same projection as a 4×4 matrix for a GPU.
// courseBasis makes the camera that both renderers and the reference take, and courseDepthRange
// gives all three their near and far (through scene/course-depth.ts): tied down by
// tests/unit/course-camera.test.ts's hand-computed bases, pixels and ranges, and
// course-depth.test.ts. The reference casts its own rays from the basis (reference/view-camera.ts).
export type Vec3 = [number, number, number];

/**
 * C the focus; N the unit view direction; V the unit up, orthogonal to N; U = N × V, the
 * "right" of a camera looking along N with V up. (U, V, N) is a left-handed triple
 * (U × V = −N), like Direct3D's view space: x right, y up, z forward, away from the eye.
 * d is the focal distance and hx, hy the half-sizes of the screen window, signs kept.
 */
export interface CourseCamera {
  c: Vec3;
  n: Vec3;
  v: Vec3;
  u: Vec3;
  d: number;
  hx: number;
  hy: number;
}

/**
 * N normalised, V made orthogonal to N (Gram-Schmidt) and normalised, U = N × V; or the
 * reason why not: N is zero, or V is parallel to N (nothing left after Gram-Schmidt).
 */
export function courseBasis(nIn: Vec3, vIn: Vec3): { n: Vec3; v: Vec3; u: Vec3 } | 'zero N' | 'V parallel to N' {
  const nLength = Math.hypot(...nIn);
  if (!(nLength > 0)) return 'zero N';
  const n = scale(nIn, 1 / nLength);
  const along = dot(vIn, n);
  const w: Vec3 = [vIn[0] - along * n[0], vIn[1] - along * n[1], vIn[2] - along * n[2]];
  const wLength = Math.hypot(...w);
  if (!(wLength > 1e-9 * Math.hypot(...vIn))) return 'V parallel to N';
  const v = scale(w, 1 / wLength);
  // `+ 0` turns −0 into 0, so a camera written with round numbers gives round vectors.
  const clean = (a: Vec3): Vec3 => [a[0] + 0, a[1] + 0, a[2] + 0];
  return { n: clean(n), v: clean(v), u: clean(cross(n, v)) };
}

/** View coordinates x = (P − C)·U, y = (P − C)·V, z = (P − C)·N. */
export function courseView(cam: CourseCamera, p: ArrayLike<number>): Vec3 {
  const q: Vec3 = [p[0] - cam.c[0], p[1] - cam.c[1], p[2] - cam.c[2]];
  return [dot(q, cam.u), dot(q, cam.v), dot(q, cam.n)];
}

/**
 * The course's projection of P onto a W×H drawing buffer: x' = (d/hx)·x/z,
 * y' = (d/hy)·y/z, pixel ((x' + 1)·W/2, (1 − y')·H/2), with pixel rows counted from the top
 * and pixel (i, j) covering [i, i + 1)×[j, j + 1). `z` is the view depth: z ≤ 0 is behind the
 * camera; the formula is applied as it stands there too, so the caller decides.
 */
export function courseProject(cam: CourseCamera, p: ArrayLike<number>, width: number, height: number): { x: number; y: number; z: number } {
  const [x, y, z] = courseView(cam, p);
  const xs = ((cam.d / cam.hx) * x) / z;
  const ys = ((cam.d / cam.hy) * y) / z;
  return { x: ((xs + 1) * width) / 2, y: ((1 - ys) * height) / 2, z };
}

/**
 * Near and far planes for the vertices in `positions` (xyz; only those `indices` use, when
 * given), which the course does not have: the range of their view depths z with a margin of
 * 0.1%, so that no vertex in front of the camera is clipped. `behind` when no vertex is in
 * front (z > 0): the course cameras that look away from their object, drawn as the course's
 * programs drew them (`courseViewProjection`), with the range of −z. When vertices lie on
 * both sides of the eye the near plane is the nearest vertex in front, at least 10⁻⁴ of the
 * far one: the part of a triangle that crosses z = 0 is clipped there.
 */
export function courseDepthRange(
  cam: CourseCamera, positions: ArrayLike<number>, indices?: ArrayLike<number>,
): { near: number; far: number; behind: boolean } {
  let nearFront = Infinity, farFront = 0, nearBack = Infinity, farBack = 0;
  // Stryker disable next-line ArithmeticOperator: reads past the end give NaN depths, which no branch below takes
  const count = indices ? indices.length : positions.length / 3;
  // Stryker disable next-line EqualityOperator: the same (k = count reads past the end: a NaN depth)
  for (let k = 0; k < count; k++) {
    const o = 3 * (indices ? indices[k] : k);
    const z = (positions[o] - cam.c[0]) * cam.n[0] + (positions[o + 1] - cam.c[1]) * cam.n[1] + (positions[o + 2] - cam.c[2]) * cam.n[2];
    if (z > 0) {
      nearFront = Math.min(nearFront, z); farFront = Math.max(farFront, z);
    } else if (z < 0) {
      nearBack = Math.min(nearBack, -z); farBack = Math.max(farBack, -z);
    }
  }
  // Stryker disable next-line ConditionalExpression,EqualityOperator: with farBack = 0 too, far = 0 returns the default below
  const behind = farFront === 0 && farBack > 0;
  let near = behind ? nearBack : nearFront, far = behind ? farBack : farFront;
  if (far === 0) return { near: 0.01, far: 100, behind: false }; // nothing off the eye's plane
  if (!behind && farBack > 0) near = Math.max(Math.min(near, far), far * 1e-4);
  near *= 0.999;
  far *= 1.001;
  return { near, far, behind };
}

/**
 * out = the course's projection as one column-major matrix (world → OpenGL clip space,
 * depth −1..1 between `near` and `far`): clip = (s·(d/hx)·x, s·(d/hy)·y, A·s·z + B, s·z),
 * with (x, y, z) the view coordinates, s = −1 when `behind` (else 1),
 * A = (f + n)/(f − n), B = −2fn/(f − n). So NDC x and y are exactly the course's x' and y'
 * for any sign of z, and GL's viewport puts a point at window x = (x' + 1)·W/2,
 * y = (y' + 1)·H/2 counted from the bottom, which is the course's pixel (its rows count from
 * the top): the same picture on a canvas. Depth grows with s·z: in front of the camera the
 * nearest point wins; behind it (s = −1) the one nearest the eye. With hx, hy > 0 a triangle
 * counter-clockwise as seen from the eye is counter-clockwise in NDC (GL's default front
 * face); one negative half-size mirrors the picture, so a renderer that culls must then
 * swap its front face.
 */
export function courseViewProjection<T extends Float64Array | Float32Array | number[]>(
  out: T, cam: CourseCamera, range: { near: number; far: number; behind: boolean },
): T {
  const s = range.behind ? -1 : 1;
  const { near, far } = range;
  const a = (far + near) / (far - near);
  const b = (-2 * far * near) / (far - near);
  const sx = (s * cam.d) / cam.hx, sy = (s * cam.d) / cam.hy;
  const { c, u, v, n } = cam;
  // Rows of the clip transform, each acting on (P − C): row·P − row·C.
  const rows: [Vec3, number][] = [
    [scale(u, sx), 0], [scale(v, sy), 0], [scale(n, s * a), b], [scale(n, s), 0],
  ];
  for (let r = 0; r < 4; r++) {
    const [w, add] = rows[r];
    out[r] = w[0]; out[4 + r] = w[1]; out[8 + r] = w[2];
    out[12 + r] = add - dot(w, c);
  }
  return out;
}

function dot(a: ArrayLike<number>, b: ArrayLike<number>): number {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

function cross(a: Vec3, b: Vec3): Vec3 {
  return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
}

function scale(a: ArrayLike<number>, k: number): Vec3 {
  return [a[0] * k, a[1] * k, a[2] * k];
}
