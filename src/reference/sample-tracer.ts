// One sample of one view: primary ray, what lies behind the glass (B), the mirror ray (R), composited.
import { viewerSide } from '../math/camera';
import { reflectPoint, signedDistance, type Plane } from '../math/mirror';
import { MAX_LIGHTS, type Scene } from '../scene/scene';
import { setClipRange, visible } from './clip';
import { courseSceneRange } from '../scene/course-depth';
import { CAMERA } from '../scene/default-scene';
import type { DecodedImage } from '../scene/decoded-image';
import { ViewCamera } from './view-camera';
import { Ray } from './ray';
import { RayScene } from './ray-scene';
import { colourCeiling, type ViewState } from './reference-state';
import { clamp01, clampTo, composeGlass, glassFresnel, prepareLight, shadeObject, type EnvironmentShading, type PreparedLight } from './shade';
import { keptHit, shadeGltf } from './gltf-surface';
import type { SurfaceCodes } from './surface-codes';
import { SurfaceHit, SURFACE_NONE } from './surface-hit';
import { Layer } from './layer';
import { SurfaceTexture, type TextureFilter } from './surface-texture';
import { srgbToLinear } from '../math/srgb';
import { ggxAlpha } from '../math/ggx';
import { RoughGlass, type Microfacets } from './rough-glass';

export { MAX_FOOTPRINT_TEXELS, type TextureFilter } from './surface-texture';
/** Surfaces per key digit in the default scene (0 none, 1..6 cube faces, 7 sphere, 8 glass). */
export const KEY_BASE = 9;

/** A depth tie between the glass and a face in its plane: t equal to this relative rounding. */
const TIE = 1e-9;

/** Surfaces one ray passes through at most: the last one is taken as opaque. */
export const MAX_LAYERS = 16;

/**
 * Traces samples of one frame. A sample returns its colour and a key naming what it saw:
 * primary + base·behind + base²·reflected (the surface codes of SurfaceCodes: behind is the
 * first surface past a glass or transparent primary, reflected the first surface the glass
 * mirrors), + base³ when a texture footprint was shortened (grazing incidence, the sphere's
 * poles, where the linearised footprint is not to be trusted), so pixels whose samples
 * disagree, or whose neighbours do, can be told apart as edges (regions.ts).
 *
 * Order of transparency: an object of opacity α < 1 gives colour·α + behind·(1 − α), behind =
 * the colour along the same ray past it (the next surface: another object, the glass, or the
 * background), each step clamped as an 8-bit target holds it — the sorted back-to-front blend
 * of the formula of docs/software-renderer.md#transparency, whatever the draw order. The glass takes part in that order too: a
 * transparent object in front of the glass is blended over the glass's result.
 */
export class SampleTracer {
  readonly scene: RayScene;
  private readonly camera: ViewCamera;
  private readonly lights: readonly PreparedLight[];
  private readonly texture: SurfaceTexture;
  private readonly plane: Plane | null;
  private readonly codes: SurfaceCodes;
  private readonly primary = new Ray();
  private readonly mirrored = new Ray();
  // Direct and mirrored paths keep their own hits: B is still in use when R is traced.
  private readonly direct: Layer[] = [];
  private readonly mirror: Layer[] = [];
  private readonly mirroredEye = new Float64Array(3);
  /**
   * +1 when the camera sees the side the glass normal points to, else −1: the eye's side in
   * perspective (on the plane counts as +), the side the view comes from in orthographic.
   */
  private readonly side: number;
  /** The first glass reflection's code in the current sample. */
  private reflected = SURFACE_NONE;
  /** The scene's background in the frame's colour space: a CSS colour, decoded to linear light with srgb. */
  private readonly backgroundColour = new Float64Array(3);
  /** docs/rough-glass.md#ggx-microfacets: the glass's GGX α (0: polished, the smooth path exactly). */
  private readonly alpha: number;
  /**
   * The microfacet normals of the current sample: (xi1[i], xi2[i]) for i in [first, first +
   * count), set by the renderer before each sample (renderScene's MicrofacetSamples).
   */
  microfacets: Microfacets | null = null;
  environment: EnvironmentShading | null = null; // the scene's, its stream restarted before each sample (renderScene)
  private readonly rough = new RoughGlass();
  /** What a colour is held to: 1 as an 8-bit target, Infinity in a tone-mapped frame (colourCeiling). */
  private readonly top: number;

  constructor(
    scene: Scene, private readonly view: ViewState, filter: TextureFilter,
    images?: ReadonlyMap<string, DecodedImage>,
  ) {
    // A course camera's near and far come from the scene (docs/course-files.md#near-and-far), as in the frame setup.
    const range = view.courseCamera ? courseSceneRange(view.courseCamera, scene, view.time) : null;
    setClipRange(range?.near ?? CAMERA.near, range?.far ?? CAMERA.far);
    this.camera = new ViewCamera(view, scene.glass?.center ?? null, range);
    this.scene = new RayScene(scene, view.time);
    this.codes = this.scene.codes;
    this.lights = scene.lights.slice(0, MAX_LIGHTS).map(prepareLight); // as the renderers: docs/scene-model.md#lights
    this.texture = new SurfaceTexture(filter, view.colorSpace, images);
    const bg = scene.background;
    for (let k = 0; k < 3; k++) this.backgroundColour[k] = view.colorSpace === 'srgb' ? srgbToLinear(bg[k]) : bg[k];
    this.plane = this.scene.glass?.plane ?? null;
    this.alpha = ggxAlpha(view.roughness ?? 0);
    this.top = colourCeiling(view);
    this.side = this.plane === null ? 1
      : viewerSide(this.plane, this.camera.eye, this.camera.forward, view.projection ?? 'perspective');
    if (this.plane !== null) reflectPoint(this.mirroredEye, this.camera.eye, this.plane);
    for (let i = 0; i <= MAX_LAYERS; i++) { this.direct.push(new Layer()); this.mirror.push(new Layer()); }
  }

  /**
   * Colour (0..1 per channel, clamped as the 8-bit target holds it; linear light with srgb,
   * docs/colour.md#srgb, encoded once per pixel by the renderer) of the sample at NDC
   * (x, y) whose footprint is fx × fy NDC units, into `out`; returns its key.
   */
  sample(x: number, y: number, fx: number, fy: number, out: Float64Array): number {
    this.texture.singular = false;
    this.reflected = SURFACE_NONE;
    const key = this.trace(x, y, fx, fy, out);
    const b = this.codes.base;
    return this.texture.singular ? key + b * b * b : key;
  }

  private trace(x: number, y: number, fx: number, fy: number, out: Float64Array): number {
    const ray = this.camera.rayThrough(this.primary, x, y, fx, fy);
    const view = this.view.view;
    if (view === 'reflection') return this.reflectionAlong(ray, out);
    if (view === 'fresnel') return this.fresnelAlong(ray, out);
    const b = this.codes.base;
    const second = this.along(ray, -Infinity, 0, view !== 'scene', out);
    return this.first + b * second + b * b * this.reflected;
  }

  /** The primary code found by the last `along` at level 0. */
  private first = SURFACE_NONE;

  /**
   * The colour along the direct `ray` past depth `tMin` into `out`; sets `first` to the code
   * of the surface it meets and returns the code of the one after it (for glass or a
   * transparent surface), else SURFACE_NONE.
   */
  private along(ray: Ray, tMin: number, level: number, glassOn: boolean, out: Float64Array): number {
    const layer = this.direct[level];
    const object = this.nearest(ray, tMin, 0, layer);
    const g = layer.glass;
    const glass = glassOn && this.scene.hitGlass(ray, g) && g.t > tMin && visible(g.t)
      && this.glassInFront(g, object) ? g : null;
    if (glass === null) {
      const next = this.shadeChain(object, ray, this.camera.eye, 0, level, glassOn, out);
      this.first = object ? object.surface : SURFACE_NONE;
      return next;
    }
    const { fresnel: model, ior, transparency } = this.view;
    const f = glassFresnel(model, ior, glass, ray.direction);
    const behind = object ? object.surface : SURFACE_NONE;
    this.shadeChain(object, ray, this.camera.eye, 0, level, false, layer.behind);
    this.reflected = this.reflectionAlong(ray, layer.reflection);
    if (this.alpha > 0 && this.microfacets !== null) {
      this.rough.apply(this, ray, this.mirrored, glass, level, this.side, this.plane!, this.alpha, this.view.ior, this.microfacets, layer.reflection, layer.behind);
    }
    composeGlass(model, f, transparency, this.texture.glassTexture(glass, ray), layer.reflection, layer.behind, out, this.top);
    this.first = glass.surface;
    return behind;
  }

  /**
   * What pass 1's FBO holds along `ray`: the scene mirrored across the glass, seen from the
   * real eye — i.e. the mirrored ray from the mirrored eye through the real scene, keeping
   * only what lies on the eye's side (the clip plane), at view depth t ∈ [near, far], shaded
   * with V towards the mirrored eye. Returns the surface code.
   */
  private reflectionAlong(ray: Ray, out: Float64Array): number {
    if (this.plane === null) {
      this.background(out);
      return SURFACE_NONE;
    }
    return this.mirroredAlong(this.mirrored.mirrorOf(ray, this.plane), -Infinity, 0, out);
  }

  private mirroredAlong(m: Ray, tMin: number, level: number, out: Float64Array, eye: Float64Array = this.mirroredEye): number {
    const object = this.nearest(m, tMin, this.side, this.mirror[level]);
    this.shadeChain(object, m, eye, this.side, level, false, out);
    return object ? object.surface : SURFACE_NONE;
  }

  /** The rough reflection's path (RoughGlass): what pass 1 sees along `ray`, shaded towards `eye`. */
  reflectedAlong(ray: Ray, eye: Float64Array, out: Float64Array): void {
    this.mirroredAlong(ray, -Infinity, 0, out, eye);
  }

  /** The rough transmission's path (RoughGlass): what lies past depth `tMin` along `ray`, shaded towards `eye`. */
  transmittedAlong(ray: Ray, tMin: number, level: number, eye: Float64Array, out: Float64Array): void {
    this.shadeChain(this.nearest(ray, tMin, 0, this.direct[level]), ray, eye, 0, level, false, out);
  }

  /**
   * Whether the glass hit is seen before `object`'s: nearer, or level with it (a face in the
   * glass plane) when the object is not on the viewer's side — what lies on the glass or beyond
   * is seen through it (the renderers pull the glass forward a hair, and objects on the
   * viewer's side further).
   */
  private glassInFront(g: SurfaceHit, object: SurfaceHit | null): boolean {
    if (object === null) return true;
    // A tie first: the glass and a face in its plane meet the ray a rounding apart either way.
    if (Math.abs(object.t - g.t) <= TIE * Math.abs(g.t)) return this.side * signedDistance(this.plane!, this.scene.centres[object.object]) <= 0;
    return g.t < object.t;
  }

  /** debug-view fresnel: F on glass not hidden by an opaque object, black elsewhere. */
  private fresnelAlong(ray: Ray, out: Float64Array): number {
    const layer = this.direct[0];
    let object = this.nearest(ray, -Infinity, 0, layer);
    const code = object ? object.surface : SURFACE_NONE;
    while (object !== null && this.opacity(object) < 1) object = this.nearest(ray, object.t, 0, layer);
    const g = layer.glass;
    if (this.scene.hitGlass(ray, g) && visible(g.t) && this.glassInFront(g, object)) {
      out.fill(glassFresnel(this.view.fresnel, this.view.ior, g, ray.direction));
      return g.surface;
    }
    out.fill(0);
    return code;
  }

  /**
   * `hit` shaded (the background when null) into `out`; a transparent hit is blended over
   * what lies past it on the same path. Returns the code of that next surface, if one was traced.
   */
  private shadeChain(
    hit: SurfaceHit | null, ray: Ray, eye: Float64Array, clipSide: number, level: number, glassOn: boolean, out: Float64Array,
  ): number {
    if (hit === null) {
      this.background(out);
      return SURFACE_NONE;
    }
    // Stryker disable next-line ConditionalExpression, EqualityOperator: the layer lends only its scratch texture buffer
    this.shade(hit, ray, eye, clipSide === 0 ? this.direct[level] : this.mirror[level], out);
    const alpha = clamp01(this.opacity(hit));
    if (alpha >= 1 || level + 1 >= MAX_LAYERS) return SURFACE_NONE;
    let next: number;
    let behind: Float64Array;
    if (clipSide === 0) {
      behind = this.direct[level + 1].colour;
      this.along(ray, hit.t, level + 1, glassOn, behind);
      next = this.first;
    } else {
      behind = this.mirror[level + 1].colour;
      next = this.mirroredAlong(ray, hit.t, level + 1, behind);
    }
    for (let k = 0; k < 3; k++) out[k] = clampTo(out[k] * alpha + behind[k] * (1 - alpha), this.top);
    return next;
  }

  private opacity(hit: SurfaceHit): number {
    return this.scene.scene.objects[hit.object].material.opacity;
  }

  /**
   * The nearest kept object hit: entry points of boxes and spheres (they are drawn with back
   * faces culled, so an entry point outside [near, far], on the clipped side when `clipSide` ≠ 0,
   * or not past `tMin` hides that object entirely), the nearest triangle of a mesh in the
   * kept interval. On a tie the earlier object wins.
   */
  private nearest(ray: Ray, tMin: number, clipSide: number, layer: Layer): SurfaceHit | null {
    const tracers = this.scene.tracers;
    const plane = this.plane;
    let best: SurfaceHit | null = null;
    let spare = layer.a;
    const objects = this.scene.scene.objects;
    for (let i = 0; i < tracers.length; i++) {
      // A mirrored path (clipSide ≠ 0) passes through an object kept out of the reflection.
      if (clipSide !== 0 && objects[i].reflected === false) continue;
      if (!tracers[i].hit(ray, tMin, clipSide, plane, spare) || !keptHit(tracers[i], this.texture, objects[i].material, ray, clipSide, plane, spare)) continue;
      if (best === null || spare.t < best.t) {
        const free: SurfaceHit = best ?? (spare === layer.a ? layer.b : layer.a);
        best = spare;
        spare = free;
      }
    }
    return best;
  }

  private background(out: Float64Array): void {
    out.set(this.backgroundColour);
  }

  private readonly viewVector = new Float64Array(3);

  /** An orthographic camera's constant view vector along `ray` (the mirrored one for a mirrored ray): −direction, unit. */
  private towardsViewer(ray: Ray): Float64Array {
    const d = ray.direction, v = this.viewVector;
    const len = Math.hypot(d[0], d[1], d[2]);
    // Stryker disable next-line ArithmeticOperator: orthographic rays (mirrored, rough) have unit directions: len = 1
    v[0] = -d[0] / len; v[1] = -d[1] / len; v[2] = -d[2] / len;
    return v;
  }

  /** Object colour, clamped to [0, 1]. */
  private shade(hit: SurfaceHit, ray: Ray, eye: Float64Array, layer: Layer, out: Float64Array): void {
    const object = this.scene.scene.objects[hit.object], m = object.material, view = this.camera.orthographic ? this.towardsViewer(ray) : null;
    const tex = this.texture.objectTexture(hit, ray, m, object.bounds, layer.tex);
    if (m.pbr) shadeGltf(this.texture, hit, ray, m, tex, this.lights, eye, out, view, this.environment);
    else shadeObject(hit, m, tex, this.lights, eye, out, view);
    out[0] = clampTo(out[0], this.top); out[1] = clampTo(out[1], this.top); out[2] = clampTo(out[2], this.top);
  }
}
