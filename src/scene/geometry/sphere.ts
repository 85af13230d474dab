// UV sphere whose vertex UVs follow docs/default-scene.md#texture-coordinates: u = 0.5 + atan2(n.x, n.z)/2π, v = acos(−n.y)/π.
import { indexArray, type MeshData } from './mesh-data';

export const MIN_SEGMENTS = 4;
export const MAX_SEGMENTS = 512;

/** `segments` around the equator; half as many rings from pole to pole. */
export function sphereMesh(radius: number, segments: number): MeshData {
  const n = Math.max(MIN_SEGMENTS, Math.min(MAX_SEGMENTS, Math.round(segments)));
  const rings = Math.max(2, Math.round(n / 2));
  const count = (n + 1) * (rings + 1);
  const positions = new Float32Array(count * 3);
  const normals = new Float32Array(count * 3);
  const uvs = new Float32Array(count * 2);
  let p = 0;
  for (let j = 0; j <= rings; j++) {
    const v = j / rings;
    const theta = v * Math.PI;
    const ny = -Math.cos(theta);
    const s = Math.sin(theta);
    for (let i = 0; i <= n; i++) {
      // At the poles every vertex is the same point; its u is the middle of its quad column.
      const u = j === 0 || j === rings ? Math.min(i + 0.5, n) / n : i / n;
      const phi = 2 * Math.PI * (u - 0.5);
      const nx = s * Math.sin(phi);
      const nz = s * Math.cos(phi);
      normals[p * 3] = nx; normals[p * 3 + 1] = ny; normals[p * 3 + 2] = nz;
      positions[p * 3] = radius * nx; positions[p * 3 + 1] = radius * ny; positions[p * 3 + 2] = radius * nz;
      uvs[p * 2] = u; uvs[p * 2 + 1] = v;
      p++;
    }
  }
  const indices = indexArray(n * rings * 6, count);
  let k = 0;
  for (let j = 0; j < rings; j++) {
    for (let i = 0; i < n; i++) {
      const a = j * (n + 1) + i;
      const b = a + 1;
      const d = a + n + 1;
      const c = d + 1;
      // Counter-clockwise seen from outside; skip the degenerate triangle at each pole.
      if (j !== 0) { indices[k++] = a; indices[k++] = b; indices[k++] = c; }
      if (j !== rings - 1) { indices[k++] = a; indices[k++] = c; indices[k++] = d; }
    }
  }
  return { positions, normals, uvs, indices: indices.subarray(0, k) as Uint16Array | Uint32Array };
}

/** Segments that keep the silhouette error r(1 − cos(π/N)) under `maxErrorPx` for a sphere `radiusPx` on screen. */
export function segmentsForScreenRadius(radiusPx: number, maxErrorPx = 0.5): number {
  if (!(radiusPx > maxErrorPx)) return MIN_SEGMENTS;
  const n = Math.PI / Math.acos(1 - maxErrorPx / radiusPx);
  return Math.max(MIN_SEGMENTS, Math.min(MAX_SEGMENTS, Math.ceil(n / 4) * 4));
}
