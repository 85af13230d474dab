// `camera-src` (docs/element.md#attribute-table, docs/course-files.md#camera-cfg): the course's camera file for the scene element, a chunk of its own
// (CameraRig loads it the first time camera-src is set). Each file is loaded once per
// URL per page like a model; while one is in force it is the view (camera-position, -rotation,
// -target, fov, projection and the camera controls wait until camera-src is removed). A file
// that fails fires `error` on the element, which keeps the camera it had.
import type { CourseCamera } from '../math/course-camera';
// Through the renderer's course chunk, so that this chunk cannot load without it: a page either
// has both (the course camera is drawn) or neither (the camera attributes stay the view).
import { courseSceneRange } from '../frame/course-projection';
import type { Scene } from '../scene/scene';
import type { SceneTurn } from '../scene/turn';
import { acquireCourseFile, loadErrorDetail, type Handle } from './children/model-cache';
import type { LoadedCamera } from './children/course-files';
import { warn } from './warnings';
import { absoluteUrl } from './absolute-url';
import type { Controller } from './controller';

/** What CameraSource needs of the scene element. */
export interface CameraSourceHost {
  /** The scene element: `error` is fired on it, and nothing loads while it is disconnected. */
  readonly element: HTMLElement;
  /** `camera-src` as written; null when absent. */
  src(): string | null;
  /** The camera in force changed, or a load failed: draw again. */
  changed(): void;
}

export class CameraSource implements Controller {
  /** The course camera in force, or null (the flyby camera). */
  camera: CourseCamera | null = null;
  private url: string | null = null;
  private handle: Handle<LoadedCamera> | null = null;
  private pending = false;
  /** Cameras already warned about looking away from everything (once each). */
  private readonly warned = new WeakSet<CourseCamera>();
  private checked: { camera: CourseCamera; scene: Scene } | null = null;

  constructor(private readonly host: CameraSourceHost) {}

  get loading(): boolean {
    return this.pending;
  }

  hostConnected(): void {
    this.srcChanged();
  }

  /** Disconnected: the load stops (the camera stays, for a move). */
  hostDisconnected(): void {
    this.handle?.release();
    this.handle = null;
    this.pending = false;
    this.url = null;
  }

  /** `camera-src` changed: load the file it names, or go back to the flyby camera. */
  srcChanged(): void {
    const src = this.host.src();
    const connected = this.host.element.isConnected;
    const url = src === null || !connected ? null : absoluteUrl(src);
    if (url === this.url && src !== null && url !== null) return;
    this.handle?.release();
    this.handle = null;
    this.pending = false;
    this.url = url;
    if (src === null) {
      if (this.camera) {
        this.camera = null;
        this.host.changed();
      }
      return;
    }
    if (!connected) return;
    if (url === null) {
      this.fail(src, { type: 'load', url: src, message: 'not a usable URL' });
      return;
    }
    this.pending = true;
    const handle = acquireCourseFile('camera', url);
    this.handle = handle;
    handle.promise.then(
      (file) => {
        if (this.handle !== handle) return;
        this.pending = false;
        this.camera = file.camera;
        this.host.changed();
      },
      (e) => {
        if (this.handle !== handle) return;
        this.pending = false;
        // Forgotten here as in the cache: camera-src set again, even to this URL, fetches again.
        this.url = null;
        this.fail(url, loadErrorDetail(url, e));
      },
    );
  }

  /**
   * A camera that looks away from everything (docs/course-files.md#cameras-that-look-away: vader.cfg, maca.cfg) is drawn as the
   * course's programs drew it, with one warning per camera. Checked when camera or scene change
   * (with the trackball's turn of that moment).
   */
  checkLooksAway(scene: Scene, time: number, turn: SceneTurn | null): void {
    const camera = this.camera;
    if (!camera || this.warned.has(camera) || (this.checked?.camera === camera && this.checked.scene === scene)) return;
    this.checked = { camera, scene };
    if (scene.objects.length === 0 || !courseSceneRange(camera, scene, time, turn).behind) return;
    this.warned.add(camera);
    warn(`camera-src: every vertex is behind the camera (z ≤ 0 along N); drawn as the course's programs drew it, the formula applied to negative z (the view along −N, mirrored top to bottom)`);
  }

  private fail(url: string, detail: ReturnType<typeof loadErrorDetail>): void {
    this.host.changed();
    queueMicrotask(() => this.host.element.dispatchEvent(new CustomEvent('error', { detail: { ...detail, url } })));
  }
}
