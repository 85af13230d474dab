// The default camera (docs/default-scene.md#the-camera), written out again from the formulas (not imported from src/math) so the
// tests check the renderer against the spec rather than against itself.
export type Vec3 = readonly [number, number, number];

export interface Camera {
  position: Vec3;
  /** Degrees; −90 looks down −Z. */
  yaw: number;
  pitch: number;
  /** Vertical field of view, degrees. */
  fov?: number;
}

const DEG = Math.PI / 180;
const sub = (a: Vec3, b: Vec3): Vec3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a: Vec3, b: Vec3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a: Vec3, b: Vec3): Vec3 => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const normalize = (a: Vec3): Vec3 => {
  const l = Math.hypot(a[0], a[1], a[2]);
  return [a[0] / l, a[1] / l, a[2] / l];
};

export function forward(yaw: number, pitch: number): Vec3 {
  const y = yaw * DEG;
  const p = pitch * DEG;
  return [Math.cos(p) * Math.cos(y), Math.sin(p), Math.cos(p) * Math.sin(y)];
}

/**
 * Where world point `p` lands on a width×height image, in pixels from the top-left corner
 * (x right, y down, like ImageData), through lookAt(position, position + forward, +Y) and a
 * perspective with vertical fov and aspect width/height. `inFront` is false behind the camera.
 */
export function project(camera: Camera, p: Vec3, width: number, height: number): { x: number; y: number; inFront: boolean } {
  // lookAt's basis: z points from the target back to the eye, x = up × z, y = z × x.
  const z = normalize(sub([0, 0, 0], forward(camera.yaw, camera.pitch)));
  const x = normalize(cross([0, 1, 0], z));
  const y = cross(z, x);
  const d = sub(p, camera.position);
  const cx = dot(x, d);
  const cy = dot(y, d);
  const cz = dot(z, d);
  const f = 1 / Math.tan(((camera.fov ?? 60) * DEG) / 2);
  const ndcX = (f / (width / height)) * (cx / -cz);
  const ndcY = f * (cy / -cz);
  return { x: ((ndcX + 1) / 2) * width, y: ((1 - ndcY) / 2) * height, inFront: cz < 0 };
}

/** Mirror image of a point across the glass plane z = 0. */
export const mirrorZ = (p: Vec3): Vec3 => [p[0], p[1], -p[2]];

/**
 * The direction (world space, not normalised) of the ray through the centre of pixel (x, y),
 * counted from the top-left corner like ImageData: the inverse of project().
 */
export function pixelRay(camera: Camera, x: number, y: number, width: number, height: number): Vec3 {
  const f = forward(camera.yaw, camera.pitch);
  const right = normalize(cross(f, [0, 1, 0]));
  const up = cross(right, f);
  const t = Math.tan(((camera.fov ?? 60) * DEG) / 2);
  const ndcX = ((x + 0.5) / width) * 2 - 1;
  const ndcY = 1 - ((y + 0.5) / height) * 2;
  const sx = ndcX * t * (width / height);
  const sy = ndcY * t;
  return [f[0] + sx * right[0] + sy * up[0], f[1] + sx * right[1] + sy * up[1], f[2] + sx * right[2] + sy * up[2]];
}
