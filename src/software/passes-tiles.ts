// The `passes` debug view of the software renderer, tiled as the WebGL renderer tiles it:
// reflection | scene over fresnel | final, each drawn at its tile's size by the renderer itself.
import type { FrameState } from '../frame/types';

export class PassesTiles {
  private tiled = new Uint8ClampedArray(0);
  /** The state each tile is drawn with (reused). */
  private readonly tileState = {} as FrameState;

  /** `draw(tile)` draws one view at the tile's size (RGBA8, top row first); on an odd size the right column and the top row take the extra pixel. */
  draw(state: FrameState, draw: (tile: FrameState) => Uint8ClampedArray): Uint8ClampedArray {
    const width = Math.max(0, Math.floor(state.width)), height = Math.max(0, Math.floor(state.height));
    if (this.tiled.length !== 4 * width * height) this.tiled = new Uint8ClampedArray(4 * width * height);
    const left = Math.floor(width / 2), right = width - left;
    const bottom = Math.floor(height / 2), top = height - bottom;
    const tile = Object.assign(this.tileState, state);
    const put = (view: FrameState['view'], x: number, y: number, w: number, h: number) => {
      if (w === 0 || h === 0) return;
      tile.view = view;
      tile.width = w;
      tile.height = h;
      const px = draw(tile);
      for (let row = 0; row < h; row++) this.tiled.set(px.subarray(4 * row * w, 4 * (row + 1) * w), 4 * ((y + row) * width + x));
    };
    put('reflection', 0, 0, left, top);
    put('scene', left, 0, right, top);
    put('fresnel', 0, top, left, bottom);
    put('final', left, top, right, bottom);
    return this.tiled;
  }
}

/** Sets the RGB triples of pixels from..to (exclusive) of `buffer` to `rgb`. */
export function fill(buffer: Float32Array, from: number, to: number, rgb: ArrayLike<number>): void {
  if (rgb[0] === rgb[1] && rgb[1] === rgb[2]) {
    buffer.fill(rgb[0], 3 * from, 3 * to);
    return;
  }
  for (let o = 3 * from, end = 3 * to; o < end; o += 3) {
    buffer[o] = rgb[0]; buffer[o + 1] = rgb[1]; buffer[o + 2] = rgb[2];
  }
}
