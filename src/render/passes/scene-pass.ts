// Pass 2: the objects from the real eye, depth-tested. `depthOnly` primes depth for the
// Fresnel debug view without writing colour. `selection`: with rough glass the opaque objects
// before it and the transparent ones after it (renderer.ts).
import { drawObjects, prepareObjectPrograms, type Selection } from './draw-objects';
import type { PassContext } from './pass-context';

/** Draws into the bound framebuffer and viewport; returns the number of draw calls. */
export function scenePass(ctx: PassContext, depthOnly = false, selection: Selection = 'all'): number {
  const { gl } = ctx;
  prepareObjectPrograms(ctx, 'none');
  gl.enable(gl.DEPTH_TEST);
  // A course camera with one negative half-size (or looking away) mirrors the picture.
  if (ctx.setup.mirrorsWinding) gl.frontFace(gl.CW);
  if (depthOnly) gl.colorMask(false, false, false, false);
  try {
    return drawObjects(ctx, 'none', false, ctx.state.height, null, selection);
  } finally {
    if (depthOnly) gl.colorMask(true, true, true, true);
    gl.frontFace(gl.CCW);
    gl.disable(gl.DEPTH_TEST);
  }
}
