// FrameSetup's lazy parts for one renderer: the course camera's projection
// (frame/course-projection.ts), loaded the first time a frame has a course camera, and the
// orthographic projection (frame/orthographic-view.ts), the first time a frame is orthographic.
// Until one is in, FrameSetup ignores the course camera, or draws in perspective; the element
// holds that frame (Renderer.load) so it is never drawn from the wrong camera.
import type { FrameSetup } from '../frame/frame-setup';
import type { FrameState } from '../frame/types';
import { LazyPart, loadAll } from './lazy-part';

export class SetupParts {
  private readonly course = new LazyPart(
    () => import('../frame/course-projection'), 'camera-src', 'drawing from the camera attributes',
  );
  private readonly ortho = new LazyPart(
    () => import('../frame/orthographic-view'), 'projection="orthographic"', 'drawing in perspective',
  );

  constructor(private readonly setup: FrameSetup) {}

  /** See Renderer.load. */
  load(state: FrameState): Promise<void> | null {
    const setup = this.setup;
    const course = setup.course ? null : this.course.load(!!state.courseCamera)?.then(() => {
      setup.course = new this.course.value!.CourseProjection();
    }) ?? null;
    const ortho = setup.ortho ? null : this.ortho.load(state.projection === 'orthographic')?.then(() => {
      setup.ortho = this.ortho.value!.orthographicView;
    }) ?? null;
    return course && ortho ? loadAll(course, ortho, null, null, null) : course ?? ortho;
  }
}
