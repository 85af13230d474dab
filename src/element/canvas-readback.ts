// The pixels a canvas shows, whatever its context (bitmaprenderer or 2d), read through a 2D copy.
// capture() uses it to return exactly the frame that was presented, without drawing again: the
// shared GL context's drawing buffer has been handed over (transferToImageBitmap) or overwritten
// by other elements since, and keeping a copy of every frame would cost a readback per frame.

/** RGBA8, top row first; null when the canvas is empty-sized. */
export function readCanvas(source: HTMLCanvasElement): ImageData | null {
  const { width, height } = source;
  if (width === 0 || height === 0) return null;
  const scratch = typeof OffscreenCanvas === 'function' ? new OffscreenCanvas(width, height) : document.createElement('canvas');
  scratch.width = width;
  scratch.height = height;
  const ctx = scratch.getContext('2d', { willReadFrequently: true }) as CanvasRenderingContext2D | OffscreenCanvasRenderingContext2D | null;
  if (!ctx) return null;
  // Frames are opaque (every pass writes alpha 1), so a straight copy loses nothing to premultiplication.
  ctx.imageSmoothingEnabled = false;
  ctx.drawImage(source, 0, 0);
  return ctx.getImageData(0, 0, width, height);
}
