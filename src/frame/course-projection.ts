// The course camera's projection (docs/course-files.md#the-course-camera) for FrameSetup: a part of its own, loaded only by a
// renderer whose frames have a course camera (`camera-src`), with what it needs — the course's
// maths and the scene's depth range (a walk over every vertex, kept while nothing it reads moves).
import { courseViewProjection, type CourseCamera } from '../math/course-camera';
import { courseSceneRange, type CourseDepthRange } from '../scene/course-depth';

export { courseSceneRange };
import type { SceneTurn } from '../scene/turn';
import type { Scene } from '../scene/scene';

const IDENTITY = [0, 0, 0, 1] as const;

/** What CourseProjection writes: FrameSetup's fields of the same names. */
export interface CourseProjectionTarget {
  readonly viewProjection: Float64Array;
  readonly projection: Float64Array;
  mirrorsWinding: boolean;
  courseRange: CourseDepthRange | null;
}

export class CourseProjection {
  /** courseSceneRange is a walk over every vertex: kept while camera, scene and clock are. */
  private key: { cam: CourseCamera; scene: Scene; time: number } | null = null;
  private readonly lastTurn = new Float64Array(4);
  private range: CourseDepthRange | null = null;
  // Stryker disable next-line ArrayDeclaration: n, v and u are replaced by the camera's before each use
  private readonly eyeRelative: CourseCamera = { c: [0, 0, 0], n: [0, 0, 1], v: [0, 1, 0], u: [1, 0, 0], d: 1, hx: 1, hy: 1 };

  /**
   * The course's projection as viewProjection, for eye-relative points: the same matrix with C
   * at the origin; `projection` holds it too (there is no separate view). Near and far from the
   * scene's geometry (courseSceneRange), recomputed only when the camera, the scene or (with
   * something spinning) the clock changed, or the trackball turned the objects.
   */
  apply(out: CourseProjectionTarget, cam: CourseCamera, scene: Scene, time: number, turn: SceneTurn | null): void {
    const spins = scene.objects.some((o) => o.transform.spin !== 0);
    const key = this.key, last = this.lastTurn, q = turn?.objects ?? IDENTITY;
    const turned = q[0] !== last[0] || q[1] !== last[1] || q[2] !== last[2] || q[3] !== last[3];
    if (!key || key.cam !== cam || key.scene !== scene || (spins && key.time !== time) || turned || !this.range) {
      this.key = { cam, scene, time };
      // Stryker disable next-line EqualityOperator: index 4 of a Float64Array(4) is dropped
      for (let i = 0; i < 4; i++) last[i] = q[i];
      this.range = courseSceneRange(cam, scene, time, turn);
    }
    const range = this.range;
    out.courseRange = range;
    const e = this.eyeRelative;
    e.n = cam.n; e.v = cam.v; e.u = cam.u; e.d = cam.d; e.hx = cam.hx; e.hy = cam.hy;
    courseViewProjection(out.viewProjection, e, range);
    out.projection.set(out.viewProjection);
    // One negative half-size mirrors the picture; so does looking away (x/z, y/z with z < 0).
    // Stryker disable next-line EqualityOperator: a course camera's half-sizes are never 0 (camera.cfg refuses them)
    const flipsX = cam.hx < 0, flipsY = cam.hy < 0;
    out.mirrorsWinding = flipsX !== flipsY !== range.behind;
  }
}
