// The Gaussian surface y = e^(−x²)·e^(−z²) (docs/scene-model.md#built-in-shapes) over x, z ∈ [−2, 2], on an N×N grid of vertices
// (the lecture compares 40² and 400²), with normals from the surface itself, not the mesh.
// Shared: the reference traces this same mesh (reference/ray-scene.ts), so it is tied down by
// tests/unit/geometry-flat-gaussian.test.ts's heights, normals and UVs, not by the comparison.
import { indexArray, type MeshData } from './mesh-data';

export const GAUSSIAN_EXTENT = 2;
export const MIN_RESOLUTION = 2;
export const MAX_RESOLUTION = 1024;

/** Height of the surface at (x, z). */
export const gaussianHeight = (x: number, z: number): number => Math.exp(-x * x - z * z);

/**
 * `resolution` × `resolution` vertices, (resolution − 1)² quads, two counter-clockwise
 * triangles each seen from +Y. UV u = (x + 2)/4, v = (z + 2)/4. The normal is the unit
 * (−∂y/∂x, 1, −∂y/∂z) with ∂y/∂x = −2x·y and ∂y/∂z = −2z·y: exact at every vertex, so Gouraud
 * and Phong differ only by where they light, as in the lecture.
 */
export function gaussianMesh(resolution: number): MeshData {
  const n = Math.max(MIN_RESOLUTION, Math.min(MAX_RESOLUTION, Math.round(resolution)));
  const count = n * n;
  const positions = new Float32Array(count * 3);
  const normals = new Float32Array(count * 3);
  const uvs = new Float32Array(count * 2);
  const step = (2 * GAUSSIAN_EXTENT) / (n - 1);
  // Stryker disable next-line EqualityOperator: a row past the end writes past the typed arrays' ends, which drops it
  for (let j = 0; j < n; j++) {
    // The last row and column sit exactly on the edge, not one rounding step short of it.
    // Stryker disable next-line ConditionalExpression,ArithmeticOperator: the float64 step short of the edge (~1e-16) is below float32's, where the mesh is stored
    const z = j === n - 1 ? GAUSSIAN_EXTENT : -GAUSSIAN_EXTENT + j * step;
    // Stryker disable next-line EqualityOperator: a column past the end lands on the next row's first vertex, written after it (the last past the end: dropped)
    for (let i = 0; i < n; i++) {
      // Stryker disable next-line ConditionalExpression,ArithmeticOperator: as for z: below float32's resolution
      const x = i === n - 1 ? GAUSSIAN_EXTENT : -GAUSSIAN_EXTENT + i * step;
      const y = gaussianHeight(x, z);
      const gx = 2 * x * y, gz = 2 * z * y; // −∂y/∂x, −∂y/∂z
      const len = Math.hypot(gx, 1, gz);
      const v = j * n + i;
      positions[v * 3] = x; positions[v * 3 + 1] = y; positions[v * 3 + 2] = z;
      normals[v * 3] = gx / len; normals[v * 3 + 1] = 1 / len; normals[v * 3 + 2] = gz / len;
      uvs[v * 2] = (x + GAUSSIAN_EXTENT) / (2 * GAUSSIAN_EXTENT);
      uvs[v * 2 + 1] = (z + GAUSSIAN_EXTENT) / (2 * GAUSSIAN_EXTENT);
    }
  }
  const indices = indexArray((n - 1) * (n - 1) * 6, count);
  let k = 0;
  // Stryker disable next-line EqualityOperator,ArithmeticOperator: extra rows write past the typed index array's end, which drops them
  for (let j = 0; j < n - 1; j++) {
    for (let i = 0; i < n - 1; i++) {
      const a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      // (x right, z towards the viewer) seen from +Y: a → c → b is counter-clockwise.
      indices[k++] = a; indices[k++] = c; indices[k++] = b;
      indices[k++] = b; indices[k++] = c; indices[k++] = d;
    }
  }
  return { positions, normals, uvs, indices };
}
