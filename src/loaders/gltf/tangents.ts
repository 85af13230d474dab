// Tangents where a normal map needs them and the file has none (docs/gltf.md#tangents): per
// vertex, the sum over its triangles of each triangle's ∂position/∂u (and ∂position/∂v for the
// handedness), in glTF's UV space (v down), made orthogonal to the vertex normal (Gram-Schmidt)
// and unit; w = +1 where (N × T) points against ∂p/∂v — towards the image's top, the normal map's +Y, as
// glTF's bitangent w·(N × T) does on a texture laid upright — −1 where the UVs are mirrored. Not
// MikkTSpace: vertices the file shares across a UV seam get one tangent, where MikkTSpace splits.

/** xyzw per vertex. `uvs` as the file has them (glTF's v-down space). */
export function computeTangents(positions: Float32Array, normals: Float32Array, uvs: Float32Array, indices: Uint32Array): Float32Array {
  const n = positions.length / 3;
  const t = new Float64Array(3 * n), b = new Float64Array(3 * n);
  // Stryker disable next-line EqualityOperator: one step more reads indices past the end (undefined): NaN slots, written nowhere
  for (let k = 0; k < indices.length; k += 3) {
    const i0 = indices[k], i1 = indices[k + 1], i2 = indices[k + 2];
    const du1 = uvs[2 * i1] - uvs[2 * i0], dv1 = uvs[2 * i1 + 1] - uvs[2 * i0 + 1];
    const du2 = uvs[2 * i2] - uvs[2 * i0], dv2 = uvs[2 * i2 + 1] - uvs[2 * i0 + 1];
    const det = du1 * dv2 - du2 * dv1;
    if (det === 0) continue; // no UV area: no direction to give
    const r = 1 / det;
    for (let c = 0; c < 3; c++) {
      const e1 = positions[3 * i1 + c] - positions[3 * i0 + c], e2 = positions[3 * i2 + c] - positions[3 * i0 + c];
      const tc = (e1 * dv2 - e2 * dv1) * r, bc = (e2 * du1 - e1 * du2) * r;
      for (const i of [i0, i1, i2]) {
        t[3 * i + c] += tc;
        b[3 * i + c] += bc;
      }
    }
  }
  const out = new Float32Array(4 * n);
  for (let i = 0; i < n; i++) {
    const nx = normals[3 * i], ny = normals[3 * i + 1], nz = normals[3 * i + 2];
    let tx = t[3 * i], ty = t[3 * i + 1], tz = t[3 * i + 2];
    const d = nx * tx + ny * ty + nz * tz;
    tx -= nx * d; ty -= ny * d; tz -= nz * d;
    let len = Math.sqrt(tx * tx + ty * ty + tz * tz);
    // Stryker disable next-line EqualityOperator: a length of exactly 1e-12 is no input's
    if (!(len > 1e-12)) {
      // No UV direction here: any unit vector perpendicular to the normal.
      // Stryker disable next-line EqualityOperator: at |nx| = 0.9 either choice is a unit vector perpendicular to N
      [tx, ty, tz] = Math.abs(nx) < 0.9 ? [0, nz, -ny] : [-nz, 0, nx];
      len = Math.sqrt(tx * tx + ty * ty + tz * tz) || 1;
    }
    tx /= len; ty /= len; tz /= len;
    // (N × T) · ∂p/∂v: negative on a texture laid upright (v runs down it), positive where the UVs are mirrored.
    const cx = ny * tz - nz * ty, cy = nz * tx - nx * tz, cz = nx * ty - ny * tx;
    const w = cx * b[3 * i] + cy * b[3 * i + 1] + cz * b[3 * i + 2] > 0 ? -1 : 1;
    out.set([tx, ty, tz, w], 4 * i);
  }
  return out;
}
