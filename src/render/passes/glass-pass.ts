// Pass 3: the two-sided glass, depth-tested without depth writes, blended over pass 2 with
// premultiplied alpha (ONE, ONE_MINUS_SRC_ALPHA). `outputFresnel` writes F as grey instead.
// Rough (SPEC §14): R̃ and B̃ gathered from mip-mapped images (rough-targets.ts), written with
// alpha 1, so the same blend leaves the glass opaque over pass 2.
import { GLASS_BODY } from '../../scene/default-scene';
import { setMatrices, type PassContext } from './pass-context';
import { encodesAtEnd } from '../../frame/linear-light';
import type { Program } from '../gl/program';
import type { RoughGatherSettings } from '../../frame/rough-glass';

const BODY_TINT = new Float32Array(GLASS_BODY);

/** What the rough variant reads beyond the sharp glass's inputs (filled in place each frame). */
export interface RoughGlassInputs {
  /** GGX α = roughness². */
  alpha: number;
  settings: RoughGatherSettings;
  /** The mip-mapped reflection (the distance code in alpha) and its size in texels. */
  reflectionWidth: number;
  reflectionHeight: number;
  reflectionTextureWidth: number;
  reflectionTextureHeight: number;
  /** The frame beyond the glass, mip-mapped likewise; null when the glass lets nothing through. */
  transmission: WebGLTexture | null;
  transmissionWidth: number;
  transmissionHeight: number;
  transmissionTextureWidth: number;
  transmissionTextureHeight: number;
  /** Each image's codes (coverage × distance code in alpha), mip-mapped as the image. */
  reflectionCodes: WebGLTexture | null;
  transmissionCodes: WebGLTexture | null;
  /** The inverse of the frame's eye-relative view-projection (float32). */
  inverseViewProjection: Float32Array;
  /** FrameState.fixedBlurLevel (≥ 0), or −1: the gather. */
  fixedLevel: number;
}

/** Uploads (float32) of this frame's camera for the rough variant: filled in place, never allocated per frame. */
const viewProjection = new Float32Array(16);
const normal = new Float32Array(3);
const forward = new Float32Array(3);
const background = new Float32Array(3);
/** The texture units the rough variant binds beyond the sharp glass's (unbound after the draw). */
const ROUGH_UNITS = [0x84c2, 0x84c3, 0x84c4]; // TEXTURE2..4

function setRough(gl: WebGL2RenderingContext, p: Program, ctx: PassContext, rough: RoughGlassInputs): void {
  const { setup, state } = ctx;
  viewProjection.set(setup.viewProjection);
  for (let k = 0; k < 3; k++) background[k] = ctx.background[k];
  const plane = setup.glass.plane;
  for (let k = 0; k < 3; k++) {
    normal[k] = setup.side * plane[k];
    forward[k] = setup.forward[k];
  }
  gl.uniformMatrix4fv(p.location('uViewProjection'), false, viewProjection);
  gl.uniform3fv(p.location('uGlassNormal'), normal);
  gl.uniform3fv(p.location('uForward'), forward);
  gl.uniform1f(p.location('uOrthographic'), setup.orthographic ? 1 : 0);
  gl.uniform1f(p.location('uAlpha'), rough.alpha);
  gl.uniform1i(p.location('uAngles'), rough.settings.angles);
  gl.uniform1f(p.location('uLodBias'), rough.settings.lodBias);
  gl.uniform4f(p.location('uReflectionSize'), rough.reflectionWidth, rough.reflectionHeight, rough.reflectionTextureWidth, rough.reflectionTextureHeight);
  gl.uniform4f(p.location('uTransmissionSize'), rough.transmissionWidth, rough.transmissionHeight, rough.transmissionTextureWidth, rough.transmissionTextureHeight);
  gl.uniform1f(p.location('uTransmits'), rough.transmission ? 1 : 0);
  gl.uniformMatrix4fv(p.location('uInverseViewProjection'), false, rough.inverseViewProjection);
  gl.uniform3fv(p.location('uBackground'), background);
  // In the reflection target's levels: its scale to the frame's pixels added.
  const level = rough.fixedLevel < 0 ? -1 : rough.fixedLevel + Math.log2(rough.reflectionWidth / state.width);
  gl.uniform1f(p.location('uFixedLevel'), level);
  gl.uniform1i(p.location('uTransmission'), 2);
  gl.uniform1i(p.location('uReflectionCodes'), 3);
  gl.uniform1i(p.location('uTransmissionCodes'), 4);
  gl.activeTexture(gl.TEXTURE2);
  gl.bindTexture(gl.TEXTURE_2D, rough.transmission);
  gl.activeTexture(gl.TEXTURE3);
  gl.bindTexture(gl.TEXTURE_2D, rough.reflectionCodes);
  gl.activeTexture(gl.TEXTURE4);
  gl.bindTexture(gl.TEXTURE_2D, rough.transmissionCodes);
}

/**
 * Draws into the bound framebuffer and viewport; returns the number of draw calls. `rough`
 * (roughness > 0, colour only): the rough variant, `reflection` then being the mip-mapped one.
 */
export function glassPass(ctx: PassContext, reflection: WebGLTexture, outputFresnel = false, rough: RoughGlassInputs | null = null): number {
  const { gl, setup, state } = ctx;
  const program = ctx.programs.glass(state.fresnel, outputFresnel, rough !== null);
  gl.enable(gl.DEPTH_TEST);
  // Rough, the glass is opaque: its depth hides what lies beyond it from the transparent objects
  // drawn after it (renderer.ts).
  gl.depthMask(rough !== null);
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
    if (rough) setRough(gl, program, ctx, rough);
    gl.activeTexture(gl.TEXTURE1);
    gl.bindTexture(gl.TEXTURE_2D, reflection);
    ctx.glassMesh.draw();
  } finally {
    if (rough) {
      for (const unit of ROUGH_UNITS) {
        gl.activeTexture(unit);
        gl.bindTexture(gl.TEXTURE_2D, null);
      }
      gl.activeTexture(gl.TEXTURE1);
    }
    gl.bindTexture(gl.TEXTURE_2D, null);
    gl.activeTexture(gl.TEXTURE0);
    gl.disable(gl.BLEND);
    gl.disable(gl.POLYGON_OFFSET_FILL);
    gl.depthMask(true);
    gl.disable(gl.DEPTH_TEST);
  }
  return 1;
}
