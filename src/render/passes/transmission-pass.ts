// Rough glass's frame beyond the glass (docs/rough-glass.md#transmission: "radiance arriving at P from the far side"):
// the objects from the real eye, clipped to the far side of the glass as pass 1 is clipped to
// the viewer's side (the plane flipped), into an off-screen target; the background where
// nothing is. What lies in the glass plane stays (a picture behind a glass wall is seen through it).
import { eyeRelativePlane, MIRROR_CONTACT } from '../../math/mirror';
import { drawObjects, prepareObjectPrograms } from './draw-objects';
import { beginTarget, type PassContext, type Viewport } from './pass-context';

/** The whole target, and the far side's clip plane: filled in place each frame. */
const full: Viewport = { x: 0, y: 0, width: 0, height: 0 };
const farSide64 = new Float64Array(4);
const farSide = new Float32Array(4);

/** Returns the number of draw calls. */
export function transmissionPass(ctx: PassContext, framebuffer: WebGLFramebuffer, width: number, height: number): number {
  const { gl, clipExtension, setup } = ctx;
  const clip = clipExtension ? 'clip-distance' : 'discard';
  prepareObjectPrograms(ctx, clip);
  full.width = width;
  full.height = height;
  beginTarget(gl, framebuffer, full, ctx.background);
  // Keep −side·(n·x + d) + MIRROR_CONTACT ≥ 0: the far side and the plane itself.
  eyeRelativePlane(farSide64, setup.glass.plane, setup.eye, -setup.side);
  farSide64[3] += MIRROR_CONTACT;
  farSide.set(farSide64);
  gl.enable(gl.DEPTH_TEST);
  if (setup.mirrorsWinding) gl.frontFace(gl.CW);
  if (clipExtension) gl.enable(clipExtension.CLIP_DISTANCE0_WEBGL);
  try {
    return drawObjects(ctx, clip, false, height, farSide);
  } finally {
    if (clipExtension) gl.disable(clipExtension.CLIP_DISTANCE0_WEBGL);
    gl.frontFace(gl.CCW);
    gl.disable(gl.DEPTH_TEST);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  }
}
