// The glass rectangle in world coordinates: corners from its frame, normal n, u along its width
// axis and v along its height axis over [0, 1] (docs/default-scene.md#texture-coordinates: u = (x + 4)/8, v = (y + 1)/4 by default).
import type { GlassFrame } from '../glass-frame';
import { type MeshData } from './mesh-data';

const UV = [0, 0, 1, 0, 1, 1, 0, 1];

export function glassMesh(frame: GlassFrame): MeshData {
  const positions = new Float32Array(12);
  const normals = new Float32Array(12);
  const [nx, ny, nz] = frame.plane;
  for (let i = 0; i < 4; i++) {
    positions.set(frame.corners[i], i * 3);
    normals.set([nx, ny, nz], i * 3);
  }
  return { positions, normals, uvs: new Float32Array(UV), indices: new Uint16Array([0, 1, 2, 0, 2, 3]) };
}
