// The element's input (docs/interaction.md#controls), in the `controls` chunk: the flyby's keys and mouse look, orbit
// and trackball pointers, their motion frame by frame, and the end of a gesture, when the pose
// is written back to the camera attributes once and `camera-change` is fired. CameraRig creates
// it the first time `controls` asks for any of them and hands it the pose it moves.
import type { quat } from 'gl-matrix';
import type { CameraPose } from '../../math/camera';
import type { SceneAttributes } from '../attributes';
import type { Scene } from '../../scene/scene';
import type { Controller } from '../controller';
import type { CameraChangeDetail } from '../types';
import { FlybyController } from './flyby-controller';
import { FlybyInput } from './flyby-input';
import { PointerControls, type PointerMode } from './pointer-controls';
import { boundsCenter } from '../../scene/group-rotation';

/** The flyby's mouse look ends this long after its last movement, ms. */
const LOOK_END_MS = 150;

/** What ControlsInput needs of the camera rig and the element: where input comes from, what it moves, whom it tells. */
export interface ControlsHost {
  /** Takes the keys; the camera attributes are written back to it, and camera-change fired on it. */
  readonly element: HTMLElement;
  /** Takes the pointers. */
  readonly canvas: HTMLCanvasElement;
  /** The parsed attributes (controls, camera-target, fov). */
  readonly values: Readonly<SceneAttributes>;
  /** The camera's pose and the trackball's rotations (quaternions), moved in place. */
  readonly pose: CameraPose;
  readonly objectRotation: Float64Array;
  readonly lightRotation: Float64Array;
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
  /** camera-change's detail: the pose now. */
  cameraDetail(): CameraChangeDetail;
}

export class ControlsInput implements Controller {
  private readonly flyby: FlybyController;
  private readonly input: FlybyInput;
  private readonly pointer: PointerControls;
  /** Where an orbit about the objects' centre turns: filled at a gesture's start. */
  private readonly target = new Float64Array(3);
  private lookTimer: ReturnType<typeof setTimeout> | undefined;
  /** The camera moved since the last write-back. */
  private cameraDirty = false;
  /** The flyby's keys moved the camera since the last write-back (their gesture ends when it stops). */
  private keysMoved = false;
  /** True while the camera attributes are written back. */
  writing = false;
  /** performance.now() of the flyby's last step; 0: no motion under way. */
  private lastNow = 0;

  constructor(private readonly host: ControlsHost) {
    const { element, canvas } = host;
    this.flyby = new FlybyController({}, host.pose);
    this.input = new FlybyInput({
      element, canvas, flyby: this.flyby,
      enabled: () => host.values.controls === 'flyby',
      moved: (byMouse) => {
        if (byMouse) {
          this.cameraDirty = true;
          clearTimeout(this.lookTimer);
          this.lookTimer = setTimeout(() => this.gestureEnd(), LOOK_END_MS);
        }
        // Motion starts now, not at the next frame: on a busy page that frame may come after
        // the key is released already, and a first step of dt = 0 would lose the press.
        else if (this.lastNow === 0) this.lastNow = performance.now();
        host.requestRender();
      },
      settle: () => {
        this.advanceFlyby();
        host.requestRender();
      },
      cycleDebugView: () => host.cycleDebugView(),
    });
    this.pointer = new PointerControls({
      element, canvas,
      objectRotation: host.objectRotation as unknown as quat, lightRotation: host.lightRotation as unknown as quat,
      mode: () => (host.values.controls === 'orbit' || host.values.controls === 'trackball' ? host.values.controls as PointerMode : null),
      pose: () => host.pose,
      target: () => host.values.cameraTarget ?? boundsCenter(host.scene().objects, this.target),
      fov: () => host.values.fov,
      changed: (camera) => {
        // A trackball turn moves objects, not the camera: no write-back, no camera-change for it.
        if (camera) this.cameraDirty = true;
        if (!camera) host.turned();
        host.requestRender();
      },
      gestureEnd: () => this.gestureEnd(),
    });
  }

  hostConnected(): void {
    this.input.hostConnected();
    this.pointer.hostConnected();
  }

  hostDisconnected(): void {
    this.input.hostDisconnected();
    this.pointer.hostDisconnected();
    clearTimeout(this.lookTimer);
  }

  /** Keys held or a motion after release going on: frames keep coming. */
  get moving(): boolean {
    return this.flyby.active || this.pointer.active;
  }

  /**
   * `controls` changed: a gesture and a motion under way stop, and end as a gesture ends: where
   * they moved the camera, it is written back and announced once (docs/interaction.md#write-back-and-camera-change).
   */
  cancel(): void {
    this.pointer.cancel();
    this.gestureEnd();
  }

  /** A frame begins: the flyby and the motion after release advance. */
  step(): void {
    this.advanceFlyby();
    // The motion after release, by the wall clock (docs/interaction.md#inertia), not the frame's timestamp.
    if (!this.pointer.update(performance.now())) return;
    if (this.host.values.controls === 'orbit') this.cameraDirty = true; // a trackball's spin turns objects, not the camera
    else this.host.turned();
  }

  /** Frames stopped: the next flyby step starts from rest. */
  paused(): void {
    this.lastNow = 0;
  }

  /** Nothing moves any more: the flyby keys' gesture ends. */
  idle(): void {
    this.lastNow = 0;
    if (this.cameraDirty && this.keysMoved) this.gestureEnd();
  }

  /**
   * Moves the flyby camera by the time since the last step. Motion is timed with
   * performance.now() (the key events' clock), not the frame's timestamp, which can be
   * earlier than a key press handled in the same frame.
   */
  private advanceFlyby(): void {
    const t = performance.now();
    const dt = this.lastNow ? (t - this.lastNow) / 1000 : 0;
    this.lastNow = t;
    if (!this.flyby.update(dt)) return;
    this.cameraDirty = true;
    this.keysMoved = true;
    this.host.flybyMoved();
  }

  /**
   * A gesture ended (docs/interaction.md#write-back-and-camera-change): the camera attributes are written once (camera-target too when
   * a pan moved it) and one camera-change is fired; the write-back itself fires none.
   */
  private gestureEnd(): void {
    clearTimeout(this.lookTimer);
    this.lookTimer = undefined;
    this.keysMoved = false;
    if (!this.cameraDirty) return;
    this.cameraDirty = false;
    const { position, yaw, pitch } = this.host.pose;
    const element = this.host.element;
    this.writing = true;
    try {
      element.setAttribute('camera-position', `${position[0]} ${position[1]} ${position[2]}`);
      element.setAttribute('camera-rotation', `${yaw} ${pitch}`);
      // A pan moves what the camera looks at: with camera-target set, the target moves with it.
      if (this.pointer.takePanned() && this.host.values.cameraTarget) {
        const t = this.pointer.orbitTarget;
        element.setAttribute('camera-target', `${t[0]} ${t[1]} ${t[2]}`);
      }
    } finally {
      this.writing = false;
    }
    element.dispatchEvent(new CustomEvent('camera-change', { detail: this.host.cameraDetail() }));
  }
}
