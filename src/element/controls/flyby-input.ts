// DOM input → FlybyController: keys on the focused host, pointer-lock mouse look on the canvas.
// Listeners live only while the host is connected, so two elements never share input.
import type { FlybyController } from './flyby-controller';
import type { Controller } from '../controller';

/** What FlybyInput needs of the scene element. */
export interface FlybyInputHost {
  /** Takes the keys (focused) and blur. */
  readonly element: HTMLElement;
  /** Takes the clicks and the pointer-lock mouse. */
  readonly canvas: HTMLCanvasElement;
  /** The pose the input moves. */
  readonly flyby: FlybyController;
  /** Are flyby controls enabled (the `controls` attribute)? */
  enabled(): boolean;
  /** A key started motion or the mouse turned the camera: draw. */
  moved(byMouse: boolean): void;
  /** The debug-view key (F) was pressed. */
  cycleDebugView(): void;
  /** A key is about to be released: account for the motion since the last frame first. */
  settle(): void;
}

const DEBUG_KEY = 'KeyF';

export class FlybyInput implements Controller {
  private readonly element: HTMLElement;
  private readonly canvas: HTMLCanvasElement;
  private readonly flyby: FlybyController;

  constructor(private readonly host: FlybyInputHost) {
    this.element = host.element;
    this.canvas = host.canvas;
    this.flyby = host.flyby;
  }

  hostConnected(): void {
    this.element.addEventListener('keydown', this.onKeyDown);
    this.element.addEventListener('keyup', this.onKeyUp);
    this.element.addEventListener('blur', this.onBlur);
    this.canvas.addEventListener('click', this.onClick);
    this.canvas.addEventListener('mousemove', this.onMouseMove);
    document.addEventListener('pointerlockchange', this.onLockChange);
  }

  hostDisconnected(): void {
    this.element.removeEventListener('keydown', this.onKeyDown);
    this.element.removeEventListener('keyup', this.onKeyUp);
    this.element.removeEventListener('blur', this.onBlur);
    this.canvas.removeEventListener('click', this.onClick);
    this.canvas.removeEventListener('mousemove', this.onMouseMove);
    document.removeEventListener('pointerlockchange', this.onLockChange);
    this.flyby.releaseAll();
  }

  private readonly onKeyDown = (e: KeyboardEvent): void => {
    if (!this.host.enabled() || e.altKey || e.ctrlKey || e.metaKey) return;
    if (e.code === DEBUG_KEY) {
      if (!e.repeat) this.host.cycleDebugView();
      return;
    }
    if (this.flyby.keyDown(e.code)) {
      e.preventDefault(); // Space and the arrows would scroll the page
      this.host.moved(false);
    }
  };

  private readonly onKeyUp = (e: KeyboardEvent): void => {
    if (this.flyby.active) this.host.settle();
    if (this.flyby.keyUp(e.code)) e.preventDefault();
  };

  private readonly onBlur = (): void => {
    this.flyby.releaseAll();
  };

  private locked(): boolean {
    return (this.element.shadowRoot?.pointerLockElement ?? null) === this.canvas;
  }

  private readonly onClick = (): void => {
    if (!this.host.enabled() || this.locked()) return;
    this.element.focus();
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
    if (!this.host.enabled() || !this.locked()) return;
    if (this.skipNext) {
      this.skipNext = false;
      return;
    }
    if (this.flyby.look(e.movementX, e.movementY)) this.host.moved(true);
  };
}
