// Pass 1: the eye's side of the glass, seen through the mirror (view × reflection), into an FBO.
// What lies beyond the glass is clipped on the GPU (gl_ClipDistance, or discard without the
// extension); an object whose bounds lie wholly beyond it is culled, not drawn.
import { BACKGROUND, CUBE, GLASS, SPHERE } from '../../scene/default-scene';
import { signedDistance } from '../../math/mirror';
import { beginTarget, setLighting, setMatrices, type PassContext, type Viewport } from './pass-context';

const CUBE_BOUND = (Math.sqrt(3) / 2) * CUBE.edge;
const centre = new Float64Array(3);
/** The whole target, filled in place each frame. */
const full: Viewport = { x: 0, y: 0, width: 0, height: 0 };

/** Returns the number of draw calls. */
export function reflectionPass(ctx: PassContext, framebuffer: WebGLFramebuffer, width: number, height: number): number {
  const { gl, setup, meshes, clipExtension, scissor } = ctx;
  // First, before any state is set: a variant that fails to compile throws, and the element
  // draws again later (another variant, a restored context) from clean state.
  const program = ctx.programs.standard(clipExtension ? 'clip-distance' : 'discard', ctx.state.shading);
  full.width = width;
  full.height = height;
  // Scissored to the glass: only texels the glass pass can read are cleared and drawn.
  beginTarget(gl, framebuffer, full, BACKGROUND, scissor ?? full);
  if (scissor) {
    gl.enable(gl.SCISSOR_TEST);
    gl.scissor(scissor.x, scissor.y, scissor.width, scissor.height);
  }
  let draws = 0;
  gl.enable(gl.DEPTH_TEST);
  gl.enable(gl.CULL_FACE);
  gl.frontFace(gl.CW); // the mirror flips winding
  if (clipExtension) gl.enable(clipExtension.CLIP_DISTANCE0_WEBGL);
  try {
    program.use();
    setLighting(gl, program);
    gl.uniform4fv(program.location('uClipPlane'), setup.clipPlane);
    ctx.texture.bind(0);

    centre[0] = CUBE.x; centre[1] = CUBE.y; centre[2] = ctx.state.cubeDistance;
    if (!ctx.cull || setup.side * signedDistance(GLASS.plane, centre) > -CUBE_BOUND) {
      setMatrices(gl, program, setup.mirrored.cube);
      gl.uniform3fv(program.location('uAlbedo'), CUBE.albedo);
      meshes.cube.draw();
      draws++;
    }
    if (!ctx.cull || setup.side * signedDistance(GLASS.plane, SPHERE.centre) > -SPHERE.radius) {
      setMatrices(gl, program, setup.mirrored.sphere);
      gl.uniform3fv(program.location('uAlbedo'), SPHERE.albedo);
      meshes.sphere.draw();
      draws++;
    }
  } finally {
    gl.disable(gl.SCISSOR_TEST);
    if (clipExtension) gl.disable(clipExtension.CLIP_DISTANCE0_WEBGL);
    gl.frontFace(gl.CCW);
    gl.disable(gl.CULL_FACE);
    gl.disable(gl.DEPTH_TEST);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  }
  return draws;
}
