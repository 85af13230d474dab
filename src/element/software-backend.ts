// Frames drawn by the CPU renderer (docs/software-renderer.md#worker), in its worker while the page goes on; one at a time
// (a change while it draws is drawn next). The pixels reach the canvas in one piece when the
// frame is complete: by a 2D context, or by a bitmap renderer when WebGL had the canvas first.
import { passesFor, type ReadbackSource } from '../render/renderer';
import type { FrameState } from '../frame/types';
import type { Scene } from '../scene/scene';
import type { DecodedImage } from '../scene/decoded-image';
import type { Backend, BackendHost } from './backend';
import type { SoftwareHost } from './software-host';


export class SoftwareBackend implements Backend {
  readonly kind = 'software';
  /** A frame is drawing; another is wanted when it is back. */
  busy = false;
  /** Disposed: a frame still on its way is dropped. */
  private disposed = false;
  /** How frames reach the canvas: a 2D context, or (after WebGL used it) a bitmap renderer. */
  private readonly out: CanvasRenderingContext2D | ImageBitmapRenderingContext | null;

  constructor(private readonly host: BackendHost, private readonly software: SoftwareHost) {
    const canvas = host.canvas;
    this.out = canvas.getContext('2d', { alpha: false }) ?? canvas.getContext('bitmaprenderer');
  }

  get thread(): 'worker' | 'main' {
    return this.software.thread;
  }

  /** ImageSink: the host keeps it (and sends it to each worker once). */
  setImage(url: string, image: DecodedImage | null): void {
    this.software.setImage(url, image);
  }

  /** The CPU renderer's chunk carries all it draws with: nothing to wait for. */
  waitsFor(): boolean {
    return false;
  }

  draw(scene: Scene, state: FrameState): void {
    const canvas = this.host.canvas;
    const { width, height } = canvas;
    this.busy = true;
    const frozen: FrameState = { ...state };
    void this.software.render(scene, frozen).then((pixels) => {
      if (this.disposed) return;
      this.busy = false;
      if (canvas.width !== width || canvas.height !== height) {
        this.host.requestRender(); // resized while it drew: draw again at the new size
        return;
      }
      const image = new ImageData(pixels as Uint8ClampedArray<ArrayBuffer>, width, height);
      const out = this.out;
      const glassSkip = frozen.view === 'final' && !scene.glass ? 'no glass' : undefined;
      const done = () => {
        if (this.disposed) return;
        this.host.drawn(frozen, { time: frozen.time, width, height, drawCalls: 0, passes: passesFor(frozen.view, glassSkip) });
        this.host.resume(this.software.thread === 'worker');
      };
      if (out && 'putImageData' in out) {
        out.putImageData(image, 0, 0);
        done();
      } else if (out) {
        // The canvas held WebGL's frames (a bitmap renderer): the frame counts once it is shown.
        void createImageBitmap(image).then((b) => {
          if (!this.disposed) (out as ImageBitmapRenderingContext).transferFromImageBitmap(b);
          done();
        });
      } else done();
    });
  }

  /** Drawn now, on this thread (capture is synchronous). */
  capture(scene: Scene, state: FrameState, source: ReadbackSource): ImageData | null {
    const s: FrameState = { ...state, view: source as FrameState['view'] };
    const pixels = this.software.renderNow(scene, s) as Uint8ClampedArray<ArrayBuffer>;
    return new ImageData(pixels, s.width, s.height);
  }

  stats(): null {
    return null;
  }

  dispose(): null {
    this.disposed = true;
    this.busy = false;
    this.software.dispose();
    return null;
  }
}
