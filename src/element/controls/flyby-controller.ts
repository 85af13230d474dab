// Keys and mouse → flyby camera pose (docs/interaction.md#flyby); no DOM, no GL.
import { clampPitch, forwardFromYawPitch, setPose, wrapYaw, type CameraPose } from '../../math/camera';

export interface FlybyOptions {
  /** Units per second (3 by default). */
  speed?: number;
  /** Degrees per pointer-lock pixel (0.002 rad by default). */
  sensitivity?: number;
  /** Degrees per second for the arrow-key look. */
  turnRate?: number;
  /** Longest step in seconds; a stalled tab must not teleport the camera (0.1 by default). */
  maxDt?: number;
}

/** The most one mouse event turns the camera, degrees (docs/interaction.md#no-jumps). */
export const MAX_LOOK_STEP = 5;

const DEFAULTS: Required<FlybyOptions> = {
  speed: 3,
  sensitivity: 0.002 * (180 / Math.PI),
  turnRate: 90,
  maxDt: 0.1,
};

// One bit per held key; both Shift keys mean "down" but are tracked apart, so releasing
// one while the other is still held keeps the camera sinking.
const FORWARD = 1, BACK = 2, LEFT = 4, RIGHT = 8, UP = 16, DOWN_L = 32, DOWN_R = 64;
const TURN_LEFT = 128, TURN_RIGHT = 256, LOOK_UP = 512, LOOK_DOWN = 1024;
const DOWN = DOWN_L | DOWN_R;

const KEY_BITS: ReadonlyMap<string, number> = new Map([
  ['KeyW', FORWARD], ['KeyS', BACK], ['KeyA', LEFT], ['KeyD', RIGHT],
  ['Space', UP], ['ShiftLeft', DOWN_L], ['ShiftRight', DOWN_R],
  ['ArrowLeft', TURN_LEFT], ['ArrowRight', TURN_RIGHT], ['ArrowUp', LOOK_UP], ['ArrowDown', LOOK_DOWN],
]);

function option(value: number | undefined, fallback: number): number {
  return value !== undefined && Number.isFinite(value) && value >= 0 ? value : fallback;
}

/** +1, −1 or 0 from a pair of opposite keys (both held cancel). */
function axis(held: number, plus: number, minus: number): number {
  return ((held & plus) !== 0 ? 1 : 0) - ((held & minus) !== 0 ? 1 : 0);
}

export class FlybyController {

  private readonly speed: number;
  private readonly sensitivity: number;
  private readonly turnRate: number;
  private readonly maxDt: number;
  private held = 0;
  // Preallocated so update() allocates nothing.
  private readonly forward = new Float64Array(3);

  /**
   * `pose`: the live pose it moves, the element's (camera-position / camera-rotation land there
   * too); the element keeps it while this controller is not loaded.
   */
  constructor(options: FlybyOptions = {}, readonly pose: CameraPose = { position: [0, 0, 0], yaw: -90, pitch: 0 }) {
    this.speed = option(options.speed, DEFAULTS.speed);
    this.sensitivity = option(options.sensitivity, DEFAULTS.sensitivity);
    this.turnRate = option(options.turnRate, DEFAULTS.turnRate);
    this.maxDt = option(options.maxDt, DEFAULTS.maxDt);
  }

  /** Copies a pose in; yaw is wrapped, pitch clamped, non-finite components leave the old value. */
  setPose(position: readonly [number, number, number], yaw: number, pitch: number): void {
    setPose(this.pose, position, yaw, pitch);
  }

  /** Returns true if the controller handles the key (the element then calls preventDefault). */
  keyDown(code: string): boolean {
    const bit = KEY_BITS.get(code);
    if (bit === undefined) return false;
    this.held |= bit;
    return true;
  }

  keyUp(code: string): boolean {
    const bit = KEY_BITS.get(code);
    if (bit === undefined) return false;
    this.held &= ~bit;
    return true;
  }

  /**
   * Pointer-lock movement in CSS pixels: yaw += dx·sens, pitch −= dy·sens, at most
   * MAX_LOOK_STEP degrees per event (docs/interaction.md#no-jumps: no single event turns the camera more than 5°).
   * True if the pose changed.
   */
  look(dx: number, dy: number): boolean {
    if (!Number.isFinite(dx) || !Number.isFinite(dy)) return false;
    let yaw = dx * this.sensitivity, pitch = -dy * this.sensitivity;
    const m = Math.hypot(yaw, pitch);
    if (m > MAX_LOOK_STEP) {
      yaw *= MAX_LOOK_STEP / m;
      pitch *= MAX_LOOK_STEP / m;
    }
    return this.rotate(yaw, pitch);
  }

  /** Drops every held key (on blur, so a key released elsewhere does not stick). */
  releaseAll(): void {
    this.held = 0;
  }

  /** True while any movement or turn key is held. */
  get active(): boolean {
    return this.held !== 0;
  }

  /** Advances by dt seconds, clamped to [0, maxDt] (NaN → 0). True if the pose changed. */
  update(dt: number): boolean {
    const t = dt > 0 ? Math.min(dt, this.maxDt) : 0; // NaN fails `> 0`
    if (t === 0 || this.held === 0) return false;
    const held = this.held;

    const turn = this.turnRate * t;
    let changed = this.rotate(axis(held, TURN_RIGHT, TURN_LEFT) * turn, axis(held, LOOK_UP, LOOK_DOWN) * turn);

    const f = forwardFromYawPitch(this.forward, this.pose.yaw, this.pose.pitch);
    // forwardFlat = normalize(fx, 0, fz); right = normalize(cross(forward, +Y)) = normalize(−fz, 0, fx).
    // Both have the length of (fx, fz); pitch is clamped so it is never zero, but guard anyway.
    const flat = Math.hypot(f[0], f[2]);
    const fx = flat > 0 ? f[0] / flat : 0;
    const fz = flat > 0 ? f[2] / flat : 0;
    const fwd = axis(held, FORWARD, BACK);
    const side = axis(held, RIGHT, LEFT);
    const up = (held & UP ? 1 : 0) - (held & DOWN ? 1 : 0);

    const mx = fwd * fx - side * fz;
    const my = up;
    const mz = fwd * fz + side * fx;
    const len = Math.hypot(mx, my, mz);
    if (len > 0) {
      const s = (this.speed * t) / len;
      const p = this.pose.position;
      p[0] += mx * s;
      p[1] += my * s;
      p[2] += mz * s;
      changed = changed || s > 0;
    }
    return changed;
  }

  private rotate(dYaw: number, dPitch: number): boolean {
    const p = this.pose;
    const yaw = wrapYaw(p.yaw + dYaw);
    const pitch = clampPitch(p.pitch + dPitch);
    if (yaw === p.yaw && pitch === p.pitch) return false;
    p.yaw = yaw;
    p.pitch = pitch;
    return true;
  }
}
