// The glass rectangle on z = 0 with u = (x + 4)/8, v = (y + 1)/4 (SPEC §3).
import { GLASS } from '../default-scene';
import { type MeshData } from './mesh-data';

export function glassMesh(): MeshData {
  const { xMin, xMax, yMin, yMax } = GLASS;
  const xs = [xMin, xMax, xMax, xMin];
  const ys = [yMin, yMin, yMax, yMax];
  const positions = new Float32Array(12);
  const normals = new Float32Array(12);
  const uvs = new Float32Array(8);
  for (let i = 0; i < 4; i++) {
    positions.set([xs[i], ys[i], 0], i * 3);
    normals.set([0, 0, 1], i * 3);
    uvs.set([(xs[i] - xMin) / (xMax - xMin), (ys[i] - yMin) / (yMax - yMin)], i * 2);
  }
  return { positions, normals, uvs, indices: new Uint16Array([0, 1, 2, 0, 2, 3]) };
}
