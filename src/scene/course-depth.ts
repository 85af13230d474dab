// Near and far for a course camera (docs/course-files.md#near-and-far), which the course's programs do not have: from the
// scene's geometry, so that nothing in front of the camera is clipped. Shared by the frame setup
// (WebGL and software renderers) and the float64 reference, so all three clip alike: tied down
// by tests/unit/course-depth.test.ts's ranges worked out by hand (mirrored far, scaled sphere,
// the order of rotations and spin).
import { mat4 } from 'gl-matrix';
import { courseDepthRange, type CourseCamera } from '../math/course-camera';
import { reflectPoint } from '../math/mirror';
import { GAUSSIAN_EXTENT, gaussianHeight } from './geometry/gaussian';
import { glassFrame } from './glass-frame';
import { isIdentity, turnMatrix, type SceneTurn } from './turn';
import type { Scene, SceneObject } from './scene';

export interface CourseDepthRange {
  near: number;
  far: number;
  /** Every point behind the eye (z < 0): the course's formula applied as it stands (docs/course-files.md#cameras-that-look-away). */
  behind: boolean;
}

const DEG = Math.PI / 180;

/**
 * courseDepthRange over the points that bound what is drawn at `time`: a mesh's vertices its
 * faces use, a box's corners, a sphere's nearest and farthest points along N, a Gaussian's
 * bounding box, the glass's corners. With a glass, `far` also covers those points mirrored
 * across it (the reflection pass draws them at their mirror images' depth). `turn`: the
 * trackball's turn of the objects (docs/interaction.md#trackball), when the scene value does not hold it already.
 */
export function courseSceneRange(cam: CourseCamera, scene: Scene, time: number, turn: SceneTurn | null = null): CourseDepthRange {
  const points: number[] = [];
  const m = mat4.create();
  const g = turn && !isIdentity(turn.objects) ? turnMatrix(new Float64Array(16) as unknown as mat4, turn.objects, turn.center) : null;
  for (const o of scene.objects) objectPoints(points, o, cam, time, m, g);
  let glassPlane: [number, number, number, number] | null = null;
  if (scene.glass) {
    const frame = glassFrame(scene.glass);
    glassPlane = frame.plane;
    for (const c of frame.corners) points.push(c[0], c[1], c[2]);
  }
  const range = courseDepthRange(cam, points);
  if (glassPlane) {
    const s = range.behind ? -1 : 1;
    const p = new Float64Array(3);
    let far = range.far;
    for (let i = 0; i < points.length; i += 3) {
      reflectPoint(p, [points[i], points[i + 1], points[i + 2]], glassPlane);
      const z = s * ((p[0] - cam.c[0]) * cam.n[0] + (p[1] - cam.c[1]) * cam.n[1] + (p[2] - cam.c[2]) * cam.n[2]);
      far = Math.max(far, z * 1.001);
    }
    return { near: range.near, far, behind: range.behind };
  }
  return range;
}

/** Same composition as the renderers: T · Rz·Ry·Rx · Ry(spin·t) · S. */
function modelMatrix(out: mat4, o: SceneObject, time: number): mat4 {
  const { position, rotation, scale, spin } = o.transform;
  mat4.fromTranslation(out, position as [number, number, number]);
  mat4.rotateZ(out, out, rotation[2] * DEG);
  mat4.rotateY(out, out, rotation[1] * DEG);
  mat4.rotateX(out, out, rotation[0] * DEG);
  const angle = spin * time;
  if (angle !== 0 && Number.isFinite(angle)) mat4.rotateY(out, out, angle % (2 * Math.PI));
  return mat4.scale(out, out, scale as [number, number, number]);
}

function push(points: number[], m: mat4, x: number, y: number, z: number): void {
  points.push(
    m[0] * x + m[4] * y + m[8] * z + m[12],
    m[1] * x + m[5] * y + m[9] * z + m[13],
    m[2] * x + m[6] * y + m[10] * z + m[14],
  );
}

function objectPoints(points: number[], o: SceneObject, cam: CourseCamera, time: number, m: mat4, turn: mat4 | null): void {
  modelMatrix(m, o, time);
  if (turn) mat4.multiply(m, turn, m);
  const g = o.geometry;
  switch (g.kind) {
    case 'mesh': {
      const { positions, indices } = g.data;
      const seen = new Uint8Array(positions.length / 3);
      for (let k = 0; k < indices.length; k++) {
        const i = indices[k];
        if (seen[i]) continue;
        seen[i] = 1;
        push(points, m, positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
      }
      return;
    }
    case 'box': {
      const h = g.size / 2;
      // Stryker disable next-line EqualityOperator: k = 8 repeats corner 0 (no bit set)
      for (let k = 0; k < 8; k++) push(points, m, k & 1 ? h : -h, k & 2 ? h : -h, k & 4 ? h : -h);
      return;
    }
    case 'gaussian': {
      const e = GAUSSIAN_EXTENT, low = gaussianHeight(e, e);
      // Stryker disable next-line EqualityOperator: k = 8 repeats corner 0 (no bit set)
      for (let k = 0; k < 8; k++) push(points, m, k & 1 ? e : -e, k & 2 ? 1 : low, k & 4 ? e : -e);
      return;
    }
    case 'sphere': {
      // Its extremes along N: the centre ± r·(largest scale) on the view axis.
      const c = [m[12], m[13], m[14]];
      const r = g.radius * Math.max(Math.abs(o.transform.scale[0]), Math.abs(o.transform.scale[1]), Math.abs(o.transform.scale[2]));
      for (const s of [-1, 1]) points.push(c[0] + s * r * cam.n[0], c[1] + s * r * cam.n[1], c[2] + s * r * cam.n[2]);
    }
  }
}
