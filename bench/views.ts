// The bench's camera views: incidences on the glass from near-normal to grazing, a camera
// almost on the glass plane, one far away, and the element's default view.
import { DEFAULT_CAMERA_POSITION, DEFAULT_CAMERA_ROTATION } from '../src/element/attributes';
import type { Projection } from '../src/frame/types';

export interface BenchView {
  name: string;
  cameraPosition: [number, number, number];
  yaw: number;
  pitch: number;
  /** Absent: perspective (bench/projection.spec.ts sets orthographic). */
  projection?: Projection;
}

const DEG = 180 / Math.PI;
const TARGET: [number, number, number] = [0, 1, 0];

/** A camera `distance` from `target`, looking at it. */
function lookingAt(name: string, from: [number, number, number], target = TARGET): BenchView {
  const d = [target[0] - from[0], target[1] - from[1], target[2] - from[2]];
  const len = Math.hypot(d[0], d[1], d[2]);
  return { name, cameraPosition: from, yaw: Math.atan2(d[2], d[0]) * DEG, pitch: Math.asin(d[1] / len) * DEG };
}

/** Camera 6 units from the glass centre, at `deg` incidence in the horizontal plane. */
function incidence(deg: number): BenchView {
  const t = deg / DEG;
  return lookingAt(`incidence ${deg}°`, [6 * Math.sin(t), 1, 6 * Math.cos(t)]);
}

export const VIEWS: readonly BenchView[] = [
  { name: 'default', cameraPosition: [...DEFAULT_CAMERA_POSITION], yaw: DEFAULT_CAMERA_ROTATION[0], pitch: DEFAULT_CAMERA_ROTATION[1] },
  incidence(10),
  incidence(60),
  incidence(80),
  incidence(89),
  { name: '0.01 from the plane', cameraPosition: [3.5, 1.2, 0.01], yaw: -172, pitch: -4 },
  lookingAt('far away', [45, 30, 60]),
];

/** Extra views for what the skips of docs/knobs.md#reflection-skips save: the glass behind the camera, and edge-on. */
export const SKIP_VIEWS: readonly BenchView[] = [
  { name: 'glass behind the camera', cameraPosition: [...DEFAULT_CAMERA_POSITION], yaw: DEFAULT_CAMERA_ROTATION[0] + 180, pitch: 0 },
  { name: 'glass edge-on', cameraPosition: [6, 1, 0], yaw: 180, pitch: 0 },
];
