// Motion after release (docs/interaction.md#inertia): rates that decay as e^(−t/τ), t the wall-clock time since
// the release, advanced exactly for any frame time, so the motion after release is the same at
// 13, 30 and 144 frames per second. Each step turns by ∫ r·e^(−s/τ) ds over the step =
// r·τ·(1 − e^(−dt/τ)), and the rates become r·e^(−dt/τ): the steps telescope to
// r₀·τ·(1 − e^(−T/τ)) whatever the frames were. Rates are in radians per second throughout.

/** Decay time constant, seconds (docs/interaction.md#inertia: ≤ 0.5 s). */
export const INERTIA_TAU = 0.35;
/** Below this rate (rad/s; docs/interaction.md#inertia: 0.05°/s) the motion stops and no more frames are drawn. */
export const INERTIA_STOP = (0.05 * Math.PI) / 180;
/** No inertia when the pointer rested this long (ms) before release. */
export const REST_MS = 100;
/** The release rate is measured over the last this-many ms of the drag. */
export const VELOCITY_WINDOW_MS = 80;
/**
 * Longest stretch of time one step turns by, seconds: a frame after a stall (a hidden tab, a
 * 1-second frame) turns no further than a 4 Hz frame would, while the rates still decay by the
 * whole time, so a stall never slows the clock. Exact for every frame rate at or above 4 Hz
 * (a slow software frame included).
 */
export const MAX_STEP = 0.25;
/** Fastest release rate, rad/s (a flick faster than a turn per second spins at one). */
export const MAX_RATE = 2 * Math.PI;

export class Inertia {
  /** Current rates per component, rad/s. */
  readonly rates: Float64Array;

  constructor(components: number) {
    this.rates = new Float64Array(components);
  }

  get active(): boolean {
    return this.magnitude() >= INERTIA_STOP;
  }

  /** Starts from `rates` (per second), scaled down to MAX_RATE in magnitude. */
  start(rates: ArrayLike<number>): void {
    for (let i = 0; i < this.rates.length; i++) this.rates[i] = Number.isFinite(rates[i]) ? rates[i] : 0;
    const m = this.magnitude();
    if (m > MAX_RATE) for (let i = 0; i < this.rates.length; i++) this.rates[i] *= MAX_RATE / m;
    if (m < INERTIA_STOP) this.stop();
  }

  stop(): void {
    this.rates.fill(0);
  }

  /**
   * Advances by `dt` seconds of wall-clock time (NaN or negative: none) and writes the
   * displacement of this step, over at most MAX_STEP of it, into `out`; returns false (and
   * writes zeros) when at rest.
   */
  step(dt: number, out: Float64Array): boolean {
    out.fill(0);
    if (!this.active) return false;
    const t = dt > 0 ? dt : 0;
    const k = Math.exp(-t / INERTIA_TAU);
    const s = Math.min(t, MAX_STEP);
    const ks = s === t ? k : Math.exp(-s / INERTIA_TAU);
    const f = INERTIA_TAU * (1 - ks);
    for (let i = 0; i < this.rates.length; i++) {
      out[i] = this.rates[i] * f;
      this.rates[i] *= k;
    }
    if (!this.active) this.stop();
    return true;
  }

  private magnitude(): number {
    let s = 0;
    for (let i = 0; i < this.rates.length; i++) s += this.rates[i] * this.rates[i];
    return Math.sqrt(s);
  }
}

/**
 * Release rates from a drag's recent displacements (one per event, since the event before; event
 * timeStamps in ms): the sum of those in the last VELOCITY_WINDOW_MS over the time they took;
 * zeros when the pointer rested more than REST_MS before the release. No allocation per event.
 */
export class VelocityTracker {
  private readonly times: Float64Array;
  private readonly deltas: Float64Array;
  private count = 0;
  private head = 0;
  private start = 0;

  constructor(private readonly components: number, private readonly capacity = 16) {
    this.times = new Float64Array(capacity);
    this.deltas = new Float64Array(capacity * components);
  }

  /** A drag begins at `time` (ms). */
  reset(time: number): void {
    this.count = 0;
    this.head = 0;
    this.start = time;
  }

  /** One event's displacement at `time`. */
  add(time: number, delta: ArrayLike<number>): void {
    const i = this.head;
    // Full: the oldest sample is dropped, and its time is where the new oldest one's motion began.
    if (this.count === this.capacity) this.start = this.times[i];
    this.times[i] = time;
    for (let c = 0; c < this.components; c++) this.deltas[i * this.components + c] = delta[c];
    this.head = (i + 1) % this.capacity;
    if (this.count < this.capacity) this.count++;
  }

  /** Rates per second at release time `releaseTime` (ms) into `out`. */
  rates(releaseTime: number, out: Float64Array): Float64Array {
    out.fill(0);
    if (this.count === 0) return out;
    const last = (this.head - 1 + this.capacity) % this.capacity;
    const lastTime = this.times[last];
    if (releaseTime - lastTime > REST_MS) return out;
    let from = lastTime;
    let n = 0;
    for (; n < this.count; n++) {
      const i = (last - n + this.capacity) % this.capacity;
      if (lastTime - this.times[i] > VELOCITY_WINDOW_MS) break;
      for (let c = 0; c < this.components; c++) out[c] += this.deltas[i * this.components + c];
      const prev = n + 1 < this.count ? this.times[(i - 1 + this.capacity) % this.capacity] : this.start;
      from = prev;
    }
    const span = (lastTime - from) / 1000;
    if (!(span > 0)) return out.fill(0);
    for (let c = 0; c < this.components; c++) out[c] /= span;
    return out;
  }
}
