// One sample of one view: primary ray, what lies behind the glass (B), the mirror ray (R), composited.
import { reflectPoint, signedDistance } from '../math/mirror';
import { BACKGROUND, CAMERA, CUBE, GLASS, SPHERE, TEXTURE_SIZE } from '../scene/default-scene';
import { PinholeCamera } from './pinhole-camera';
import { Ray } from './ray';
import { RayScene, SurfaceHit, SURFACE_GLASS, SURFACE_NONE, isCube } from './ray-scene';
import { clamp01, composeGlass, glassFresnel, shadeObject } from './shade';
import { TextureSampler } from './texture-sampler';
import type { ReferenceState } from './reference-state';

/** 'point': bilinear at the sample's UV (GL LINEAR at mip 0). 'box': exact mean over its footprint. */
export type TextureFilter = 'point' | 'box';

/** Longest footprint edge, in texels: beyond it (grazing angles, sphere poles) it is shortened. */
export const MAX_FOOTPRINT_TEXELS = 64;

/** Surfaces per key digit (0 none, 1..6 cube faces, 7 sphere, 8 glass). */
export const KEY_BASE = 9;
/** Added to a key when a texture footprint had to be shortened (a singular mapping). */
export const KEY_SINGULAR = KEY_BASE ** 3;

const { near: NEAR, far: FAR } = CAMERA;

/**
 * Traces samples of one frame. A sample returns its colour and a key naming every surface
 * it saw — primary + 9·behind + 81·reflected, + KEY_SINGULAR when a texture footprint was
 * shortened (grazing incidence, the sphere's poles, where the linearised footprint is not
 * to be trusted) — so pixels whose samples disagree, or whose neighbours do, can be told
 * apart as edges (regions.ts).
 */
export class SampleTracer {
  private readonly camera: PinholeCamera;
  private readonly scene: RayScene;
  private readonly sampler = new TextureSampler();
  private readonly primary = new Ray();
  private readonly mirrored = new Ray();
  // Direct and mirrored paths keep their own hits: B is still in use when R is traced.
  private readonly cubeHit = new SurfaceHit();
  private readonly sphereHit = new SurfaceHit();
  private readonly mirroredCubeHit = new SurfaceHit();
  private readonly mirroredSphereHit = new SurfaceHit();
  private readonly glassHit = new SurfaceHit();
  private readonly mirroredEye = new Float64Array(3);
  /** +1 when the eye is on the +Z side of the glass (z = 0 counts as +), else −1. */
  private readonly side: number;
  private readonly behind = new Float64Array(3);
  private readonly reflection = new Float64Array(3);
  /** Set by textureAt when it shortened a footprint during the current sample. */
  private singular = false;

  constructor(private readonly state: ReferenceState, private readonly filter: TextureFilter) {
    this.camera = new PinholeCamera(state);
    this.scene = new RayScene(state);
    this.side = signedDistance(GLASS.plane, this.camera.eye) >= 0 ? 1 : -1;
    reflectPoint(this.mirroredEye, this.camera.eye, GLASS.plane);
  }

  /**
   * Colour (0..1 per channel, clamped as the 8-bit target holds it) of the sample at NDC
   * (x, y) whose footprint is fx × fy NDC units, into `out`; returns its key.
   */
  sample(x: number, y: number, fx: number, fy: number, out: Float64Array): number {
    this.singular = false;
    const key = this.trace(x, y, fx, fy, out);
    return this.singular ? key + KEY_SINGULAR : key;
  }

  private trace(x: number, y: number, fx: number, fy: number, out: Float64Array): number {
    const ray = this.camera.rayThrough(this.primary, x, y, fx, fy);
    const view = this.state.view;
    if (view === 'reflection') return this.traceReflection(ray, out);
    const object = this.nearestObject(ray, 0, this.cubeHit, this.sphereHit);
    const glass = view !== 'scene' && this.scene.hitGlass(ray, this.glassHit) && visible(this.glassHit.t)
      && (object === null || this.glassHit.t < object.t) ? this.glassHit : null;
    if (glass === null) {
      if (view === 'fresnel') out.fill(0);
      else this.shade(object, ray, this.camera.eye, out);
      return object ? object.surface : SURFACE_NONE;
    }
    const { fresnel: model, ior, transparency } = this.state;
    const f = glassFresnel(model, ior, glass, ray.direction);
    if (view === 'fresnel') {
      out.fill(f);
      return SURFACE_GLASS;
    }
    const behind = object ? object.surface : SURFACE_NONE;
    this.shade(object, ray, this.camera.eye, this.behind);
    const reflected = this.traceReflection(this.primary, this.reflection);
    composeGlass(model, f, transparency, this.textureAt(glass, ray), this.reflection, this.behind, out);
    return SURFACE_GLASS + KEY_BASE * behind + KEY_BASE * KEY_BASE * reflected;
  }

  /**
   * What pass 1's FBO holds along `ray`: the scene mirrored across the glass, seen from the
   * real eye — i.e. the mirrored ray from the mirrored eye through the real scene, keeping
   * only what lies on the eye's side (the clip plane), at view depth t ∈ [near, far], shaded
   * with V towards the mirrored eye. Returns the surface code.
   */
  private traceReflection(ray: Ray, out: Float64Array): number {
    const m = this.mirrored.mirrorOf(ray);
    const object = this.nearestObject(m, this.side, this.mirroredCubeHit, this.mirroredSphereHit);
    this.shade(object, m, this.mirroredEye, out);
    return object ? object.surface : SURFACE_NONE;
  }

  /**
   * The nearest object whose front face the ray enters at a depth the GPU keeps: the cube
   * and sphere are drawn with back faces culled, so an entry point outside [near, far]
   * (or on the clipped side, when `clipSide` ≠ 0) hides that object entirely.
   */
  private nearestObject(ray: Ray, clipSide: number, cubeHit: SurfaceHit, sphereHit: SurfaceHit): SurfaceHit | null {
    const cube = this.scene.hitCube(ray, cubeHit) && kept(cubeHit, clipSide) ? cubeHit : null;
    const sphere = this.scene.hitSphere(ray, sphereHit) && kept(sphereHit, clipSide) ? sphereHit : null;
    if (cube === null) return sphere;
    return sphere === null || cube.t <= sphere.t ? cube : sphere;
  }

  /** Object colour (or the background when `hit` is null), clamped to [0, 1]. */
  private shade(hit: SurfaceHit | null, ray: Ray, eye: Float64Array, out: Float64Array): void {
    if (hit === null) {
      out[0] = BACKGROUND[0]; out[1] = BACKGROUND[1]; out[2] = BACKGROUND[2];
      return;
    }
    const albedo = isCube(hit.surface) ? CUBE.albedo : SPHERE.albedo;
    shadeObject(hit, albedo, this.textureAt(hit, ray), eye, out);
    out[0] = clamp01(out[0]); out[1] = clamp01(out[1]); out[2] = clamp01(out[2]);
  }

  /** The texture at a hit: a bilinear point sample, or its mean over the sample's footprint. */
  private textureAt(hit: SurfaceHit, ray: Ray): number {
    if (this.filter === 'point') return this.sampler.bilinear(hit.u, hit.v);
    const d = ray.direction, n = hit.n, t = hit.t;
    const dn = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
    if (dn === 0) {
      this.singular = true;
      return this.sampler.bilinear(hit.u, hit.v);
    }
    // ∂p = t·∂d − t(∂d·n)/(d·n)·d: the differential moved onto the tangent plane at the hit.
    const a = FOOTPRINT_1, b = FOOTPRINT_2;
    if (footprintEdge(ray.ddx, d, n, dn, t, hit, a)) this.singular = true;
    if (footprintEdge(ray.ddy, d, n, dn, t, hit, b)) this.singular = true;
    return this.sampler.boxFilter(hit.u, hit.v, a[0], a[1], b[0], b[1]);
  }
}

const FOOTPRINT_1 = new Float64Array(2);
const FOOTPRINT_2 = new Float64Array(2);

function visible(t: number): boolean {
  return t >= NEAR && t <= FAR;
}

/** Inside the depth range and, for the mirrored pass, on the kept side of the glass plane. */
function kept(hit: SurfaceHit, clipSide: number): boolean {
  return visible(hit.t) && clipSide * signedDistance(GLASS.plane, hit.p) >= 0;
}

/** One footprint edge in texels (s, t) into `out`; true when it had to be shortened to MAX_FOOTPRINT_TEXELS. */
function footprintEdge(
  dd: Float64Array, d: Float64Array, n: Float64Array, dn: number, t: number, hit: SurfaceHit, out: Float64Array,
): boolean {
  const k = (t * (dd[0] * n[0] + dd[1] * n[1] + dd[2] * n[2])) / dn;
  let es = 0, et = 0;
  for (let i = 0; i < 3; i++) {
    const dp = t * dd[i] - k * d[i];
    es += hit.gu[i] * dp;
    et += hit.gv[i] * dp;
  }
  es *= TEXTURE_SIZE;
  et *= TEXTURE_SIZE;
  const len = Math.hypot(es, et);
  if (len <= MAX_FOOTPRINT_TEXELS) {
    out[0] = es;
    out[1] = et;
    return false;
  }
  // NaN/Infinity (a degenerate mapping) end up as NaN, which boxFilter treats as zero area.
  out[0] = (es * MAX_FOOTPRINT_TEXELS) / len;
  out[1] = (et * MAX_FOOTPRINT_TEXELS) / len;
  return true;
}
