// What every pass reads: the GL context, compiled variants, meshes, texture, the scene and
// this frame's matrices.
import type { Mesh } from '../gl/mesh';
import type { Program } from '../gl/program';
import type { TextureCache } from '../texture-cache';
import type { DrawMatrices, FrameSetup, LightVectors } from '../../frame/frame-setup';
import type { ObjectMeshes } from '../object-meshes';
import type { ProgramCache } from '../programs';
import type { EnvironmentGl } from '../environment-gl';
import type { PbrMapsGl } from '../pbr-maps-gl';
import type { FrameState, Viewport } from '../../frame/types';
import type { Material, Scene, SceneObject } from '../../scene/scene';

export type { Viewport };

export interface PassContext {
  gl: WebGL2RenderingContext;
  programs: ProgramCache;
  /** The mesh of each scene object, by index. */
  objectMeshes: ObjectMeshes;
  /** The glass rectangle, in world coordinates. */
  glassMesh: Mesh;
  /** The procedural texture (the glass's, and objects' without an image) and images, in the frame's colour space. */
  textures: TextureCache;
  /** The clear colour in the frame's colour space (decoded for `srgb`). */
  background: readonly number[];
  setup: FrameSetup;
  state: FrameState;
  scene: Scene;
  /** The WEBGL_clip_cull_distance extension, or null (then the shader discards). */
  clipExtension: { CLIP_DISTANCE0_WEBGL: number } | null;
  /** Cull objects beyond the glass from the reflection (off only to measure what it saves). */
  cull: boolean;
  /** Pass 1 draws only inside this rectangle of its target, or everywhere when null. */
  scissor: Viewport | null;
  /**
   * Transparent objects write depth too in the reflection and the frame beyond the glass: rough
   * glass's distance codes come from those passes' depth, and a transparent surface with only the background behind it is a surface to the
   * gather (docs/rough-glass.md#the-gather). Off otherwise: depth from transparent objects decides nothing.
   */
  transparentDepth: boolean;
  /**
   * The frame keeps light above 1 in half-float targets and tone maps it at the end (docs/pbr.md#tone-mapping): asked for
   * (toneMapped), and the context can render to half float, and the tone-mapping chunk is in.
   */
  hdr: boolean;
  /** The share of a pixel every material texture is read over: 1 / the frame's refinement scale (docs/refinement.md#footprints). */
  footprint: number;
  /** An environment's textures (docs/pbr.md#the-environment), once its chunk is in (ENVIRONMENT_LIGHT, render/parts.ts); the renderer disposes them. */
  environment: EnvironmentGl | null;
  /** glTF materials' maps (docs/gltf.md#drawing), once the PBR chunk is in (PBR_MATERIALS); the renderer disposes them. */
  pbrMaps: PbrMapsGl | null;
  /** Triangles submitted since the frame began, by the eye they were drawn from. */
  triangles: { scene: number; reflection: number };
}

/** Binds `framebuffer`, sets the viewport and clears it (scissored, so tiles clear only themselves). */
export function beginTarget(
  gl: WebGL2RenderingContext, framebuffer: WebGLFramebuffer | null, vp: Viewport, clear: readonly number[],
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

/** The lights (vectors relative to the eye drawn from) and view vector shared by every object of a pass. */
export function setLights(gl: WebGL2RenderingContext, p: Program, setup: FrameSetup, mirrored: boolean): void {
  const vectors: LightVectors = mirrored ? setup.lightsMirrored : setup.lightsMain;
  gl.uniform1i(p.location('uTexture'), 0);
  gl.uniform4fv(p.location('uLightVector'), vectors.vectors);
  gl.uniform4fv(p.location('uViewVector'), mirrored ? setup.viewVectorMirrored : setup.viewVectorMain);
  gl.uniform3fv(p.location('uLightAmbient'), setup.lightAmbient);
  gl.uniform3fv(p.location('uLightDiffuse'), setup.lightDiffuse);
  gl.uniform3fv(p.location('uLightSpecular'), setup.lightSpecular);
}

export function setMaterial(gl: WebGL2RenderingContext, p: Program, o: SceneObject): void {
  const m: Material = o.material;
  const { ambient: a, diffuse: d, specular: s } = m;
  const c = o.bounds.center;
  gl.uniform4f(p.location('uBounds'), c[0], c[1], c[2], o.bounds.radius);
  gl.uniform3f(p.location('uKa'), a[0], a[1], a[2]);
  gl.uniform3f(p.location('uKd'), d[0], d[1], d[2]);
  gl.uniform3f(p.location('uKs'), s[0], s[1], s[2]);
  gl.uniform1f(p.location('uShininess'), m.shininess);
  gl.uniform1f(p.location('uOpacity'), m.opacity);
  const e = m.emissive ?? NO_EMISSION;
  gl.uniform3f(p.location('uEmissive'), e[0], e[1], e[2]);
  const pbr = m.pbr;
  if (pbr) {
    const b = pbr.baseColor;
    gl.uniform3f(p.location('uBaseColor'), b[0], b[1], b[2]);
    gl.uniform3f(p.location('uPbr'), pbr.metallic, pbr.roughness, pbr.unlit ? 1 : 0);
  }
}

const NO_EMISSION = [0, 0, 0] as const;

export function setMatrices(gl: WebGL2RenderingContext, p: Program, m: DrawMatrices): void {
  gl.uniformMatrix4fv(p.location('uModelViewProjection'), false, m.modelViewProjection);
  gl.uniformMatrix4fv(p.location('uModelRelative'), false, m.modelRelative);
  gl.uniformMatrix3fv(p.location('uNormalMatrix'), false, m.normal);
}
