// Pass 2: the objects from the real eye, depth-tested. `depthOnly` primes depth for the
// Fresnel debug view without writing colour.
import { drawObjects, prepareObjectPrograms } from './draw-objects';
import type { PassContext } from './pass-context';

/** Draws into the bound framebuffer and viewport; returns the number of draw calls. */
export function scenePass(ctx: PassContext, depthOnly = false): number {
  const { gl } = ctx;
  prepareObjectPrograms(ctx, 'none');
  gl.enable(gl.DEPTH_TEST);
  // A course camera with one negative half-size (or looking away) mirrors the picture.
  if (ctx.setup.mirrorsWinding) gl.frontFace(gl.CW);
  if (depthOnly) gl.colorMask(false, false, false, false);
  try {
    return drawObjects(ctx, 'none', false, ctx.state.height);
  } finally {
    if (depthOnly) gl.colorMask(true, true, true, true);
    gl.frontFace(gl.CCW);
    gl.disable(gl.DEPTH_TEST);
  }
}
