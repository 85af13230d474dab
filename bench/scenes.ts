// Scenes beyond the default one for `npm run bench`: the Gaussian at 40² and
// 400² (the lecture's trade: flat, Gouraud, Phong), and a ~100k-triangle mesh over a glass floor
// (the Gaussian at 225²: 2·224² = 100,352 triangles). Built the same way in Node (the reference)
// and in the page (the renderer).
import { DEFAULT_LIGHT } from '../src/scene/default-scene';
import type { Scene, SceneObject, Vec3 } from '../src/scene/scene';
import type { BenchView } from './views';

export interface BenchScene {
  name: string;
  /** Triangles drawn (for the table). */
  triangles: number;
  scene: Scene;
  view: BenchView;
}

const DEG = 180 / Math.PI;
function looking(name: string, from: [number, number, number], to: Vec3): BenchView {
  const d = [to[0] - from[0], to[1] - from[1], to[2] - from[2]];
  const len = Math.hypot(d[0], d[1], d[2]);
  return { name, cameraPosition: from, yaw: Math.atan2(d[2], d[0]) * DEG, pitch: Math.asin(d[1] / len) * DEG };
}

function gaussian(resolution: number, y = 0): SceneObject {
  return {
    geometry: { kind: 'gaussian', resolution },
    transform: { position: [0, y, 0], rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0 },
    material: {
      ambient: [0.05, 0.12, 0.22], diffuse: [0.2, 0.5, 0.9], specular: [0.5, 0.5, 0.5], shininess: 32, opacity: 1,
      texture: { kind: 'procedural' }, mapping: 'uv',
    },
    bounds: { center: [0, 0.5, 0], radius: 2.9 },
  };
}

const tris = (n: number) => 2 * (n - 1) * (n - 1);

const BACKGROUND: Vec3 = [0.1, 0.1, 0.1];

export const BENCH_SCENES: readonly BenchScene[] = [
  ...[40, 400].map((n): BenchScene => ({
    name: `gaussian ${n}²`, triangles: tris(n),
    scene: { glass: null, objects: [gaussian(n)], lights: [DEFAULT_LIGHT], background: BACKGROUND },
    view: looking(`gaussian ${n}²`, [3, 3, 4], [0, 0.3, 0]),
  })),
  {
  name: '100k-triangle mesh over a glass floor', triangles: tris(225),
  scene: {
    glass: { center: [0, 0, 0], normal: [0, 1, 0], size: [8, 8] }, objects: [gaussian(225, 0.4)],
    lights: [DEFAULT_LIGHT], background: BACKGROUND,
  },
  view: looking('glass floor', [4, 2.2, 5], [0, 0.4, 0]),
  },
];
