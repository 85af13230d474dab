// The camera and the trackball (docs/interaction.md#trackball, docs/course-files.md#the-course-camera): the pose the camera attributes give, the course
// camera of `camera-src`, and the input that moves them — the flyby keys and mouse, orbit and
// trackball pointers, the write-back at a gesture's end (controls/controls-input.ts, a chunk
// loaded when `controls` first asks). Fills the camera's part of each frame's state; no GL.
import type { FrameState } from '../frame/types';
import type { Scene } from '../scene/scene';
import type { SceneAttributes } from './attributes';
import type { CameraSource } from './camera-source';
import type { Controller } from './controller';
import type { ControlsInput } from './controls/controls-input';
import { setPose, type CameraPose } from '../math/camera';
import type { CameraChangeDetail } from './types';

const DEG = 180 / Math.PI;

/** What CameraRig needs of the scene element. */
export interface CameraRigHost {
  /** Takes the keys; the camera attributes are written back to it, and camera-change fired on it. */
  readonly element: HTMLElement;
  /** Takes the pointers. */
  readonly canvas: HTMLCanvasElement;
  /** The parsed attributes (controls, camera-*, fov, projection, camera-src). */
  readonly values: Readonly<SceneAttributes>;
  /** Draw again. */
  requestRender(): void;
  /** The trackball turned the objects or the first light (the camera did not move). */
  turned(): void;
  /** The flyby moved during a frame: that frame must be drawn even if another is on its way. */
  flybyMoved(): void;
  /** The scene as drawn (turned): orbit turns about the centre of its objects without `camera-target`. */
  scene(): Scene;
  /** The debug-view key (F) was pressed. */
  cycleDebugView(): void;
}

export class CameraRig implements Controller {
  /** The camera's pose: the camera attributes', moved by the flyby and orbit. */
  readonly pose: CameraPose = { position: [0, 0, 0], yaw: -90, pitch: 0 };
  /**
   * `camera-src`: the course camera, when one is in force (docs/course-files.md#camera-cfg). Its reader is a lazy part
   * (element/parts.ts, CAMERA_SOURCE); null until it is in.
   */
  private source: CameraSource | null = null;
  /** The trackball's rotation of the objects, a unit quaternion [x, y, z, w]. */
  readonly objectRotation = new Float64Array([0, 0, 0, 1]);
  /** The trackball's rotation of the first light about the objects' centre. */
  readonly lightRotation = new Float64Array([0, 0, 0, 1]);
  /**
   * The flyby's keys and mouse, orbit and trackball pointers, the end of a gesture
   * (controls/controls-input.ts): a lazy part (element/parts.ts, CONTROLS); null until it is in.
   */
  private controls: ControlsInput | null = null;
  private connected = false;
  /** A camera attribute set by the page: one camera-change after the current task. */
  private cameraChangeQueued = false;

  constructor(private readonly host: CameraRigHost) {
    const values = host.values;
    setPose(this.pose, values.cameraPosition, values.cameraRotation[0], values.cameraRotation[1]);
  }

  hostConnected(): void {
    this.connected = true;
    this.controls?.hostConnected();
    this.source?.hostConnected();
  }

  hostDisconnected(): void {
    this.connected = false;
    this.controls?.hostDisconnected();
    this.source?.hostDisconnected();
  }

  /** The controls' chunk is in: input is taken from now on. */
  controlsArrived(chunk: typeof import('./controls/controls')): void {
    const h = this.host;
    this.controls = new chunk.ControlsInput({
      element: h.element, canvas: h.canvas, values: h.values,
      pose: this.pose, objectRotation: this.objectRotation, lightRotation: this.lightRotation,
      requestRender: () => h.requestRender(), turned: () => h.turned(), flybyMoved: () => h.flybyMoved(),
      scene: () => h.scene(), cycleDebugView: () => h.cycleDebugView(), cameraDetail: () => this.cameraDetail(),
    });
    if (this.connected) this.controls.hostConnected();
  }

  /** camera-src's reader is in: its file loads. */
  sourceArrived(chunk: typeof import('./camera-source')): void {
    this.source = new chunk.CameraSource({ element: this.host.element, src: () => this.host.values.cameraSrc, changed: () => this.host.requestRender() });
    if (this.connected) this.source.hostConnected();
  }

  /** True while the pose is written back to the attributes (their changes are not news). */
  get writingBack(): boolean {
    return this.controls?.writing ?? false;
  }

  /** Keys held or a motion after release going on: frames keep coming. */
  get moving(): boolean {
    return this.controls?.moving ?? false;
  }

  /** The flown camera's attributes read live (the pose moves before it is written back); else undefined. */
  liveValue(property: keyof SceneAttributes): unknown {
    const pose = this.pose;
    if (property === 'cameraPosition') return pose.position;
    if (property === 'cameraRotation') return [pose.yaw, pose.pitch];
    return undefined;
  }

  /** A course camera file is loading (`ready` waits for it). */
  get loading(): boolean {
    return this.source?.loading ?? false;
  }

  /** `camera-src` changed: its file loads (the reader, the first time, with the next frame's parts). */
  cameraSrcChanged(): void {
    this.source?.srcChanged();
  }

  /** The page set camera-position, -rotation or -target: the pose follows, one camera-change. */
  cameraAttributeChanged(): void {
    const v = this.host.values;
    setPose(this.pose, v.cameraPosition, v.cameraRotation[0], v.cameraRotation[1]);
    this.aimAtTarget();
    this.queueCameraChange();
  }

  /**
   * Sets the trackball's rotation of the objects, normalised; false (nothing changed) unless
   * `value` is four finite numbers, not all zero.
   */
  setObjectRotation(value: ArrayLike<number>): boolean {
    const q = Array.from(value ?? [], Number);
    const len = Math.hypot(...q);
    if (q.length !== 4 || !Number.isFinite(len) || len === 0) return false;
    const r = this.objectRotation;
    for (let i = 0; i < 4; i++) r[i] = q[i] / len;
    this.host.turned();
    this.host.requestRender();
    return true;
  }

  /** `controls` changed: a gesture and a motion under way stop (the chunk, if needed, comes with the next frame). */
  controlsChanged(): void {
    this.controls?.cancel();
  }

  /** A frame begins: the flyby and the motion after release advance. */
  step(): void {
    this.controls?.step();
  }

  /** Frames stopped: the next flyby step starts from rest. */
  paused(): void {
    this.controls?.paused();
  }

  /** Nothing moves any more: the flyby keys' gesture ends. */
  idle(): void {
    this.controls?.idle();
  }

  /**
   * The camera's part of a frame: the pose, or the course camera while one is in force
   * (cameraPosition and fov then follow it, for the level-of-detail choices that read them).
   */
  aim(s: FrameState, scene: Scene): void {
    const v = this.host.values, pose = this.pose;
    s.fov = v.fov;
    s.cameraPosition = pose.position;
    s.yaw = pose.yaw;
    s.pitch = pose.pitch;
    s.projection = v.projection;
    s.target = v.cameraTarget; // the orthographic size is taken there (else at the glass centre)
    const source = this.source, cam = source?.camera ?? null;
    s.courseCamera = cam;
    if (!source || !cam) return;
    s.cameraPosition = cam.c;
    // The vertical field of view the course window stands for (for level-of-detail choices).
    s.fov = 2 * Math.atan(Math.abs(cam.hy / cam.d)) * DEG;
    s.projection = 'perspective';
    source.checkLooksAway(scene, s.time, s.turn ?? null);
  }

  /** With `camera-target`, the camera looks at it (docs/element.md#attribute-table): yaw and pitch from position → target. */
  private aimAtTarget(): void {
    const t = this.host.values.cameraTarget;
    if (!t) return;
    const p = this.pose.position;
    const dx = t[0] - p[0], dy = t[1] - p[1], dz = t[2] - p[2];
    const d = Math.hypot(dx, dy, dz);
    if (!(d > 0)) return; // at the target: keep camera-rotation
    setPose(this.pose, p, Math.atan2(dz, dx) * DEG, Math.asin(dy / d) * DEG);
  }

  /** camera-change's detail: the pose now (and the target, when one is set). */
  cameraDetail(): CameraChangeDetail {
    const { position, yaw, pitch } = this.pose;
    const t = this.host.values.cameraTarget;
    return t ? { position: [...position], rotation: [yaw, pitch], target: [...t] } : { position: [...position], rotation: [yaw, pitch] };
  }

  /** The page changed a camera attribute: one camera-change after its batch of changes. */
  private queueCameraChange(): void {
    const element = this.host.element;
    if (this.cameraChangeQueued || !element.isConnected) return;
    this.cameraChangeQueued = true;
    queueMicrotask(() => {
      this.cameraChangeQueued = false;
      if (element.isConnected) element.dispatchEvent(new CustomEvent('camera-change', { detail: this.cameraDetail() }));
    });
  }
}
