// The course camera's projection (frame/course-projection.ts) for one renderer: loaded the first
// time a frame has a course camera. Until it is in, FrameSetup ignores the course camera; the
// element holds that frame (Renderer.load) so it is never drawn from the wrong camera.
import type { FrameSetup } from '../frame/frame-setup';
import type { FrameState } from '../frame/types';

export class CourseLoader {
  private loading: Promise<void> | null = null;
  private failed = false;

  constructor(private readonly setup: FrameSetup) {}

  /** See Renderer.load. */
  load(state: FrameState): Promise<void> | null {
    if (!state.courseCamera || this.setup.course || this.failed) return null;
    return (this.loading ??= import('../frame/course-projection').then(
      (chunk) => {
        this.setup.course = new chunk.CourseProjection();
      },
      (e: unknown) => {
        this.failed = true;
        throw new Error(`camera-src could not load its projection (${String(e).slice(0, 200)}); drawing from the camera attributes`);
      },
    ));
  }
}
