// FrameSetup's lazy parts for one renderer: the course camera's projection
// (frame/course-projection.ts), loaded the first time a frame has a course camera, and the
// orthographic projection (frame/orthographic-view.ts), the first time a frame is orthographic.
// Until one is in, FrameSetup ignores the course camera, or draws in perspective; the element
// holds that frame (Renderer.load) so it is never drawn from the wrong camera.
import type { FrameSetup } from '../frame/frame-setup';
import type { FrameState } from '../frame/types';
import { LazyPart } from './lazy-part';

export class SetupParts {
  private readonly coursePart = new LazyPart(
    () => import('../frame/course-projection'), 'camera-src', 'drawing from the camera attributes',
  );
  private readonly orthoPart = new LazyPart(
    () => import('../frame/orthographic-view'), 'projection="orthographic"', 'drawing in perspective',
  );

  constructor(private readonly setup: FrameSetup) {}

  /** See Renderer.load: the course projection, given to FrameSetup as it arrives. */
  course(state: FrameState): Promise<void> | null {
    const setup = this.setup;
    return setup.course ? null : this.coursePart.load(!!state.courseCamera)?.then(() => {
      setup.course = new this.coursePart.value!.CourseProjection();
    }) ?? null;
  }

  /** See Renderer.load: the orthographic projection, given to FrameSetup as it arrives. */
  ortho(state: FrameState): Promise<void> | null {
    const setup = this.setup;
    return setup.ortho ? null : this.orthoPart.load(state.projection === 'orthographic')?.then(() => {
      setup.ortho = this.orthoPart.value!.orthographicView;
    }) ?? null;
  }
}
