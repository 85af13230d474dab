// A coarser copy of a mesh by vertex clustering (Rossignac and Borrel): the bounding box is cut
// into cubic cells, every vertex moves to the mean of its cell's vertices, and triangles that
// lose a corner to the merge disappear. One pass, no per-vertex objects; what the reflection of
// a dense mesh draws (object-meshes.ts), where the glass shows it faint and small.
import { indexArray, type MeshData } from './mesh-data';

/** The largest side of the box around `positions` (0 for an empty or single-point mesh). */
export function meshExtent(positions: Float32Array): number {
  if (positions.length < 3) return 0;
  let x0 = Infinity, y0 = Infinity, z0 = Infinity, x1 = -Infinity, y1 = -Infinity, z1 = -Infinity;
  for (let i = 0; i < positions.length; i += 3) {
    const x = positions[i], y = positions[i + 1], z = positions[i + 2];
    if (x < x0) x0 = x; if (x > x1) x1 = x;
    if (y < y0) y0 = y; if (y > y1) y1 = y;
    if (z < z0) z0 = z; if (z > z1) z1 = z;
  }
  return Math.max(x1 - x0, y1 - y0, z1 - z0);
}

/**
 * `data` with its vertices merged on a grid of `grid` cells along the box's largest side.
 * Normals are the normalized mean of the merged ones (the first vertex's where they cancel),
 * UVs the mean; a triangle whose corners fall in fewer than three cells is dropped, and one
 * that merges into a triangle already kept too. Winding is kept. Flat meshes (with centroids) are not clustered: cluster first, then flatten.
 */
export function clusterMesh(data: MeshData, grid: number): MeshData {
  const { positions: p, normals: n, uvs: t, indices } = data;
  const vertexCount = p.length / 3;
  const extent = meshExtent(p);
  if (!(extent > 0) || !(grid >= 1) || data.centroids) return data;
  let x0 = Infinity, y0 = Infinity, z0 = Infinity;
  for (let i = 0; i < p.length; i += 3) {
    if (p[i] < x0) x0 = p[i];
    if (p[i + 1] < y0) y0 = p[i + 1];
    if (p[i + 2] < z0) z0 = p[i + 2];
  }
  const inv = grid / extent;
  const cells = grid + 1; // a vertex on the far face lands in cell `grid`
  const clusterOf = new Int32Array(vertexCount);
  const ids = new Map<number, number>();
  const sums = new Float64Array(vertexCount * 8); // position 3, normal 3, uv 2; sized for the worst case
  const counts = new Uint32Array(vertexCount);
  const first = new Int32Array(vertexCount);
  for (let v = 0; v < vertexCount; v++) {
    const ix = Math.min(grid, Math.floor((p[v * 3] - x0) * inv));
    const iy = Math.min(grid, Math.floor((p[v * 3 + 1] - y0) * inv));
    const iz = Math.min(grid, Math.floor((p[v * 3 + 2] - z0) * inv));
    const key = ix + cells * (iy + cells * iz);
    let c = ids.get(key);
    if (c === undefined) {
      c = ids.size;
      ids.set(key, c);
      first[c] = v;
    }
    clusterOf[v] = c;
    const s = c * 8;
    sums[s] += p[v * 3]; sums[s + 1] += p[v * 3 + 1]; sums[s + 2] += p[v * 3 + 2];
    sums[s + 3] += n[v * 3]; sums[s + 4] += n[v * 3 + 1]; sums[s + 5] += n[v * 3 + 2];
    sums[s + 6] += t[v * 2]; sums[s + 7] += t[v * 2 + 1];
    counts[c]++;
  }
  const clusters = ids.size;
  const positions = new Float32Array(clusters * 3);
  const normals = new Float32Array(clusters * 3);
  const uvs = new Float32Array(clusters * 2);
  for (let c = 0; c < clusters; c++) {
    const s = c * 8, k = 1 / counts[c];
    positions[c * 3] = sums[s] * k; positions[c * 3 + 1] = sums[s + 1] * k; positions[c * 3 + 2] = sums[s + 2] * k;
    let nx = sums[s + 3], ny = sums[s + 4], nz = sums[s + 5];
    let len = Math.hypot(nx, ny, nz);
    if (len < 1e-6 * counts[c]) {
      const f = first[c];
      nx = n[f * 3]; ny = n[f * 3 + 1]; nz = n[f * 3 + 2];
      len = Math.hypot(nx, ny, nz) || 1;
    }
    normals[c * 3] = nx / len; normals[c * 3 + 1] = ny / len; normals[c * 3 + 2] = nz / len;
    uvs[c * 2] = sums[s + 6] * k; uvs[c * 2 + 1] = sums[s + 7] * k;
  }
  const kept = new Uint32Array(indices.length - (indices.length % 3));
  // Fine triangles often merge into the same coarse one: kept once, so a transparent object's
  // reflection is not blended twice over itself. Keyed by the rotation starting at the smallest
  // index (winding kept); a number key while clusters³ stays exact in a double.
  const seen = new Set<number | string>();
  // Stryker disable next-line ConditionalExpression,EqualityOperator: both keys name the same triangles while clusters³ < 2⁵³ (clusters < 208,063); past that only the string is exact
  const exact = clusters < 200_000;
  let m = 0;
  for (let f = 0; f + 2 < indices.length; f += 3) {
    let a = clusterOf[indices[f]], b = clusterOf[indices[f + 1]], c = clusterOf[indices[f + 2]];
    if (a === b || b === c || a === c) continue;
    if (b < a && b < c) [a, b, c] = [b, c, a];
    else if (c < a && c < b) [a, b, c] = [c, a, b];
    // Stryker disable next-line StringLiteral: the same (a shorter string key only runs past 200,000 clusters)
    const key = exact ? (a * clusters + b) * clusters + c : `${a},${b},${c}`;
    if (seen.has(key)) continue;
    seen.add(key);
    kept[m++] = a; kept[m++] = b; kept[m++] = c;
  }
  const out = indexArray(m, clusters);
  out.set(kept.subarray(0, m));
  return { positions, normals, uvs, indices: out };
}
