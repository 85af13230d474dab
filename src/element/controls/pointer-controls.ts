// DOM input for `controls="orbit"` and `controls="trackball"` (docs/interaction.md#trackball): pointer drags (mouse,
// pen, one finger), two-finger pinch and pan, the wheel, and keys while the host has focus.
// orbit: drag turns the camera about its target, right-drag (or Shift-drag, or two fingers)
// pans, wheel and pinch dolly. trackball: drag turns the objects with the arcball, right-drag
// or Shift-drag turns the first light the same way, wheel and pinch dolly, two fingers pan.
// Rotations keep spinning after release (inertia.ts). Listeners live while the host is
// connected; nothing is allocated per event.
import { quat, vec3 } from 'gl-matrix';
import { forwardFromYawPitch, type CameraPose } from '../../math/camera';
import { arcballPoint } from './arcball';
import { Inertia, VelocityTracker } from './inertia';
import { OrbitCamera, ORBIT_DEG_PER_PX } from './orbit';
import type { Controller } from '../controller';

export type PointerMode = 'orbit' | 'trackball';

/** What PointerControls needs of the scene element. */
export interface PointerControlsHost {
  /** Takes the keys (focused); focused by a press. */
  readonly element: HTMLElement;
  /** Takes the pointers and the wheel. */
  readonly canvas: HTMLElement;
  /** The mode in force, or null (flyby or no controls: this class ignores input). */
  mode(): PointerMode | null;
  /** The live camera pose (changed in place). */
  pose(): CameraPose;
  /** What orbit turns about and what the trackball dollies towards: `camera-target`, else the objects' centre. */
  target(): ArrayLike<number>;
  /** Vertical field of view, degrees. */
  fov(): number;
  /** The camera (`camera` true) or the trackball's objects or light moved: draw. */
  changed(camera: boolean): void;
  /** A gesture ended (pointer up, 150 ms after the wheel, a key): write back and announce if the camera moved. */
  gestureEnd(): void;
  /** The trackball's rotation of the objects, a unit quaternion [x, y, z, w], turned in place. */
  readonly objectRotation: quat;
  /** The trackball's rotation of the first light about the objects' centre, turned in place. */
  readonly lightRotation: quat;
}

/** No single input event turns anything by more than this (docs/interaction.md#no-jumps), degrees. */
export const MAX_EVENT_TURN = 5;
/** Dolly per wheel pixel: e^(0.0015·deltaY). */
const WHEEL_RATE = 0.0015;
/** The wheel's gesture ends this long after its last event (docs/interaction.md#write-back-and-camera-change), ms. */
export const WHEEL_END_MS = 150;
/** Keys: degrees per arrow press, dolly factor per +/−. */
const KEY_TURN = 5, KEY_DOLLY = 1.1;
const DEG = Math.PI / 180;

type Drag = 'rotate' | 'pan' | 'light' | 'pinch' | null;

export class PointerControls implements Controller {
  /** The host's rotations (PointerControlsHost), which this class turns. */
  private readonly objectRotation: quat;
  private readonly lightRotation: quat;

  private readonly orbit = new OrbitCamera();
  private readonly pointers = new Map<number, { x: number; y: number }>();
  private drag: Drag = null;
  private last = { x: 0, y: 0 };
  private span = 0;
  private rect = { left: 0, top: 0, width: 1, height: 1 };
  private wheelTimer: ReturnType<typeof setTimeout> | undefined;
  private moved = false;
  private panned = false;
  // Rotation rates after release, rad/s: trackball (world rotation vector) or orbit (yaw, pitch).
  private readonly spin = new Inertia(3);
  /** Wall-clock time (performance.now(), ms) the motion after release has been advanced to. */
  private spinTime = 0;
  private spinKind: 'trackball' | 'orbit' = 'trackball';
  private readonly velocity = new VelocityTracker(3);
  // Scratch, so events allocate nothing.
  private readonly a = (new Float64Array(3) as unknown as vec3);
  private readonly b = (new Float64Array(3) as unknown as vec3);
  private readonly q = (new Float64Array([0, 0, 0, 1]) as unknown as quat);
  private readonly axis = (new Float64Array(3) as unknown as vec3);
  private readonly delta = new Float64Array(3);
  private readonly f = new Float64Array(3);

  private readonly element: HTMLElement;
  private readonly canvas: HTMLElement;

  constructor(private readonly host: PointerControlsHost) {
    this.element = host.element;
    this.canvas = host.canvas;
    this.objectRotation = host.objectRotation;
    this.lightRotation = host.lightRotation;
  }

  hostConnected(): void {
    const c = this.canvas;
    c.addEventListener('pointerdown', this.onDown);
    c.addEventListener('pointermove', this.onMove);
    c.addEventListener('pointerup', this.onUp);
    c.addEventListener('pointercancel', this.onUp);
    c.addEventListener('lostpointercapture', this.onUp);
    c.addEventListener('wheel', this.onWheel, { passive: false });
    c.addEventListener('contextmenu', this.onContextMenu);
    this.element.addEventListener('keydown', this.onKey);
  }

  hostDisconnected(): void {
    const c = this.canvas;
    c.removeEventListener('pointerdown', this.onDown);
    c.removeEventListener('pointermove', this.onMove);
    c.removeEventListener('pointerup', this.onUp);
    c.removeEventListener('pointercancel', this.onUp);
    c.removeEventListener('lostpointercapture', this.onUp);
    c.removeEventListener('wheel', this.onWheel);
    c.removeEventListener('contextmenu', this.onContextMenu);
    this.element.removeEventListener('keydown', this.onKey);
    this.cancel();
  }

  /** Stops any gesture and motion in progress (mode change, disconnection); the host ends the gesture. */
  cancel(): void {
    this.pointers.clear();
    this.drag = null;
    this.moved = false;
    this.spin.stop();
    clearTimeout(this.wheelTimer);
    this.wheelTimer = undefined;
  }

  /** The orbit's centre after the last gesture (a pan moves it). */
  get orbitTarget(): ArrayLike<number> {
    return this.orbit.target;
  }

  /** Whether a pan moved the orbit's centre since the last call. */
  takePanned(): boolean {
    const p = this.panned;
    this.panned = false;
    return p;
  }

  /** True while the motion after a release goes on. */
  get active(): boolean {
    return this.spin.active;
  }

  /**
   * Advances the motion after release to `now` (performance.now(), ms: the wall clock, whatever
   * the frames' own timestamps); true if anything moved.
   */
  update(now: number): boolean {
    if (!this.spin.active) return false;
    const mode = this.host.mode();
    if (mode === null) {
      this.spin.stop();
      return false;
    }
    const d = this.delta;
    const dt = (now - this.spinTime) / 1000;
    this.spinTime = now;
    if (!this.spin.step(dt, d)) return false;
    if (this.spinKind === 'orbit') {
      this.orbit.rotate(this.host.pose(), d[0] / DEG, d[1] / DEG);
    } else {
      const angle = Math.hypot(d[0], d[1], d[2]);
      if (angle > 0) {
        vec3.set(this.axis, d[0] / angle, d[1] / angle, d[2] / angle);
        quat.setAxisAngle(this.q, this.axis, angle);
        quat.multiply(this.objectRotation, this.q, this.objectRotation);
        quat.normalize(this.objectRotation, this.objectRotation);
      }
    }
    if (!this.spin.active) this.host.gestureEnd();
    return true;
  }

  // ---- pointers --------------------------------------------------------------------------

  private readonly onContextMenu = (e: Event): void => {
    if (this.host.mode() !== null) e.preventDefault(); // right-drag is ours
  };

  private readonly onDown = (e: PointerEvent): void => {
    const mode = this.host.mode();
    if (mode === null) return;
    e.preventDefault();
    this.element.focus({ preventScroll: true });
    try { this.canvas.setPointerCapture(e.pointerId); } catch { /* synthetic pointer */ }
    const r = this.canvas.getBoundingClientRect();
    this.rect.left = r.left; this.rect.top = r.top; this.rect.width = r.width || 1; this.rect.height = r.height || 1;
    this.pointers.set(e.pointerId, { x: e.clientX - r.left, y: e.clientY - r.top });
    this.spin.stop();
    if (this.pointers.size === 1) this.orbit.begin(this.host.pose(), this.host.target());
    this.startDrag(e, mode);
  };

  /** A drag begins (or begins again with the pointers now down): from where they are, no jump. */
  private startDrag(e: PointerEvent, mode: PointerMode): void {
    const n = this.pointers.size;
    if (n >= 2) {
      this.drag = 'pinch';
      this.pinchState();
      return;
    }
    const p = this.pointers.values().next().value!;
    this.last.x = p.x;
    this.last.y = p.y;
    const alternate = e.button === 2 || e.shiftKey;
    this.drag = e.button === 1 ? 'pan' : alternate ? (mode === 'trackball' ? 'light' : 'pan') : 'rotate';
    this.spinKind = mode;
    this.velocity.reset(e.timeStamp);
  }

  private pinchState(): void {
    let x = 0, y = 0;
    const ps = [...this.pointers.values()].slice(0, 2);
    for (const p of ps) { x += p.x / 2; y += p.y / 2; }
    this.last.x = x;
    this.last.y = y;
    this.span = Math.hypot(ps[0].x - ps[1].x, ps[0].y - ps[1].y);
  }

  private readonly onMove = (e: PointerEvent): void => {
    const p = this.pointers.get(e.pointerId);
    const mode = this.host.mode();
    if (!p || mode === null || this.drag === null) return;
    p.x = e.clientX - this.rect.left;
    p.y = e.clientY - this.rect.top;
    const pose = this.host.pose();
    if (this.drag === 'pinch') {
      const lx = this.last.x, ly = this.last.y, span = this.span, d = this.orbit.distance;
      this.pinchState();
      if (span > 0 && this.span > 0) this.orbit.dolly(pose, span / this.span);
      // About the fingers: the dolly moves a point drawn m px off the centre (at the target's
      // depth) to m/k, so the pan takes it from there to under the fingers' new midpoint.
      const k = this.orbit.distance / d, cx = this.rect.width / 2, cy = this.rect.height / 2;
      this.orbit.pan(pose, this.last.x - cx - (lx - cx) / k, this.last.y - cy - (ly - cy) / k, this.rect.height, this.host.fov());
      this.panned = true;
    } else {
      const dx = p.x - this.last.x, dy = p.y - this.last.y;
      if (this.drag === 'pan') {
        this.orbit.pan(pose, dx, dy, this.rect.height, this.host.fov());
        this.panned = true;
      } else if (this.drag === 'rotate' && mode === 'orbit') {
        let yaw = dx * ORBIT_DEG_PER_PX, pitch = -dy * ORBIT_DEG_PER_PX;
        const m = Math.hypot(yaw, pitch);
        if (m > MAX_EVENT_TURN) { yaw *= MAX_EVENT_TURN / m; pitch *= MAX_EVENT_TURN / m; }
        this.orbit.rotate(pose, yaw, pitch);
        this.delta[0] = yaw * DEG; this.delta[1] = pitch * DEG; this.delta[2] = 0;
        this.velocity.add(e.timeStamp, this.delta);
      } else {
        this.arcball(this.last.x, this.last.y, p.x, p.y, this.drag === 'light' ? this.lightRotation : this.objectRotation);
        if (this.drag === 'rotate') this.velocity.add(e.timeStamp, this.delta);
      }
      this.last.x = p.x;
      this.last.y = p.y;
    }
    this.moved = true;
    this.host.changed(this.drag === 'pinch' || this.drag === 'pan' || mode === 'orbit');
  };

  private readonly onUp = (e: PointerEvent): void => {
    if (!this.pointers.delete(e.pointerId)) return;
    const mode = this.host.mode();
    if (mode === null) return;
    if (this.pointers.size > 0) {
      this.startDrag(e, mode); // two fingers to one: go on from where the other finger is
      return;
    }
    if (this.drag === 'rotate') {
      this.velocity.rates(e.timeStamp, this.delta);
      this.spin.start(this.delta);
      this.spinTime = performance.now(); // the motion runs from the release, on the wall clock
    }
    this.drag = null;
    if (this.spin.active) this.host.changed(this.spinKind === 'orbit');
    else if (this.moved) this.end();
  };

  /**
   * Turns `target` by the arcball rotation of a drag from (x0, y0) to (x1, y1), at most
   * MAX_EVENT_TURN; leaves the world rotation vector in `delta`.
   */
  private arcball(x0: number, y0: number, x1: number, y1: number, target: quat): void {
    const { width, height } = this.rect;
    arcballPoint(this.a, x0, y0, width, height);
    arcballPoint(this.b, x1, y1, width, height);
    vec3.cross(this.axis, this.a, this.b);
    const s = vec3.length(this.axis);
    let angle = Math.atan2(s, vec3.dot(this.a, this.b));
    this.delta.fill(0);
    if (!(s > 1e-12) || !(angle > 0)) return;
    angle = Math.min(angle, MAX_EVENT_TURN * DEG);
    // View space → world: x along the camera's right, y its up, z towards the viewer.
    const pose = this.host.pose();
    const f = forwardFromYawPitch(this.f, pose.yaw, pose.pitch);
    const h = Math.hypot(f[0], f[2]) || 1;
    const rx = -f[2] / h, rz = f[0] / h;
    const ux = -rz * f[1], uy = rz * f[0] - rx * f[2], uz = rx * f[1];
    const vx = this.axis[0] / s, vy = this.axis[1] / s, vz = this.axis[2] / s;
    vec3.set(this.axis, vx * rx + vy * ux - vz * f[0], vy * uy - vz * f[1], vx * rz + vy * uz - vz * f[2]);
    vec3.normalize(this.axis, this.axis);
    quat.setAxisAngle(this.q, this.axis, angle);
    quat.multiply(target, this.q, target);
    quat.normalize(target, target);
    this.delta[0] = this.axis[0] * angle; this.delta[1] = this.axis[1] * angle; this.delta[2] = this.axis[2] * angle;
  }

  // ---- wheel and keys --------------------------------------------------------------------

  private readonly onWheel = (e: WheelEvent): void => {
    if (this.host.mode() === null) return;
    e.preventDefault();
    const lines = e.deltaMode === 1 ? 16 : e.deltaMode === 2 ? this.canvas.clientHeight || 400 : 1;
    const dy = Math.max(-200, Math.min(200, e.deltaY * lines)); // one event, one normal step
    if (this.wheelTimer === undefined) this.orbit.begin(this.host.pose(), this.host.target());
    this.orbit.dolly(this.host.pose(), Math.exp(dy * WHEEL_RATE));
    this.moved = true;
    this.host.changed(true);
    clearTimeout(this.wheelTimer);
    this.wheelTimer = setTimeout(() => {
      this.wheelTimer = undefined;
      this.end();
    }, WHEEL_END_MS);
  };

  private readonly onKey = (e: KeyboardEvent): void => {
    const mode = this.host.mode();
    if (mode === null || e.altKey || e.ctrlKey || e.metaKey) return;
    let yaw = 0, pitch = 0, dolly = 1;
    switch (e.key) {
      case 'ArrowLeft': yaw = -KEY_TURN; break;
      case 'ArrowRight': yaw = KEY_TURN; break;
      case 'ArrowUp': pitch = KEY_TURN; break;
      case 'ArrowDown': pitch = -KEY_TURN; break;
      case '+': case '=': dolly = 1 / KEY_DOLLY; break;
      case '-': case '_': dolly = KEY_DOLLY; break;
      default: return;
    }
    e.preventDefault(); // the arrows would scroll the page
    this.spin.stop();
    const pose = this.host.pose();
    this.orbit.begin(pose, this.host.target());
    if (dolly !== 1) this.orbit.dolly(pose, dolly);
    else if (mode === 'orbit') this.orbit.rotate(pose, yaw, pitch);
    else {
      // The objects turn as a drag from the centre would turn them: right turns them right.
      // On the sphere near its centre a drag of sin(θ)·r turns by θ.
      const r = 100;
      this.rect.width = this.rect.height = 2 * r;
      this.arcball(r, r, r + Math.sin(yaw * DEG) * r, r - Math.sin(pitch * DEG) * r, this.objectRotation);
    }
    this.moved = true;
    this.host.changed(dolly !== 1 || mode === 'orbit');
    this.end();
  };

  private end(): void {
    this.moved = false;
    this.host.gestureEnd();
  }
}
