// The course camera's projection (frame/course-projection.ts) for one renderer: loaded the first
// time a frame has a course camera. Until it is in, FrameSetup ignores the course camera; the
// element holds that frame (Renderer.load) so it is never drawn from the wrong camera.
import type { FrameSetup } from '../frame/frame-setup';
import type { FrameState } from '../frame/types';
import { LazyPart } from './lazy-part';

export class CourseLoader {
  private readonly part = new LazyPart(
    () => import('../frame/course-projection'), 'camera-src', 'drawing from the camera attributes',
  );

  constructor(private readonly setup: FrameSetup) {}

  /** See Renderer.load. */
  load(state: FrameState): Promise<void> | null {
    if (this.setup.course) return null;
    return this.part.load(!!state.courseCamera)?.then(() => {
      this.setup.course = new this.part.value!.CourseProjection();
    }) ?? null;
  }
}
