// Unit-edge box centred at the origin; each face carries UVs over [0,1]² (docs/default-scene.md#texture-coordinates).
// BOX_FACES is shared by the reference's analytic box (reference/analytic-tracers.ts) and both
// renderers' mesh: tied down by tests/unit/geometry.test.ts (faces, winding, UV corners) and
// reference-pixels.test.ts's texels of the +Z and top faces worked out by hand.
import { type MeshData } from './mesh-data';

type V3 = readonly [number, number, number];

/** Each face: outward normal, then the axes along which u and v grow (u × v = normal). */
export const BOX_FACES: readonly (readonly [V3, V3, V3])[] = [
  [[0, 0, 1], [1, 0, 0], [0, 1, 0]],
  [[0, 0, -1], [-1, 0, 0], [0, 1, 0]],
  [[1, 0, 0], [0, 0, -1], [0, 1, 0]],
  [[-1, 0, 0], [0, 0, 1], [0, 1, 0]],
  [[0, 1, 0], [1, 0, 0], [0, 0, -1]],
  [[0, -1, 0], [1, 0, 0], [0, 0, 1]],
];

const CORNERS = [[0, 0], [1, 0], [1, 1], [0, 1]] as const;

export function boxMesh(edge = 1): MeshData {
  const positions = new Float32Array(24 * 3);
  const normals = new Float32Array(24 * 3);
  const uvs = new Float32Array(24 * 2);
  const indices = new Uint16Array(36);
  const h = edge / 2;
  BOX_FACES.forEach(([n, a, b], f) => {
    CORNERS.forEach(([u, v], c) => {
      const i = f * 4 + c;
      // Stryker disable next-line EqualityOperator: k = 3 writes the next vertex's x, written again after it (the last one past the end: dropped)
      for (let k = 0; k < 3; k++) {
        positions[i * 3 + k] = h * n[k] + (u - 0.5) * edge * a[k] + (v - 0.5) * edge * b[k];
        normals[i * 3 + k] = n[k];
      }
      uvs[i * 2] = u;
      uvs[i * 2 + 1] = v;
    });
    indices.set([0, 1, 2, 0, 2, 3].map((k) => f * 4 + k), f * 6);
  });
  return { positions, normals, uvs, indices };
}
