// The debug views of `debug-view` (docs/element.md#debug-views): the reflection pass alone, F as grey, and the four
// passes in quadrants. A chunk of its own (docs/package.md#chunks), fetched by Renderer.load the first time a
// frame asks for one of them; the final image and the `scene` view (which capture draws) are
// the core's. The software renderer draws its own.
import blitFrag from '../../shaders/blit.frag?raw';
import type { ProgramCache } from './programs';
import { beginTarget, type PassContext } from './passes/pass-context';
import { scenePass } from './passes/scene-pass';
import { glassPass } from './passes/glass-pass';
import type { RenderView, Viewport } from '../frame/types';

/** What the debug views draw with: the renderer's context, programs and passes (the Renderer itself). */
export interface DebugViewFrame {
  readonly gl: WebGL2RenderingContext;
  readonly ctx: PassContext;
  readonly programs: ProgramCache;
  /** The full-screen triangle's (empty) vertex array. */
  readonly blitVao: WebGLVertexArrayObject;
  /** This frame's sharp reflection texture. */
  reflectionColor(): WebGLTexture;
  /** Pass 1, whole (not scissored to the glass), into the reflection texture; its draw calls. */
  runReflection(): number;
  /** Rough glass's images when this frame's final image has rough glass (their draw calls), else null. */
  roughImages(): number | null;
  /** Passes 2 and 3 as the final image draws them (`rough`: after roughImages). */
  sceneAndGlass(rough: boolean): number;
}

const BLACK = [0, 0, 0] as const;
/** The quadrant being drawn (filled in place: nothing is allocated per frame). */
const tile: Viewport = { x: 0, y: 0, width: 0, height: 0 };

function setTile(x: number, y: number, width: number, height: number): Viewport {
  tile.x = x;
  tile.y = y;
  tile.width = width;
  tile.height = height;
  return tile;
}

/** `view` (reflection, fresnel or passes) into `framebuffer` over `full`; returns the draw calls. */
export function drawDebugView(f: DebugViewFrame, view: Exclude<RenderView, 'final' | 'scene'>, framebuffer: WebGLFramebuffer | null, full: Viewport): number {
  if (view === 'fresnel') return fresnel(f, framebuffer, full);
  if (view === 'reflection') return f.runReflection() + blit(f, framebuffer, full);
  return tiles(f, framebuffer, full.width, full.height);
}

/** F as grey: the scene for depth, then the glass writing F (docs/colour.md#debug-views: a number, unencoded). */
function fresnel(f: DebugViewFrame, framebuffer: WebGLFramebuffer | null, vp: Viewport): number {
  beginTarget(f.gl, framebuffer, vp, BLACK);
  return scenePass(f.ctx, true) + glassPass(f.ctx, f.reflectionColor(), true);
}

/**
 * Reflection | scene over fresnel | final, in the four quadrants. On an odd size the right
 * column and top row of tiles take the extra pixel, so no line between them is left unwritten.
 */
function tiles(f: DebugViewFrame, framebuffer: WebGLFramebuffer | null, width: number, height: number): number {
  const { gl, ctx } = f;
  const left = Math.floor(width / 2), right = width - left;
  const bottom = Math.floor(height / 2), top = height - bottom;
  const roughDraws = f.roughImages();
  let n = (roughDraws ?? 0) + f.runReflection();
  n += blit(f, framebuffer, setTile(0, bottom, left, top));
  beginTarget(gl, framebuffer, setTile(left, bottom, right, top), ctx.background);
  n += scenePass(ctx);
  n += fresnel(f, framebuffer, setTile(0, 0, left, bottom));
  beginTarget(gl, framebuffer, setTile(left, 0, right, bottom), ctx.background);
  return n + f.sceneAndGlass(roughDraws !== null);
}

/** The reflection texture, as stored, over `vp`. */
function blit(f: DebugViewFrame, framebuffer: WebGLFramebuffer | null, vp: Viewport): number {
  const gl = f.gl;
  beginTarget(gl, framebuffer, vp, f.ctx.background);
  const p = f.programs.fullScreen('blit', blitFrag);
  p.use();
  gl.uniform1i(p.location('uSource'), 0);
  gl.activeTexture(gl.TEXTURE0);
  gl.bindTexture(gl.TEXTURE_2D, f.reflectionColor());
  gl.bindVertexArray(f.blitVao);
  gl.drawArrays(gl.TRIANGLES, 0, 3);
  gl.bindVertexArray(null);
  gl.bindTexture(gl.TEXTURE_2D, null);
  return 1;
}
