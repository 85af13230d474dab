// Pass 1: the eye's side of the glass, seen through the mirror (view × reflection), into an FBO.
// What lies beyond the glass is clipped on the GPU (gl_ClipDistance, or discard without the
// extension); an object whose bounds lie wholly beyond it is culled, not drawn.
import { drawObjects, prepareObjectPrograms } from './draw-objects';
import { beginTarget, type PassContext, type Viewport } from './pass-context';

/** The whole target, filled in place each frame. */
const full: Viewport = { x: 0, y: 0, width: 0, height: 0 };

/** Returns the number of draw calls. */
export function reflectionPass(ctx: PassContext, framebuffer: WebGLFramebuffer, width: number, height: number): number {
  const { gl, clipExtension, scissor } = ctx;
  const clip = clipExtension ? 'clip-distance' : 'discard';
  // First, before any state is set: a variant that fails to compile throws, and the element
  // draws again later (another variant, a restored context) from clean state.
  prepareObjectPrograms(ctx, clip);
  full.width = width;
  full.height = height;
  // Scissored to the glass: only texels the glass pass can read are cleared and drawn.
  beginTarget(gl, framebuffer, full, ctx.background, scissor ?? full);
  if (scissor) {
    gl.enable(gl.SCISSOR_TEST);
    gl.scissor(scissor.x, scissor.y, scissor.width, scissor.height);
  }
  gl.enable(gl.DEPTH_TEST);
  // The mirror flips winding, and so does a mirroring course camera (docs/course-files.md#the-course-camera).
  gl.frontFace(ctx.setup.mirrorsWinding ? gl.CCW : gl.CW);
  if (clipExtension) gl.enable(clipExtension.CLIP_DISTANCE0_WEBGL);
  try {
    return drawObjects(ctx, clip, true, height);
  } finally {
    gl.disable(gl.SCISSOR_TEST);
    if (clipExtension) gl.disable(clipExtension.CLIP_DISTANCE0_WEBGL);
    gl.frontFace(gl.CCW);
    gl.disable(gl.DEPTH_TEST);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  }
}
