// The bench scene for rough glass (docs/rough-glass.md#roughness): a glass floor with a cube resting on it
// (contact: its reflection should stay sharp where it touches) and a sphere whose lowest point
// is 1.5 above it (far: its reflection blurs), seen from above at a slant.
import { DEFAULT_LIGHT, defaultMaterial } from '../src/scene/default-scene';
import type { Scene, Vec3 } from '../src/scene/scene';
import type { BenchView } from './views';

const DEG = 180 / Math.PI;

/** The sphere's lowest point above the floor. */
export const SPHERE_HEIGHT = 1.5;

export function roughFloorScene(): Scene {
  return {
    glass: { center: [0, 0, 0], normal: [0, 1, 0], size: [8, 8] },
    objects: [
      {
        geometry: { kind: 'box', size: 1 },
        transform: { position: [-0.9, 0.5, 0.2], rotation: [0, 25, 0], scale: [1, 1, 1], spin: 0 },
        material: defaultMaterial([0.9, 0.3, 0.3]),
        bounds: { center: [0, 0, 0], radius: Math.sqrt(3) / 2 },
      },
      {
        geometry: { kind: 'sphere', radius: 0.5 },
        transform: { position: [0.9, SPHERE_HEIGHT + 0.5, -0.2], rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0 },
        material: defaultMaterial([0.3, 0.8, 0.4]),
        bounds: { center: [0, 0, 0], radius: 0.5 },
      },
    ],
    lights: [DEFAULT_LIGHT],
    background: [0.1, 0.1, 0.12] as Vec3,
  };
}

function looking(name: string, from: [number, number, number], to: Vec3): BenchView {
  const d = [to[0] - from[0], to[1] - from[1], to[2] - from[2]];
  const len = Math.hypot(d[0], d[1], d[2]);
  return { name, cameraPosition: from, yaw: Math.atan2(d[2], d[0]) * DEG, pitch: Math.asin(d[1] / len) * DEG };
}

export const ROUGH_FLOOR_VIEW: BenchView = looking('rough floor', [0.3, 1.9, 5.2], [0, 0.6, 0]);
