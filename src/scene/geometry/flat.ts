// Flat shading (docs/scene-model.md#shading-modes): lighting once per triangle, from its face normal at its
// centroid. Each triangle gets three vertices of its own carrying the face normal and the
// centroid, so whichever vertex the GPU takes as provoking gives the same light.
import { indexArray, type MeshData } from './mesh-data';

/**
 * The face-normal mesh of `data`: the same triangles, de-indexed, UVs kept per corner. The
 * face normal is the cross product's direction, turned to agree with the mean of the corners'
 * own normals (so a builder's winding never flips the lighting); a degenerate triangle (zero
 * area, as at a UV sphere's poles) takes that mean.
 */
export function flatMesh(data: MeshData): MeshData {
  const { positions: p, normals: n, uvs: t, indices } = data;
  const count = indices.length - (indices.length % 3);
  const positions = new Float32Array(count * 3);
  const normals = new Float32Array(count * 3);
  const centroids = new Float32Array(count * 3);
  const uvs = new Float32Array(count * 2);
  const out = indexArray(count, count);
  for (let f = 0; f < count; f += 3) {
    const a = indices[f] * 3, b = indices[f + 1] * 3, c = indices[f + 2] * 3;
    const e1x = p[b] - p[a], e1y = p[b + 1] - p[a + 1], e1z = p[b + 2] - p[a + 2];
    const e2x = p[c] - p[a], e2y = p[c + 1] - p[a + 1], e2z = p[c + 2] - p[a + 2];
    let nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
    const mx = n[a] + n[b] + n[c], my = n[a + 1] + n[b + 1] + n[c + 1], mz = n[a + 2] + n[b + 2] + n[c + 2];
    let len = Math.hypot(nx, ny, nz);
    if (!(len > 0)) {
      nx = mx; ny = my; nz = mz;
      len = Math.hypot(nx, ny, nz) || 1;
    } else if (nx * mx + ny * my + nz * mz < 0) {
      len = -len;
    }
    nx /= len; ny /= len; nz /= len;
    const cx = (p[a] + p[b] + p[c]) / 3, cy = (p[a + 1] + p[b + 1] + p[c + 1]) / 3, cz = (p[a + 2] + p[b + 2] + p[c + 2]) / 3;
    for (let k = 0; k < 3; k++) {
      const v = f + k;
      const src = indices[v];
      positions.set(p.subarray(src * 3, src * 3 + 3), v * 3);
      uvs[v * 2] = t[src * 2];
      uvs[v * 2 + 1] = t[src * 2 + 1];
      normals[v * 3] = nx; normals[v * 3 + 1] = ny; normals[v * 3 + 2] = nz;
      centroids[v * 3] = cx; centroids[v * 3 + 1] = cy; centroids[v * 3 + 2] = cz;
      out[v] = v;
    }
  }
  return { positions, normals, uvs, indices: out, centroids };
}
