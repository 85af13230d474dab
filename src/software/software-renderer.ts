// The CPU renderer (docs/software-renderer.md): the GL path's passes and equations (reflection into a second frame
// buffer, scene, glass) without DOM or GL, for a worker; RGBA8 out, top row first. In 'srgb'
// (docs/colour.md#srgb) textures and background are decoded, the Float32 buffers sum linear light and the
// resolve encodes once; 'none' uses every value as stored.
import { isRough } from '../frame/roughness';
import { eyeRelativePlane } from '../math/mirror';
import { srgbToLinear, type ColorSpace } from '../math/srgb';
import { colourCeiling, resolveFrame } from './encode';
import { RunningMean } from './running-mean';
import { gatherJitter, refinementScale, refines } from '../frame/refinement';
import { CourseProjection } from '../frame/course-projection';
import { orthographicView } from '../frame/orthographic-view';
import { FrameSetup } from '../frame/frame-setup';
import type { FrameState } from '../frame/types';
import type { SceneImages } from '../scene/decoded-image';
import { DefaultSceneCache } from '../scene/default-scene';
import type { Scene, SceneObject } from '../scene/scene';
import { GlassShader, GLASS_INDICES, GLASS_TIE_BIAS } from './glass-shader';
import { Lights } from './lighting';
import { drawnTwoSided } from '../frame/mesh-choice';
import { SoftwareMeshes } from './meshes';
import { proceduralMipTexture } from './mip-texture';
import { ImageTextures } from './image-textures';
import { ObjectShader, type ObjectDraw, type SoftwareTiming } from './object-shader';
import { ObjectCache } from './object-cache';
import { Rasterizer } from './raster';
import { RoughBuffers, RoughGather } from './rough-gather';
import { ROUGH_GATHER } from '../frame/rough-glass';
import { ggxAlpha } from '../math/ggx';
import { fill, PassesTiles } from './passes-tiles';

export interface SoftwareRendererOptions {
  /**
   * Samples per pixel along each axis (1..8): the frame is drawn on an n× finer grid at the
   * sample positions of the reference renderer's n×n strata and box-filtered, every sample
   * shaded (supersampling). Default 1: the frame state's `samples` decides — 2 or 4 draw with
   * 2×2 samples per pixel shaded once per pixel and triangle (multisampling, as MSAA), 0 with one.
   */
  samplesPerAxis?: number;
}

/** Which objects a draw takes, and on which side of the glass plane their fragments must lie. */
type Selection = 'opaque' | 'transparent';
type Side = 'all' | 'eye' | 'beyond';

const BLACK = [0, 0, 0] as const;

export class SoftwareRenderer {
  samplesPerAxis: number;
  /** The bench's split of a frame: when set, render() adds its phase times (ms) here. */
  timing: SoftwareTiming | null = null;
  /** Every part FrameSetup takes: this chunk is lazy already. */
  private readonly setup = new FrameSetup(new CourseProjection(), orthographicView);
  private readonly meshes = new SoftwareMeshes();
  private readonly main = new Rasterizer();
  private readonly mirror = new Rasterizer();
  private readonly objectShader = new ObjectShader();
  /** Opaque objects' colours from the frames before, on the scene's grid and the reflection's. */
  private readonly mainCache = new ObjectCache();
  private readonly mirrorCache = new ObjectCache();
  private readonly glassShader = new GlassShader();
  private readonly lightsMain = new Lights();
  private readonly lightsMirrored = new Lights();
  private colour = new Float32Array(0);
  /** The mean of a still view's refinement frames (docs/refinement.md#averaging). */
  private readonly mean = new RunningMean();
  private reflection = new Float32Array(0);
  private mask = new Uint8Array(0);
  private output = new Uint8ClampedArray(0);
  private readonly textures = new ImageTextures();
  // Stryker disable StringLiteral,ArrayDeclaration,ObjectLiteral,BooleanLiteral: first values, each set before it is read (space, transparent, the glass's texture by prepare(), every field of draw by drawObjects()); options {} has no samplesPerAxis either
  /** The frame's colour space, and the background in it (decoded with 'srgb'). */
  private space: ColorSpace = 'none';
  private readonly background = new Float64Array(3);
  private readonly sideClip = new Float64Array(4);
  private readonly transparent: number[] = [];
  /**
   * The pixel rows to draw, [top, bottom): one band of a frame split across workers
   * (element/software-host.ts); the output's other rows are left as they were. Every row drawn
   * is the whole frame's, bit for bit (the same setup, tessellation and triangles, clamped to the
   * rows; Rasterizer.top). Ignored — the whole frame drawn — by rough glass, whose glass gathers
   * from around each pixel over the whole frame, and by the `passes` view. null: every row.
   */
  band: { top: number; bottom: number } | null = null;
  private readonly passesTiles = new PassesTiles();
  /** The samples drawn this frame, [from, to) on the target's grid (the band's rows). */
  private from = 0;
  private to = 0;
  private readonly draw: ObjectDraw;
  private readonly defaultScene = new DefaultSceneCache();
  /** Shaded samples per pixel along an axis (supersampling's n; 1 when multisampled). */
  private pixelScale = 1;
  /** Rough glass (docs/rough-glass.md#roughness). */
  private readonly rough = new RoughGather();
  private readonly roughBuffers = new RoughBuffers();
  private readonly forward = new Float64Array(3);
  private readonly viewerNormal = new Float64Array(3);

  constructor(options: SoftwareRendererOptions = {}) {
    this.samplesPerAxis = options.samplesPerAxis ?? 1;
    this.glassShader.texture = proceduralMipTexture('none');
    this.draw = {
      mesh: { positions: new Float32Array(0), normals: new Float32Array(0), uvs: new Float32Array(0), indices: new Uint16Array(0) },
      model: new Float64Array(16), normal: new Float64Array(9), eye: [0, 0, 0], view: [0, 0, 0, 1], viewProjection: new Float64Array(16),
      clipPlane: null, material: undefined as unknown as ObjectDraw['material'], bounds: { center: [0, 0, 0], radius: 1 },
      texture: this.glassShader.texture, twoSided: false, shading: 'phong', lights: this.lightsMain, cache: null, index: 0, maps: { metalRough: null, occlusion: null, emissive: null, normal: null, alpha: null },
    };
  }
  // Stryker restore StringLiteral,ArrayDeclaration,ObjectLiteral,BooleanLiteral

  /** Whether `band` is drawn as a band for this state (else the whole frame is: rough glass, the `passes` view). */
  drawsBands(state: FrameState): boolean {
    return state.view !== 'passes' && !isRough(state);
  }

  /**
   * Draws `state.view` of `scene` and returns its pixels: RGBA8, top row first. The array is the
   * renderer's own and is overwritten by the next call. The renderer contract (ARCHITECTURE.md,
   * "How a frame flows"): `scene` null is the default scene for `state` (docs/default-scene.md),
   * kept between frames; `images` the decoded images the scene names, by URL (a material whose
   * image is missing draws with the procedural texture).
   */
  render(scene: Scene | null, state: FrameState, images?: SceneImages | null): Uint8ClampedArray {
    if (state.view === 'passes') return this.passesTiles.draw(state, (tile) => this.timed(scene, tile, images, false));
    return this.timed(scene, state, images, true);
  }

  private timed(scene: Scene | null, state: FrameState, images: SceneImages | null | undefined, banded: boolean): Uint8ClampedArray {
    const timing = this.timing;
    this.objectShader.timing = timing;
    if (!timing) return this.frame(scene, state, images, banded);
    const t0 = performance.now();
    try {
      return this.frame(scene, state, images, banded);
    } finally {
      timing.total += performance.now() - t0;
    }
  }

  private frame(scene: Scene | null, state: FrameState, images: SceneImages | null | undefined, banded: boolean): Uint8ClampedArray {
    scene ??= this.defaultScene.get(state.cubeDistance, state.spin);
    const ssaa = Math.max(1, Math.min(8, Math.floor(this.samplesPerAxis)));
    const msaa = ssaa === 1 && state.samples >= 2 ? 2 : 1;
    const n = ssaa * msaa;
    this.main.shadeEvery = this.mirror.shadeEvery = msaa;
    this.pixelScale = ssaa;
    this.main.footprint = this.mirror.footprint = 1 / refinementScale(state);
    const width = Math.max(0, Math.floor(state.width)), height = Math.max(0, Math.floor(state.height));
    const W = width * n, H = height * n;
    this.resize(W, H, width * height);
    if (W === 0 || H === 0) return this.output;
    const band = banded && this.drawsBands(state) ? this.band : null;
    const top = band ? Math.max(0, Math.min(height, Math.floor(band.top))) : 0;
    const bottom = band ? Math.max(top, Math.min(height, Math.floor(band.bottom))) : height;
    this.main.top = this.mirror.top = top * n;
    this.main.bottom = this.mirror.bottom = bottom * n;
    this.from = top * n * W;
    this.to = bottom * n * W;
    this.prepare(scene, state);
    this.objectShader.top = this.glassShader.top = colourCeiling(state);

    const view = state.view; // 'passes' is tiled by render()
    let source = this.colour;
    const hasGlass = this.setup.hasGlass;
    switch (view) {
      case 'reflection':
        if (hasGlass) {
          this.mask.fill(1, this.from, this.to);
          this.reflectionPass(scene, state, images, false);
          source = this.reflection;
        } else {
          fill(this.colour, this.from, this.to, this.background);
        }
        break;
      case 'scene':
        this.scenePass(scene, state, images, 'all');
        break;
      case 'fresnel':
        this.opaquePass(scene, state, images);
        fill(this.colour, this.from, this.to, BLACK);
        if (hasGlass) this.glass('fresnel');
        break;
      default:
        if (!hasGlass) {
          this.scenePass(scene, state, images, 'all');
          break;
        }
        // Opaque objects, transparent ones beyond the glass, the glass's footprint, the
        // reflection there only, the glass over it all, transparent objects on the eye's side.
        if (isRough(state)) this.roughGlass(scene, state, images, width);
        else {
          this.scenePass(scene, state, images, 'beyond');
          this.mask.fill(0, this.from, this.to);
          this.glass('mask');
          this.reflectionPass(scene, state, images, true);
          this.glass('compose');
        }
        this.drawObjects(this.main, scene, state, images, false, 'transparent', 'eye');
    }
    // F is a number, shown unencoded in either space (docs/colour.md#debug-views); every other view is a picture.
    const out = this.output.subarray(4 * top * width, 4 * bottom * width);
    const samples = source.subarray(3 * this.from, 3 * this.to);
    if (refines(state)) resolveFrame(out, this.mean.add(samples, width, height, top, bottom, n, state.refinement!, state.refinementFrames ?? 1), width, bottom - top, 1, state);
    else resolveFrame(out, samples, width, bottom - top, n, state);
    return this.output;
  }

  /**
   * The glass passes when rough (docs/rough-glass.md#roughness): the frame beyond the glass alone (when T > 0) and
   * the whole reflection, each with its distance codes and mips, then the scene and the glass
   * gathering R̃ and B̃ from them (rough-gather.ts).
   */
  private roughGlass(scene: Scene, state: FrameState, images: SceneImages | null | undefined, width: number): void {
    const r = this.main, W = r.width, H = r.height, s = this.setup, g = this.rough, b = this.roughBuffers, shader = this.objectShader;
    b.resize(W * H);
    const transmits = state.transparency > 0, plane = s.glass.plane, codePlane = shader.codePlane;
    shader.codes = b.codes;
    try {
      if (transmits) {
        for (let k = 0; k < 4; k++) codePlane[k] = -s.side * plane[k];
        fill(b.behind, 0, W * H, this.background);
        b.codes.fill(1, 0, W * H);
        r.clearDepth();
        r.mask = null;
        shader.colour = b.behind;
        this.drawObjects(r, scene, state, images, false, 'opaque', 'beyond');
        this.drawObjects(r, scene, state, images, false, 'transparent', 'beyond');
        b.build(g, 1, b.behind, W, H);
      }
      shader.colour = this.colour;
      for (let k = 0; k < 4; k++) codePlane[k] = s.side * plane[k];
      b.codes.fill(1, 0, W * H);
      this.reflectionPass(scene, state, images, false);
      b.build(g, 0, this.reflection, W, H);
    } finally {
      shader.codes = null;
      shader.colour = this.colour;
    }
    this.scenePass(scene, state, images, 'beyond');
    g.alpha = ggxAlpha(state.roughness ?? 0);
    g.ior = state.ior;
    g.settings = ROUGH_GATHER[state.roughnessQuality ?? 'medium'];
    g.fixedLevel = state.fixedBlurLevel ?? -1;
    g.cells = W / width;
    g.footprint = r.shadeEvery;
    gatherJitter(state, g.jitter);
    const v = s.viewVectorMain;
    this.forward[0] = -v[0]; this.forward[1] = -v[1]; this.forward[2] = -v[2];
    for (let k = 0; k < 3; k++) this.viewerNormal[k] = s.side * plane[k];
    g.background.set(this.background);
    g.frame(s.viewProjection, s.eye, W, H, this.viewerNormal, v[3] === 0, this.forward);
    const glass = this.glassShader;
    glass.rough = g;
    glass.roughTransmission = transmits;
    try {
      this.glass('compose');
    } finally {
      glass.rough = null;
    }
  }

  private resize(W: number, H: number, pixels: number): void {
    const N = W * H;
    if (this.colour.length < 3 * N) {
      this.colour = new Float32Array(3 * N);
      this.reflection = new Float32Array(3 * N);
      this.mask = new Uint8Array(N);
    }
    if (this.output.length !== 4 * pixels) this.output = new Uint8ClampedArray(4 * pixels);
    this.main.resize(W, H);
    this.mirror.resize(W, H);
    this.objectShader.colour = this.colour;
    this.glassShader.colour = this.colour;
    this.glassShader.reflection = this.reflection;
    this.glassShader.mask = this.mask;
  }

  private prepare(scene: Scene, state: FrameState): void {
    const s = this.setup;
    const space: ColorSpace = state.colorSpace === 'srgb' ? 'srgb' : 'none';
    this.space = space;
    const bg = scene.background, b = this.background;
    for (let k = 0; k < 3; k++) b[k] = space === 'srgb' ? srgbToLinear(bg[k]) : bg[k];
    this.glassShader.texture = proceduralMipTexture(space);
    // The frame's matrices, both eyes' and the reflection's clip plane, as the GL path has them.
    s.update(state, scene);
    this.lightsMain.set(scene, s.lightWorld, s.eye);
    this.lightsMirrored.set(scene, s.lightWorld, s.mirroredEye);
    this.glassShader.model = state.fresnel;
    this.glassShader.ior = state.ior;
    this.glassShader.transparency = state.transparency;
    // Transparent objects back to front by their bounds' centre (the GL path draws them in
    // scene order; the reference sorts per ray).
    const t = this.transparent;
    t.length = 0;
    for (let i = 0; i < scene.objects.length; i++) if (scene.objects[i].material.opacity < 1) t.push(i);
    const eye = s.eye;
    const dist = (i: number) => {
      const c = s.objects[i].center;
      return (c[0] - eye[0]) ** 2 + (c[1] - eye[1]) ** 2 + (c[2] - eye[2]) ** 2;
    };
    t.sort((a, b) => dist(b) - dist(a));
  }

  /** Pass 2: background, opaque objects, then transparent ones (those on `side` of the glass). */
  private scenePass(scene: Scene, state: FrameState, images: SceneImages | null | undefined, side: Side): void {
    this.opaquePass(scene, state, images);
    this.drawObjects(this.main, scene, state, images, false, 'transparent', side);
  }

  private opaquePass(scene: Scene, state: FrameState, images: SceneImages | null | undefined): void {
    const r = this.main;
    fill(this.colour, this.from, this.to, this.background);
    r.clearDepth();
    r.mask = null;
    this.drawObjects(r, scene, state, images, false, 'opaque', 'all');
  }

  /** Pass 1 into the reflection buffer, at the masked pixels only when `masked`. */
  private reflectionPass(scene: Scene, state: FrameState, images: SceneImages | null | undefined, masked: boolean): void {
    const r = this.mirror;
    fill(this.reflection, this.from, this.to, this.background);
    r.clearDepth();
    r.mask = masked ? this.mask : null;
    this.objectShader.colour = this.reflection;
    try {
      this.drawObjects(r, scene, state, images, true, 'opaque', 'eye');
      this.drawObjects(r, scene, state, images, true, 'transparent', 'eye');
    } finally {
      this.objectShader.colour = this.colour;
      r.mask = null;
    }
  }

  private glass(mode: GlassShader['mode']): void {
    const g = this.glassShader, s = this.setup;
    g.mode = mode;
    g.setup(s.glass, s.eye, s.viewProjection, s.viewVectorMain);
    this.main.mask = null;
    const timing = this.timing;
    const t0 = timing ? performance.now() : 0;
    g.draw(this.main, GLASS_INDICES);
    if (timing) timing.glass += performance.now() - t0;
  }

  private drawObjects(
    r: Rasterizer, scene: Scene, state: FrameState, images: SceneImages | null | undefined,
    mirrored: boolean, selection: Selection, side: Side,
  ): void {
    const s = this.setup, d = this.draw, objects = scene.objects;
    const eye = mirrored ? s.mirroredEye : s.eye;
    const plane = s.glass.plane;
    let clip: Float64Array | null = null;
    if (mirrored) clip = s.mirroredClip;
    else if (side !== 'all' && s.hasGlass) clip = eyeRelativePlane(this.sideClip, plane, eye, side === 'eye' ? s.side : -s.side);
    const order = selection === 'transparent' ? this.transparent : null;
    const count = order ? order.length : objects.length;
    r.depthTest = true;
    r.depthWrite = selection === 'opaque';
    r.frontCCW = !mirrored !== s.mirrorsWinding; // the mirror flips winding; so may a course camera
    for (let k = 0; k < count; k++) {
      const i = order ? order[k] : k;
      const o: SceneObject = objects[i];
      if (selection === 'opaque' && o.material.opacity < 1) continue;
      // Selection: an object kept out of the reflection (docs/scene-model.md#glass-object).
      if (mirrored && o.reflected === false) continue;
      const m = s.objects[i];
      // Culling, not selection (docs/rendering.md#what-is-skipped): bounds wholly beyond the glass cannot be reflected.
      if (mirrored && m.viewerDistance <= -m.radius) continue;
      d.mesh = this.meshes.get(o.geometry, state, m.center, m.radius, s.halfHeight, this.pixelScale);
      d.model = m.model;
      d.normal = m.normal;
      d.eye = eye;
      d.view = mirrored ? s.viewVectorMirrored : s.viewVectorMain;
      d.viewProjection = mirrored ? s.mirroredViewProjection : s.viewProjection;
      d.clipPlane = clip;
      d.material = o.material;
      d.bounds = o.bounds;
      d.texture = this.textures.base(o.material, images, this.space);
      this.textures.maps(o.material.pbr, images, this.space, d.maps);
      d.twoSided = drawnTwoSided(o);
      d.shading = state.shading;
      d.lights = mirrored ? this.lightsMirrored : this.lightsMain;
      d.cache = selection === 'opaque' ? (mirrored ? this.mirrorCache : this.mainCache) : null;
      d.index = i;
      r.cull = d.twoSided ? 'none' : 'back';
      // A depth tie with the glass: an object on the viewer's side wins, one on the plane or
      // beyond it loses (pushed back twice as far as the glass).
      r.depthBias = !mirrored && s.hasGlass && m.viewerDistance <= 0 ? 2 * GLASS_TIE_BIAS : 0;
      this.objectShader.render(d, r);
    }
    r.depthBias = 0;
  }
}
