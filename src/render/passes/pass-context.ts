// What every pass reads: the GL context, compiled variants, meshes, texture and this frame's matrices.
import type { Mesh } from '../gl/mesh';
import type { Program } from '../gl/program';
import type { Texture } from '../gl/texture';
import type { DrawMatrices, FrameSetup } from '../frame-setup';
import type { ProgramCache } from '../programs';
import type { FrameState } from '../types';
import { BACKGROUND, LIGHT, MATERIAL } from '../../scene/default-scene';

export interface SceneMeshes {
  cube: Mesh;
  sphere: Mesh;
  glass: Mesh;
}

/** A rectangle of the bound framebuffer, in pixels, origin bottom-left. */
export interface Viewport {
  x: number;
  y: number;
  width: number;
  height: number;
}

export interface PassContext {
  gl: WebGL2RenderingContext;
  programs: ProgramCache;
  meshes: SceneMeshes;
  texture: Texture;
  setup: FrameSetup;
  state: FrameState;
  /** The WEBGL_clip_cull_distance extension, or null (then the shader discards). */
  clipExtension: { CLIP_DISTANCE0_WEBGL: number } | null;
  /** Cull objects beyond the glass from the reflection (off only to measure what it saves). */
  cull: boolean;
  /** Pass 1 draws only inside this rectangle of its target, or everywhere when null. */
  scissor: Viewport | null;
}

/** Binds `framebuffer`, sets the viewport and clears it (scissored, so tiles clear only themselves). */
export function beginTarget(
  gl: WebGL2RenderingContext, framebuffer: WebGLFramebuffer | null, vp: Viewport, clear: readonly number[] = BACKGROUND,
  scissor: Viewport = vp,
): void {
  gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
  gl.viewport(vp.x, vp.y, vp.width, vp.height);
  gl.enable(gl.SCISSOR_TEST);
  gl.scissor(scissor.x, scissor.y, scissor.width, scissor.height);
  gl.clearColor(clear[0], clear[1], clear[2], 1);
  gl.clearDepth(1);
  gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
  gl.disable(gl.SCISSOR_TEST);
}

/** Light and material uniforms shared by every opaque draw. */
export function setLighting(gl: WebGL2RenderingContext, p: Program): void {
  gl.uniform1i(p.location('uTexture'), 0);
  gl.uniform3fv(p.location('uLightDirection'), LIGHT.direction);
  gl.uniform3f(p.location('uLightIntensity'), LIGHT.ambient, LIGHT.diffuse, LIGHT.specular);
  gl.uniform2f(p.location('uSpecular'), MATERIAL.ks, MATERIAL.shininess);
}

export function setMatrices(gl: WebGL2RenderingContext, p: Program, m: DrawMatrices): void {
  gl.uniformMatrix4fv(p.location('uModelViewProjection'), false, m.modelViewProjection);
  gl.uniformMatrix4fv(p.location('uModelRelative'), false, m.modelRelative);
  gl.uniformMatrix3fv(p.location('uNormalMatrix'), false, m.normal);
}
