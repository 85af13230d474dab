// Plain data both renderers take and give back (the frame's state, its reports): no DOM, no GL handles.
import type { FresnelModel } from '../math/fresnel';
import type { ColorSpace } from '../math/srgb';
import type { ToneMapping } from '../math/tone-map';
import type { Projection } from '../math/camera';
import type { CourseCamera } from '../math/course-camera';
import type { SceneTurn } from '../scene/turn';
import type { RoughnessQuality } from './rough-glass';

export type { Projection, ColorSpace };

export type PassName = 'reflection' | 'scene' | 'glass';

export type RenderView = 'final' | 'reflection' | 'scene' | 'fresnel' | 'passes';

/** Everything a frame depends on. Same state in, same pixels out. */
export interface FrameState {
  width: number;
  height: number;
  time: number;
  spin: number;
  cubeDistance: number;
  transparency: number;
  ior: number;
  fresnel: FresnelModel;
  fov: number;
  cameraPosition: readonly [number, number, number];
  yaw: number;
  pitch: number;
  view: RenderView;
  /** Reflection framebuffer size ÷ drawing-buffer size (0.125..2). */
  reflectionScale: number;
  /** MSAA samples (0 = none); clamped to the context's MAX_SAMPLES. */
  samples: number;
  shading: Shading;
  /** Sphere segments, or 'auto' from its size on screen. */
  tessellation: number | 'auto';
  /** Storage of the reflection: 8-bit, or half float (where the context can render to it). */
  reflectionFormat: ReflectionFormat;
  /**
   * docs/colour.md#srgb: `srgb` decodes colour data (images, the procedural texture, the background), mixes
   * light linearly and encodes the image once; `none` uses every value as stored.
   */
  colorSpace: ColorSpace;
  /**
   * docs/pbr.md#tone-mapping: with colorSpace srgb, the curve that brings light to the screen once, at the frame's end,
   * after `exposure`; light above 1 is kept until then. Absent or `none` with exposure 1: every
   * target clamps to [0, 1], today's frames exactly (frame/linear-light.ts toneMapped).
   */
  toneMapping?: ToneMapping;
  /** A factor on the frame's light before tone mapping; absent: 1. */
  exposure?: number;
  /**
   * docs/rough-glass.md#ggx-microfacets: the glass's roughness, 0..1 (GGX α = roughness²); absent or 0: polished, today's
   * glass exactly.
   */
  roughness?: number;
  /** How many neighbours rough glass gathers (frame/rough-glass.ts); absent: 'medium'. */
  roughnessQuality?: RoughnessQuality;
  /**
   * The bench's comparison (the peers' method), not a user setting: with roughness > 0, the
   * reflection read at this one mip level over the whole glass, what is behind it left sharp.
   */
  fixedBlurLevel?: number;
  /** Absent: perspective. Orthographic keeps the reflection (docs/interaction.md#orthographic-projection). */
  projection?: Projection;
  /** The camera target, if any: only the orthographic size reads it (depth of this point). */
  target?: readonly [number, number, number] | null;
  /**
   * A course camera (docs/course-files.md#camera-cfg, `camera-src`): when set it is the view, in place of
   * cameraPosition/yaw/pitch/fov/projection; near and far come from the scene's geometry.
   * The element then sets cameraPosition to C and fov to 2·atan(|hy/d|), which only the
   * level-of-detail choices (sphere segments, reflection meshes) read.
   */
  courseCamera?: CourseCamera | null;
  /**
   * The trackball's turn of the objects and the first light (docs/interaction.md#trackball), applied as the frame is
   * set up. It travels here, not in the scene value, so a turn rebuilds nothing. Absent or
   * identity: the scene as it is.
   */
  turn?: SceneTurn | null;
  /**
   * docs/refinement.md: 0 or absent, an ordinary frame; k ≥ 1, the k-th frame of a still view, its pixel grid moved by
   * frame/refinement.ts's offset and averaged with the k − 1 frames before it (in linear light; 1 starts the average).
   */
  refinement?: number;
  /** How many frames the still view's refinement draws (the `refine` attribute): the grid its offsets fill. Absent: 1. */
  refinementFrames?: number;
}

export type ReflectionFormat = 'rgba8' | 'rgba16f';

export type Shading = 'phong' | 'gouraud' | 'flat';

export interface PassReport {
  readonly ran: boolean;
  /** Why a pass did not run. */
  readonly reason?: string;
}

export interface FrameReport {
  /** Frames rendered so far by this element, this one included. */
  frame: number;
  /** Scene clock of the frame, seconds. */
  time: number;
  width: number;
  height: number;
  passes: Readonly<Record<PassName, PassReport>>;
  drawCalls: number;
  /**
   * docs/refinement.md#events: the frame's place in a still view's refinement, 1 (the preview) to `refine` (the last, with
   * `refined`); 0 a frame that refines nothing (moving, refinement off). Set by the element.
   */
  refinement?: number;
}

export interface ResourceCounts {
  buffers: number;
  textures: number;
  framebuffers: number;
  renderbuffers: number;
  vertexArrays: number;
  programs: number;
  shaders: number;
}

export interface RenderStats {
  frames: number;
  /** Shader programs compiled (only the variants in use). */
  programs: number;
  /** Segments of the sphere mesh in use. */
  sphereSegments: number;
  passesRun: Record<PassName, number>;
  passesSkipped: Record<PassName, number>;
  /** Draw calls of the last frame. */
  drawCalls: number;
  /**
   * Triangles the last frame submitted from each eye. With tessellation 'auto' the reflection
   * of a dense mesh draws a coarser copy (cells of a few reflection pixels), so `reflection`
   * can be well below `scene`.
   */
  triangles: { scene: number; reflection: number };
  /** Which renderer draws (set by the element): WebGL2, or the CPU in a worker or on the main thread. */
  renderer?: 'webgl' | 'software' | null;
  thread?: 'worker' | 'main';
  /**
   * Times the element built its scene value (set by the element): once per change of content
   * (an attribute that shapes the scene, a child, a model), never for a camera or trackball move.
   */
  sceneBuilds?: number;
  /** Refinement frames drawn (set by the element): among `frames`, those of still views (docs/refinement.md#events). */
  refinementFrames?: number;
  /** Live GL objects owned by this element; all zero after it is removed. */
  resources: ResourceCounts & { total: number };
}

/** A rectangle of a framebuffer, in pixels, origin bottom-left. */
export interface Viewport {
  x: number;
  y: number;
  width: number;
  height: number;
}
