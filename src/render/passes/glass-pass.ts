// Pass 3: the two-sided glass, depth-tested without depth writes, blended over pass 2 with
// premultiplied alpha (ONE, ONE_MINUS_SRC_ALPHA). `outputFresnel` writes F as grey instead.
// Rough (docs/rough-glass.md#the-gather): R̃ and B̃ gathered from mip-mapped images (render/rough-targets.ts binds
// them), written with alpha 1, so the same blend leaves the glass opaque over pass 2.
import { GLASS_BODY } from '../../scene/default-scene';
import { setMatrices, type PassContext } from './pass-context';
import { encodesAtEnd } from '../../frame/linear-light';
import type { Program } from '../gl/program';

const BODY_TINT = new Float32Array(GLASS_BODY);

/** Rough glass's part of the glass pass (render/rough-targets.ts, in its own chunk). */
export interface RoughBinding {
  /** Sets the rough variant's uniforms and binds its textures (units 2 and up) for `program`. */
  bind(program: Program, ctx: PassContext): void;
  /** Unbinds what bind() bound; leaves texture unit 1 active. */
  unbind(): void;
}

/**
 * Draws into the bound framebuffer and viewport; returns the number of draw calls. `rough`
 * (roughness > 0, colour only): the rough variant, `reflection` then being the mip-mapped one.
 */
export function glassPass(ctx: PassContext, reflection: WebGLTexture, outputFresnel = false, rough: RoughBinding | null = null): number {
  const { gl, setup, state } = ctx;
  const program = ctx.programs.glass(state.fresnel, outputFresnel, rough !== null);
  gl.enable(gl.DEPTH_TEST);
  // Rough, the glass is opaque: its depth hides what lies beyond it from the transparent objects
  // drawn after it (renderer.ts).
  gl.depthMask(rough !== null);
  // No polygon offset: on a depth tie (LESS) what is drawn first wins, and objects are drawn
  // before the glass — a face in its plane of an object on the viewer's side stays in front
  // (glass-tie.spec.ts); objects on the plane or beyond are pushed back in the scene pass
  // (draw-objects.ts), so the glass covers them (a picture behind a glass wall).
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
    gl.uniform1f(program.location('uFootprint'), ctx.footprint);
    gl.uniform1f(program.location('uLinearFrame'), encodesAtEnd(state) ? 1 : 0);
    // docs/pbr.md#tone-mapping: a tone-mapped frame keeps R above 1 (65504, a half float's largest).
    gl.uniform1f(program.location('uCeiling'), ctx.hdr ? 65504 : 1);
    gl.uniform1i(program.location('uTexture'), 0);
    gl.uniform1i(program.location('uReflection'), 1);
    ctx.textures.procedural.bind(0);
    if (rough) rough.bind(program, ctx);
    gl.activeTexture(gl.TEXTURE1);
    gl.bindTexture(gl.TEXTURE_2D, reflection);
    ctx.glassMesh.draw();
  } finally {
    rough?.unbind();
    gl.bindTexture(gl.TEXTURE_2D, null);
    gl.activeTexture(gl.TEXTURE0);
    gl.disable(gl.BLEND);
    gl.depthMask(true);
    gl.disable(gl.DEPTH_TEST);
  }
  return 1;
}
