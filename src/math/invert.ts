// The inverse of a 4×4 matrix (column-major, float64), for rough glass: the gather unprojects its
// neighbours by the inverse of the eye-relative view-projection. Written here rather than taken
// from gl-matrix's mat4 module, whose functions all sit in the core's copy of that module as soon
// as any chunk uses one: the core has no use for an inverse (docs/package.md#chunks).

/**
 * out = m⁻¹ by Laplace expansion over the 2×2 minors of the top two and bottom two rows
 * (m[c·4 + r] is row r, column c). False, with `out` untouched, when m is singular (det = 0).
 */
export function invert4(out: Float64Array | Float32Array | number[], m: ArrayLike<number>): boolean {
  const m00 = m[0], m10 = m[1], m20 = m[2], m30 = m[3];
  const m01 = m[4], m11 = m[5], m21 = m[6], m31 = m[7];
  const m02 = m[8], m12 = m[9], m22 = m[10], m32 = m[11];
  const m03 = m[12], m13 = m[13], m23 = m[14], m33 = m[15];
  // Minors of rows 0–1 (t) and of rows 2–3 (b), columns i and j: tij.
  const t01 = m00 * m11 - m01 * m10, t02 = m00 * m12 - m02 * m10, t03 = m00 * m13 - m03 * m10;
  const t12 = m01 * m12 - m02 * m11, t13 = m01 * m13 - m03 * m11, t23 = m02 * m13 - m03 * m12;
  const b01 = m20 * m31 - m21 * m30, b02 = m20 * m32 - m22 * m30, b03 = m20 * m33 - m23 * m30;
  const b12 = m21 * m32 - m22 * m31, b13 = m21 * m33 - m23 * m31, b23 = m22 * m33 - m23 * m32;
  const det = t01 * b23 - t02 * b13 + t03 * b12 + t12 * b03 - t13 * b02 + t23 * b01;
  if (det === 0 || !Number.isFinite(det)) return false;
  const k = 1 / det;
  // out[c·4 + r] = cofactor(r, c)·k: the adjugate is the transposed cofactor matrix.
  out[0] = (m11 * b23 - m12 * b13 + m13 * b12) * k;
  out[1] = (-m10 * b23 + m12 * b03 - m13 * b02) * k;
  out[2] = (m10 * b13 - m11 * b03 + m13 * b01) * k;
  out[3] = (-m10 * b12 + m11 * b02 - m12 * b01) * k;
  out[4] = (-m01 * b23 + m02 * b13 - m03 * b12) * k;
  out[5] = (m00 * b23 - m02 * b03 + m03 * b02) * k;
  out[6] = (-m00 * b13 + m01 * b03 - m03 * b01) * k;
  out[7] = (m00 * b12 - m01 * b02 + m02 * b01) * k;
  out[8] = (m31 * t23 - m32 * t13 + m33 * t12) * k;
  out[9] = (-m30 * t23 + m32 * t03 - m33 * t02) * k;
  out[10] = (m30 * t13 - m31 * t03 + m33 * t01) * k;
  out[11] = (-m30 * t12 + m31 * t02 - m32 * t01) * k;
  out[12] = (-m21 * t23 + m22 * t13 - m23 * t12) * k;
  out[13] = (m20 * t23 - m22 * t03 + m23 * t02) * k;
  out[14] = (-m20 * t13 + m21 * t03 - m23 * t01) * k;
  out[15] = (m20 * t12 - m21 * t02 + m22 * t01) * k;
  return true;
}
