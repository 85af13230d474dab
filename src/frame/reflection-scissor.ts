// Where the screen lands in the reflection target: its size, and the glass's rectangle in its texels.
// The target is the drawing buffer × reflection-scale, clamped to the GL limits; the glass reads it
// with normalised coordinates, so screen pixel x maps to texel x × (target width ÷ screen width),
// whatever the nominal scale was.
import type { ScreenRect } from './glass-bounds';
import type { Viewport } from './types';

/** One side of the reflection target: `side` × `scale`, rounded, within 1..`max`. */
export function reflectionTargetSide(side: number, scale: number, max: number): number {
  return Math.max(1, Math.min(max, Math.round(side * scale)));
}

/**
 * The glass's screen rectangle `rect` (on a `width` × `height` screen) in the texels of a
 * `targetWidth` × `targetHeight` reflection, one texel wider on each side for bilinear reads.
 * Written into `out`.
 */
export function reflectionScissor(
  rect: ScreenRect, width: number, height: number, targetWidth: number, targetHeight: number, out: Viewport,
): Viewport {
  const sx = targetWidth / width;
  const sy = targetHeight / height;
  const x0 = Math.max(0, Math.floor(rect.x0 * sx) - 1);
  const y0 = Math.max(0, Math.floor(rect.y0 * sy) - 1);
  const x1 = Math.min(targetWidth, Math.ceil(rect.x1 * sx) + 1);
  const y1 = Math.min(targetHeight, Math.ceil(rect.y1 * sy) + 1);
  out.x = x0;
  out.y = y0;
  out.width = Math.max(0, x1 - x0);
  out.height = Math.max(0, y1 - y0);
  return out;
}
