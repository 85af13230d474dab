// The scene's objects drawn with the standard program, from the real eye (pass 2) or the
// mirrored one (pass 1): opaque ones first, then those with opacity < 1 blended over them
// (depth-tested, no depth write), as docs/software-renderer.md#transparency says.
import { focalPixels, orthoPixelsPerUnit } from '../../frame/reflection-lod';
import type { Program } from '../gl/program';
import type { Texture } from '../gl/texture';
import type { ClipMode, ObjectVariant } from '../programs';
import type { SceneObject } from '../../scene/scene';
import { setLights, setMaterial, setMatrices, type PassContext } from './pass-context';
import { drawnTwoSided } from '../../frame/mesh-choice';

/**
 * Compiles (or finds) every variant the objects need before the caller touches GL state:
 * a variant that fails to compile throws, and the element draws again later from clean state.
 */
export function prepareObjectPrograms(ctx: PassContext, clip: ClipMode): void {
  for (const o of ctx.scene.objects) ctx.programs.standard(clip, ctx.state.shading, variantOf(ctx, o));
}

/** The object's variant, filled in place (no allocation per draw). */
const variant: ObjectVariant = { twoSided: false, lights: 1, pointMask: 0, mapping: 'uv', pbr: false, environment: false, normalMap: false, vertexColors: false, alphaMask: false };
function variantOf(ctx: PassContext, o: SceneObject): ObjectVariant {
  variant.twoSided = drawnTwoSided(o);
  variant.lights = ctx.setup.lightCount;
  variant.pointMask = ctx.setup.pointMask;
  variant.mapping = o.material.mapping;
  // Without the PBR chunk (not in yet, or failed: render/parts.ts), the Blinn-Phong stand-in.
  variant.pbr = o.material.pbr !== undefined && ctx.programs.hasPbr;
  // Without its chunk (not in yet, or failed), glTF materials are lit by the scene's lights alone.
  const env = ctx.scene.environment;
  variant.environment = variant.pbr && !!env && ctx.environment !== null && ctx.environment.use(env);
  // A normal map on TEXCOORD_0 and a mesh with tangents (docs/gltf.md#the-normal-map); a clustered copy in the reflection has none.
  const g = o.geometry;
  // Under another mapping no map is read (docs/gltf.md#the-maps).
  variant.normalMap = variant.pbr && g.kind === 'mesh' && !!g.data.tangents && o.material.mapping === 'uv' && o.material.pbr!.normalTexture?.texCoord === 0;
  variant.vertexColors = variant.pbr && g.kind === 'mesh' && !!g.data.colors;
  variant.alphaMask = variant.pbr && o.material.pbr!.alphaMode === 'mask';
  return variant;
}

/** Which objects a call draws: all, or (rough glass's scene pass, renderer.ts) the opaque or the transparent ones alone. */
export type Selection = 'all' | 'opaque' | 'transparent';

/**
 * Draws into the bound framebuffer; depth test on, blending and culling as each object needs.
 * `mirrored`: pass 1 (mirrored matrices and lights, the clip plane, objects wholly beyond
 * the glass culled). `targetHeight`: the height in pixels of the target drawn into, which sets
 * how coarse a dense mesh's reflection may be (reflection-lod.ts). `farSide` (not mirrored): the
 * frame beyond the glass for rough glass (transmission-pass.ts), clipped by this eye-relative
 * plane, objects wholly on the viewer's side culled. `selection`: which objects. Returns the draw calls.
 */
export function drawObjects(
  ctx: PassContext, clip: ClipMode, mirrored: boolean, targetHeight: number, farSide: Float32Array | null = null,
  selection: Selection = 'all',
): number {
  const { gl, setup, scene } = ctx;
  const eye = setup.mirroredEye;
  const focal = focalPixels(targetHeight, ctx.state.fov);
  // The mirrored camera is orthographic too: the same pixels per unit at every depth.
  const orthoPpu = setup.orthographic ? orthoPixelsPerUnit(targetHeight, setup.halfHeight) : 0;
  const objects = scene.objects;
  let draws = 0;
  let current: Program | null = null;
  let texture: Texture | null = null;
  for (let pass = selection === 'transparent' ? 1 : 0; pass < (selection === 'opaque' ? 1 : 2); pass++) {
    const transparent = pass === 1;
    for (let i = 0; i < objects.length; i++) {
      const o = objects[i];
      if ((o.material.opacity < 1) !== transparent) continue;
      // Selection: an object kept out of the reflection (docs/scene-model.md#glass-object).
      if (mirrored && o.reflected === false) continue;
      const m = setup.objects[i];
      // Culling, not selection (docs/rendering.md#what-is-skipped): bounds wholly beyond the glass cannot be reflected.
      if (mirrored && ctx.cull && m.viewerDistance <= -m.radius) continue;
      if (farSide && ctx.cull && m.viewerDistance >= m.radius) continue;
      const twoSided = drawnTwoSided(o);
      const program = ctx.programs.standard(clip, ctx.state.shading, variantOf(ctx, o));
      const switched = program !== current;
      if (switched) {
        current = program;
        program.use();
        setLights(gl, program, setup, mirrored);
        gl.uniform1f(program.location('uFootprint'), ctx.footprint);
        if (variant.environment) ctx.environment!.bind(program, ctx.scene.environment!.intensity);
        if (mirrored) gl.uniform4fv(program.location('uClipPlane'), setup.clipPlane);
        else if (farSide) gl.uniform4fv(program.location('uClipPlane'), farSide);
      }
      const t = ctx.textures.textureFor(o.material.texture);
      if (switched || t !== texture) {
        if (t !== texture) t.bind(0);
        texture = t;
        gl.uniform1f(program.location('uImageTexture'), ctx.textures.isImage(t) ? 1 : 0);
      }
      if (twoSided) gl.disable(gl.CULL_FACE);
      else gl.enable(gl.CULL_FACE);
      // On a depth tie with the glass (a face in its plane) an object on the viewer's side wins,
      // one on the plane or beyond it loses: pushed back further than glass-pass.ts pushes the glass.
      if (!mirrored && !farSide && setup.hasGlass && m.viewerDistance <= 0) {
        gl.enable(gl.POLYGON_OFFSET_FILL);
        gl.polygonOffset(0, 2);
      } else gl.disable(gl.POLYGON_OFFSET_FILL);
      if (transparent) {
        gl.enable(gl.BLEND);
        // Straight alpha over what is drawn; the target's alpha stays 1 for the glass pass.
        gl.blendFuncSeparate(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA, gl.ZERO, gl.ONE);
        // Into rough glass's images (the reflection, the frame beyond the glass) with depth.
        gl.depthMask(ctx.transparentDepth && (mirrored || farSide !== null));
      }
      setMatrices(gl, program, mirrored ? m.mirrored : m.main);
      setMaterial(gl, program, o);
      if (variant.pbr) ctx.pbrMaps?.bind(program, o.material.pbr!);
      if (mirrored) {
        const d = Math.hypot(m.center[0] - eye[0], m.center[1] - eye[1], m.center[2] - eye[2]);
        const mesh = ctx.objectMeshes.mirrored(i, o.geometry, m, ctx.state, setup.orthographic ? orthoPpu : focal / d);
        mesh.draw();
        ctx.triangles.reflection += mesh.count / 3;
      } else {
        const mesh = ctx.objectMeshes.get(i, o.geometry, m, ctx.state);
        mesh.draw();
        ctx.triangles.scene += mesh.count / 3;
      }
      draws++;
    }
  }
  gl.disable(gl.BLEND);
  gl.depthMask(true);
  gl.disable(gl.CULL_FACE);
  gl.disable(gl.POLYGON_OFFSET_FILL);
  return draws;
}
