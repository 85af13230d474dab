// DOM input → FlybyController: keys on the focused host, pointer-lock mouse look on the canvas.
// Listeners live only between attach() and detach(), so two elements never share input.
import type { FlybyController } from './flyby-controller';

export interface FlybyInputHooks {
  /** Are controls enabled (the `controls` attribute)? */
  enabled(): boolean;
  /** A key started motion or the mouse turned the camera: draw. */
  moved(byMouse: boolean): void;
  /** The debug-view key (F) was pressed. */
  cycleDebugView(): void;
  /** A key is about to be released: account for the motion since the last frame first. */
  settle(): void;
}

const DEBUG_KEY = 'KeyF';

export class FlybyInput {
  constructor(
    private readonly host: HTMLElement,
    private readonly canvas: HTMLCanvasElement,
    private readonly flyby: FlybyController,
    private readonly hooks: FlybyInputHooks,
  ) {}

  attach(): void {
    this.host.addEventListener('keydown', this.onKeyDown);
    this.host.addEventListener('keyup', this.onKeyUp);
    this.host.addEventListener('blur', this.onBlur);
    this.canvas.addEventListener('click', this.onClick);
    this.canvas.addEventListener('mousemove', this.onMouseMove);
    document.addEventListener('pointerlockchange', this.onLockChange);
  }

  detach(): void {
    this.host.removeEventListener('keydown', this.onKeyDown);
    this.host.removeEventListener('keyup', this.onKeyUp);
    this.host.removeEventListener('blur', this.onBlur);
    this.canvas.removeEventListener('click', this.onClick);
    this.canvas.removeEventListener('mousemove', this.onMouseMove);
    document.removeEventListener('pointerlockchange', this.onLockChange);
    this.flyby.releaseAll();
  }

  private readonly onKeyDown = (e: KeyboardEvent): void => {
    if (!this.hooks.enabled() || e.altKey || e.ctrlKey || e.metaKey) return;
    if (e.code === DEBUG_KEY) {
      if (!e.repeat) this.hooks.cycleDebugView();
      return;
    }
    if (this.flyby.keyDown(e.code)) {
      e.preventDefault(); // Space and the arrows would scroll the page
      this.hooks.moved(false);
    }
  };

  private readonly onKeyUp = (e: KeyboardEvent): void => {
    if (this.flyby.active) this.hooks.settle();
    if (this.flyby.keyUp(e.code)) e.preventDefault();
  };

  private readonly onBlur = (): void => {
    this.flyby.releaseAll();
  };

  private locked(): boolean {
    return (this.host.shadowRoot?.pointerLockElement ?? null) === this.canvas;
  }

  private readonly onClick = (): void => {
    if (!this.hooks.enabled() || this.locked()) return;
    this.host.focus();
    try {
      // Refusal (headless, iframes without allow-pointer-lock) leaves keyboard look working.
      const p = this.canvas.requestPointerLock() as unknown as Promise<void> | undefined;
      p?.catch?.(() => {});
    } catch { /* pointer lock unavailable */ }
  };

  /**
   * The first movement after entering pointer lock carries the jump from where the pointer was
   * to the lock's centre (Chrome has reported (−528, −377) px): it is dropped, not turned by.
   */
  private skipNext = false;
  private readonly onLockChange = (): void => {
    this.skipNext = true;
  };

  private readonly onMouseMove = (e: MouseEvent): void => {
    if (!this.hooks.enabled() || !this.locked()) return;
    if (this.skipNext) {
      this.skipNext = false;
      return;
    }
    if (this.flyby.look(e.movementX, e.movementY)) this.hooks.moved(true);
  };
}
