// Pass 3: the two-sided glass, depth-tested without depth writes, blended over pass 2 with
// premultiplied alpha (ONE, ONE_MINUS_SRC_ALPHA). `outputFresnel` writes F as grey instead.
import { GLASS_BODY } from '../../scene/default-scene';
import { setMatrices, type PassContext } from './pass-context';
import { encodesAtEnd } from '../../frame/linear-light';

const BODY_TINT = new Float32Array(GLASS_BODY);

/** Draws into the bound framebuffer and viewport; returns the number of draw calls. */
export function glassPass(ctx: PassContext, reflection: WebGLTexture, outputFresnel = false): number {
  const { gl, setup, state } = ctx;
  const program = ctx.programs.glass(state.fresnel, outputFresnel);
  gl.enable(gl.DEPTH_TEST);
  gl.depthMask(false);
  // Pushed back a hair — a constant, not scaled by its depth slope, which at grazing incidence
  // let objects behind the glass cover it — so a face of an object on the viewer's side lying in
  // the glass plane stays in front of it instead of z-fighting; objects on the plane or beyond
  // it are pushed back further in the scene pass (draw-objects.ts), so the glass covers their
  // faces in the plane (a picture behind a glass wall, cube-distance −0.5 with spin 0).
  gl.polygonOffset(0, 1);
  if (!outputFresnel) {
    gl.enable(gl.BLEND);
    gl.blendFunc(gl.ONE, gl.ONE_MINUS_SRC_ALPHA);
  }
  try {
    program.use();
    setMatrices(gl, program, setup.glassMain);
    gl.uniformMatrix4fv(program.location('uReflectionViewProjection'), false, setup.reflectionViewProjection);
    gl.uniform1f(program.location('uTransparency'), state.transparency);
    gl.uniform1f(program.location('uIor'), state.ior);
    gl.uniform4fv(program.location('uViewVector'), setup.viewVectorMain);
    gl.uniform3fv(program.location('uBodyTint'), BODY_TINT);
    gl.uniform1f(program.location('uLinearFrame'), encodesAtEnd(state) ? 1 : 0);
    gl.uniform1i(program.location('uTexture'), 0);
    gl.uniform1i(program.location('uReflection'), 1);
    ctx.textures.procedural.bind(0);
    gl.activeTexture(gl.TEXTURE1);
    gl.bindTexture(gl.TEXTURE_2D, reflection);
    ctx.glassMesh.draw();
  } finally {
    gl.bindTexture(gl.TEXTURE_2D, null);
    gl.activeTexture(gl.TEXTURE0);
    gl.disable(gl.BLEND);
    gl.disable(gl.POLYGON_OFFSET_FILL);
    gl.depthMask(true);
    gl.disable(gl.DEPTH_TEST);
  }
  return 1;
}
