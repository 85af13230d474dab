// The renderer's lazy parts (frame/lazy-parts.ts): what only some frames need, each declared once.
// A frame that needs one waits for it; the renderer draws without it if it cannot load.
import type { LazyPartSpec } from '../frame/lazy-parts';
import { isRough } from '../frame/roughness';
import { toneMapped } from '../frame/linear-light';
import type { FrameState } from '../frame/types';
import { hasPbrMaterial, type Scene } from '../scene/scene';
import type { PassContext } from './passes/pass-context';
import type { RoughGlass } from './rough-glass';
import type { ResourceCounter } from './gl/resource-counter';

/** What the renderer's parts read and are handed to: the frame's context, and whether checks are on. */
export interface RenderPartsHost {
  readonly ctx: PassContext;
  readonly checks: boolean;
  readonly rough: RoughGlass;
  readonly counter: ResourceCounter;
}

type Part<T> = LazyPartSpec<RenderPartsHost, T>;

/** gl.getError() and finite uniforms after each frame (RendererOptions.checks). */
export const FRAME_CHECKS: Part<typeof import('./frame-checks')> = {
  name: 'the frame checks', chunk: 'diagnostics', load: () => import('./frame-checks'),
  needed: (h) => h.checks, holds: true, instead: 'frames go unchecked',
};

/** Rough glass's passes, targets and shaders (docs/rough-glass.md). */
export const ROUGH_GLASS: Part<typeof import('./rough-glass-gl')> = {
  name: 'rough glass', chunk: 'rough-glass-gl', load: () => import('./rough-glass-gl'),
  needed: (h) => isRough(h.ctx.state), holds: true, instead: 'drawing the glass polished',
  arrived: (h, chunk) => {
    h.ctx.programs.setRoughSources(chunk.ROUGH_SOURCES);
    h.rough.chunk = chunk;
  },
};

/** A course camera's projection and depth range, given to FrameSetup. */
export const COURSE_PROJECTION: Part<typeof import('../frame/course-projection')> = {
  name: 'camera-src', chunk: 'camera-extras', load: () => import('../frame/course-projection'),
  needed: (h) => !!h.ctx.state.courseCamera, holds: true, instead: 'drawing from the camera attributes',
  arrived: (h, m) => {
    h.ctx.setup.course ??= new m.CourseProjection();
  },
};

/** The orthographic projection, given to FrameSetup. */
export const ORTHOGRAPHIC_VIEW: Part<typeof import('../frame/orthographic-view')> = {
  name: 'projection="orthographic"', chunk: 'camera-extras', load: () => import('../frame/orthographic-view'),
  needed: (h) => h.ctx.state.projection === 'orthographic', holds: true, instead: 'drawing in perspective',
  arrived: (h, m) => {
    h.ctx.setup.ortho ??= m.orthographicView;
  },
};

/**
 * Whether a frame needs the mesh extras: flat shading, a Gaussian, or (tessellation auto) a mesh
 * whose reflection may be clustered.
 */
export function needsExtras(state: FrameState, scene: Scene): boolean {
  if (state.shading === 'flat') return true;
  for (const o of scene.objects) {
    const k = o.geometry.kind;
    if (k === 'gaussian' || (k === 'mesh' && state.tessellation === 'auto')) return true;
  }
  return false;
}

/** Flat shading, the Gaussian and the reflection's clustering, given to the object meshes. */
export const MESH_EXTRAS: Part<typeof import('./mesh-extras')> = {
  name: "flat shading, the Gaussian and the reflection's clustering", chunk: 'render-extras', load: () => import('./mesh-extras'),
  needed: (h) => needsExtras(h.ctx.state, h.ctx.scene), holds: true,
  instead: 'drawing smooth meshes, no Gaussian, full meshes in the reflection',
  arrived: (h, m) => h.ctx.objectMeshes.setExtras(m),
};

/** glTF materials' and tone mapping's shader parts, given to the program cache. */
export const PBR_MATERIALS: Part<typeof import('./pbr-gl')> = {
  name: 'glTF materials and tone mapping', chunk: 'pbr-gl', load: () => import('./pbr-gl'),
  needed: (h) => hasPbrMaterial(h.ctx.scene) || toneMapped(h.ctx.state), holds: true,
  instead: 'drawing glTF materials with their Blinn-Phong stand-in, without tone mapping',
  arrived: (h, m) => {
    h.ctx.programs.setPbrSources(m.PBR_SOURCE, m.TONE_MAP_SOURCE);
    h.ctx.pbrMaps ??= new m.PbrMapsGl(h.ctx.gl, h.counter);
  },
};

/** An environment's light on glTF materials (docs/pbr.md#the-environment): its shader part, given to the program cache, and its textures. */
export const ENVIRONMENT_LIGHT: Part<typeof import('./environment-gl')> = {
  // The load takes the making of the studio's maps too (the one environment there is), in slices: the frame waits, the page does not.
  name: 'the environment', chunk: 'environment-gl', load: () => import('./environment-gl').then((m) => m.studioReady().then(() => m)),
  needed: (h) => !!h.ctx.scene.environment && hasPbrMaterial(h.ctx.scene), holds: true,
  instead: 'lighting glTF materials by the scene\'s lights alone',
  arrived: (h, m) => {
    h.ctx.programs.setEnvironmentSource(m.ENVIRONMENT_SOURCE);
    h.ctx.environment ??= new m.EnvironmentGl(h.ctx.gl, h.counter);
  },
};

/** debug-view reflection, fresnel and passes. */
export const DEBUG_VIEWS: Part<typeof import('./debug-views')> = {
  name: 'debug-view', chunk: 'diagnostics', load: () => import('./debug-views'),
  needed: (h) => h.ctx.state.view !== 'final' && h.ctx.state.view !== 'scene', holds: true, instead: 'the final image is drawn',
};

export const RENDER_PARTS: readonly Part<unknown>[] = [
  FRAME_CHECKS, ROUGH_GLASS, COURSE_PROJECTION, ORTHOGRAPHIC_VIEW, MESH_EXTRAS, PBR_MATERIALS, ENVIRONMENT_LIGHT, DEBUG_VIEWS,
];
