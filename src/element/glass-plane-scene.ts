// <glass-plane-scene>: a thin host over its controllers. It owns the shadow DOM, parses the attributes and fans their
// changes out, and keeps the public API and its events. When frames are drawn is the FrameLoop's business, the camera
// the CameraRig's, the scene value SceneValue's, who draws the BackendController's (WebGL2 or CPU), GL the renderer's.
import { ATTRIBUTES, DEBUG_VIEWS, defaultAttributes, type SceneAttributes } from './attributes';
import { defineAttributeProperties, parseAttribute, upgradeProperties, type AttributeHost } from './attribute-properties';
import { AttributeWarnings, warn } from './warnings';
import { applyStyle } from './element-style';
import { readCanvas } from './canvas-readback';
import type { FrameState, RenderStats } from '../frame/types';
import type { Scene } from '../scene/scene';
import type { CapturePass, GlassPlaneSceneEventMap } from './types';
import type { Controller } from './controller';
import { ElementBase } from './element-base';
import { SceneSource } from './scene-source';
import type { TextureImages } from './texture-images';
import { LazyParts } from '../frame/lazy-parts';
import { ELEMENT_PARTS, FAILURE_MESSAGES, GROUP_ROTATION, type ElementPartsHost } from './parts';
import { sceneSpins } from './compose-scene';
import { SceneValue } from './scene-value';
import { FrameStates, refineFrames } from './frame-state';
import { CameraRig } from './camera-rig';
import { FrameLoop } from './frame-loop';
import { BackendController } from './backend-controller';
import { Failure } from './failure';
import { FrameEvents } from './frame-events';
import { routeAttribute, type AttributeRoutes } from './attribute-routes';
import { LoadingView } from './loading-view';

const DEFAULT_LABEL = 'A dark glass plane reflecting a cube, with a sphere behind it';
export interface GlassPlaneScene extends SceneAttributes {}

/**
 * A plane of dark glass that reflects the viewer's side and lets through what is behind it, with Fresnel (docs/element.md,
 * docs/default-scene.md); `<glass-object>` and `<glass-light>` children replace the default objects and light
 * (docs/scene-model.md#children). Every attribute is also a camelCase property.
 *
 * @tagname glass-plane-scene
 * @attr {number} [transparency=0.5] - T in the glass equation, 0..1; 1 = clear glass
 * @attr {number} [cube-distance=0.75] - z of the cube's centre (signed distance from the glass)
 * @attr {number} [ior=1.5] - index of refraction for the Fresnel term, 1..10
 * @attr {'exact' | 'schlick' | 'classic'} [fresnel="exact"] - Fresnel model
 * @attr {string} [camera-position="3.6 2.4 0.2"] - "x y z" of the camera
 * @attr {string} [camera-rotation="-169 -23.6"] - "yaw pitch" in degrees; yaw −90 looks down −Z, pitch clamped to ±89.9
 * @attr {number} [fov=60] - vertical field of view in degrees, 1..179
 * @attr {'perspective' | 'orthographic'} [projection="perspective"] - orthographic keeps the size the perspective view had at the target (or the glass centre)
 * @attr {'flyby' | 'orbit' | 'trackball' | boolean} [controls=null] - the input mode; the bare attribute means flyby; absent: no input
 * @attr {'auto' | 'webgl' | 'software'} [renderer="auto"] - auto: WebGL2 where available, else the CPU renderer (in a worker)
 * @attr {string} [camera-target=null] - "x y z" the camera looks at (overrides camera-rotation); orbit turns about it
 * @attr {string} [camera-src=null] - URL of a course camera file (.cfg: C, N, V, d hx hy); while it is in force it is the view
 * @attr {number} [spin=0.8] - the cube's spin about its Y axis, rad/s; 0 stops it
 * @attr {number} [time=null] - fixes the scene clock, in seconds (deterministic frames); absent: the live clock
 * @attr {'none' | 'reflection' | 'scene' | 'fresnel' | 'passes'} [debug-view="none"] - shows one pass instead of the final image
 * @attr {number} [reflection-scale=1] - reflection framebuffer size ÷ drawing-buffer size, 0.125..2
 * @attr {0 | 2 | 4} [samples=4] - MSAA samples of the reflection and scene passes (software: 2×2 per pixel for 2 and 4)
 * @attr {number} [refine=10] - frames a still view draws to converge to the supersampled picture, 0..1024; 0 off; with it moving frames draw one sample
 * @attr {'phong' | 'gouraud' | 'flat'} [shading="phong"] - per-fragment phong, per-vertex gouraud, or flat
 * @attr {number | 'auto'} [tessellation="auto"] - sphere segments 4..512, or auto (from the sphere's size on screen)
 * @attr {number | 'auto'} [pixel-ratio="auto"] - drawing-buffer pixels per CSS pixel 0.25..4, or auto (devicePixelRatio)
 * @attr {'rgba8' | 'rgba16f'} [reflection-format="rgba8"] - reflection storage (rgba16f: half float, where supported)
 * @attr {'srgb' | 'none'} [color-space="srgb"] - srgb: linear-light rendering with sRGB in and out; none: colours used as stored (the course programs)
 * @attr {'auto' | 'neutral' | 'aces' | 'none'} [tone-mapping="auto"] - the curve from light to the screen at the frame's end (srgb): auto is neutral for a scene with a glTF material, else none (clipped at 1)
 * @attr {number} [exposure=1] - a factor on the frame's light before the tone mapping, 0..64
 * @attr {string} [environment="neutral"] - the light from all around on glTF materials: neutral (a studio of soft panels), none (the lights alone), or the URL of an equirectangular .hdr, PNG or JPEG
 * @attr {number} [environment-intensity=1] - a factor on the environment's light, 0..64
 * @attr {number} [roughness=0] - rough glass (GGX, α = roughness²), 0..1: 0 polished; blurs what the glass reflects and lets through, sharp where an object touches it
 * @attr {'low' | 'medium' | 'high'} [roughness-quality="medium"] - neighbours rough glass gathers per pixel: low 4, medium 8, high 16 per ring
 * @attr {string} [glass-center="0 1 0"] - "x y z": centre of the glass rectangle
 * @attr {string} [glass-normal="0 0 1"] - "x y z": normal of the glass; "0 1 0" makes a glass floor
 * @attr {string} [glass-size="8 4"] - "w h": width and height of the glass; "0 0" means no glass
 * @attr {string} [background="0.1 0.1 0.1"] - any CSS colour, or "r g b" in 0..1: the clear colour, also of the reflection
 * @attr {string} [poster=null] - URL of an image shown until the first frame with the content is drawn
 * @attr {string} [alt="A dark glass plane reflecting a cube, with a sphere behind it"] - text alternative; becomes the aria-label
 * @fires {CustomEvent<FrameReport>} ready - once, after the first frame is on the canvas
 * @fires {CustomEvent<FrameReport>} frame - after every frame drawn
 * @fires {CustomEvent<FrameReport>} refined - after the last frame of a still view's refinement: the picture is final
 * @fires {CustomEvent<GlassPlaneSceneErrorDetail>} error - WebGL2 unavailable, a shader failed, the context was lost, or a load failed
 * @fires {CustomEvent<CameraChangeDetail>} camera-change - after a gesture moved the camera, or the page set a camera attribute
 * @csspart canvas - the canvas the scene is drawn on
 * @csspart message - the message shown when the scene cannot be drawn
 * @csspart progress - the bar shown while children's models load; its fill is `progress-bar`
 * @csspart poster - the `poster` image, until the first frame with the content is drawn
 */
export class GlassPlaneScene extends ElementBase<GlassPlaneSceneEventMap> implements AttributeHost {
  static get observedAttributes(): string[] {
    return [...ATTRIBUTES.map((a) => a.attribute), 'alt'];
  }

  private readonly values: SceneAttributes = defaultAttributes();
  private readonly canvas: HTMLCanvasElement;
  private readonly failure: Failure;
  private readonly warnings = new AttributeWarnings();
  /** The light-DOM children (<glass-object>, <glass-light>) as parts of the scene. */
  private readonly source = new SceneSource({ element: this, partsChanged: () => this.sceneChanged(), environment: () => this.values.environment });
  /** Image textures the scene names, decoded once per URL per page, given to the renderer: a lazy part (TEXTURE_IMAGES); null before it is in. */
  private images: TextureImages | null = null;
  /** What only some pages need (element/parts.ts), asked for with the renderer's once per frame. */
  private readonly parts: LazyParts<ElementPartsHost>;
  /** The camera, its controls, the trackball and the course camera. */
  private readonly rig: CameraRig;
  /** The scene value, built when its content changes; the trackball's turn travels apart. */
  private readonly scenes: SceneValue;
  private readonly states = new FrameStates();
  /** When frames are drawn: on demand, in view, with the page shown. */
  private readonly loop: FrameLoop;
  /** Who draws them: WebGL2 or the CPU renderer. */
  private readonly backend: BackendController;
  /** Connected and disconnected in this order. */
  private readonly controllers: Controller[];
  private readonly events: FrameEvents;
  /** Where each attribute's change goes beyond the scene value and the frame state. */
  private readonly routes: AttributeRoutes;

  constructor() {
    super();
    const root = this.attachShadow({ mode: 'open' });
    applyStyle(root);
    const canvas = (this.canvas = document.createElement('canvas'));
    canvas.setAttribute('part', 'canvas');
    this.failure = new Failure(this, canvas, () => this.parts.fetch(FAILURE_MESSAGES));
    root.append(canvas, this.failure.message);
    const requestRender = () => this.requestRender();
    this.rig = new CameraRig({
      element: this, canvas, values: this.values, requestRender,
      turned: () => this.scenes.turnChanged(), flybyMoved: () => { this.loop.dirty = true; }, scene: () => this.scene,
      cycleDebugView: () => { this.debugView = DEBUG_VIEWS[(DEBUG_VIEWS.indexOf(this.values.debugView) + 1) % DEBUG_VIEWS.length]; },
    });
    const { objectRotation, lightRotation } = this.rig;
    this.scenes = new SceneValue({
      inputs: () => ({ ...this.values, spin: this.effectiveSpin() }), parts: () => this.source.current(), objectRotation, lightRotation,
    });
    const parts: ElementPartsHost = {
      values: this.values, rig: this.rig, scenes: this.scenes, source: this.source,
      namesImages: () => this.scenes.namesImages(),
      imagesArrived: (chunk) => { this.images = new chunk.TextureImages({ sink: () => this.backend.current, loaded: requestRender }); },
      provideRotation: (code) => this.parts.provide(GROUP_ROTATION, code),
    };
    this.parts = new LazyParts(ELEMENT_PARTS, parts, { settled: requestRender, warn });
    this.states.current.turn = this.scenes.turn;
    this.loop = new FrameLoop({
      element: this, canvas, pixelRatio: () => this.values.pixelRatio, maxSize: () => this.backend.maxSize,
      canDraw: () => this.backend.current !== null && !this.failure.type,
      animating: () => (this.values.time === null && sceneSpins(this.scenes.current)) || this.rig.moving,
      frame: (now, k) => this.drawFrame(now, k), refineFrames: () => refineFrames(this.values),
      paused: () => this.rig.paused(), idle: () => this.rig.idle(), motionPreferenceChanged: () => this.sceneChanged(),
    });
    this.backend = new BackendController({
      element: this, canvas, failure: this.failure, requestRender, renderer: () => this.values.renderer,
      started: (backend) => { this.images?.feed(backend); this.loop.resize(); this.requestRender(); },
      stopFrames: () => this.loop.cancel(), drawn: (state, report) => this.events.drawn(state, report), resume: (t) => this.loop.resume(t),
    });
    this.events = new FrameEvents({
      element: this, loading: () => this.source.loading || this.rig.loading || this.parts.loading, atRest: () => this.loop.atRest(),
      // A frame drawn clears a shader failure's message and is kept for capture.
      drawn: (state) => { this.failure.drawn(); this.states.drawn(state); }, failed: () => this.failure.type !== null,
    });
    const loading = new LoadingView({ element: this, root, poster: () => this.values.poster });
    this.routes = { rig: this.rig, backend: this.backend, loop: this.loop, failure: this.failure, loading, element: this, requestRender };
    this.controllers = [this.rig, this.loop, this.source, this.backend];
    // An upgrade: what the page set before the definition goes through the accessors now, so it
    // holds before the element is connected; the attributes it writes get no callback meanwhile.
    for (const name of upgradeProperties(this, ['alt', 'objectRotation'])) this.attributeChangedCallback(name);
  }

  // ---- lifecycle -------------------------------------------------------------------------

  connectedCallback(): void {
    if (!this.hasAttribute('tabindex')) this.tabIndex = 0;
    if (!this.hasAttribute('role')) this.setAttribute('role', 'img');
    if (!this.hasAttribute('aria-label')) this.setAttribute('aria-label', this.alt);
    for (const c of this.controllers) c.hostConnected?.();
  }

  disconnectedCallback(): void {
    for (const c of this.controllers) c.hostDisconnected?.();
  }

  attributeChangedCallback(name: string): void {
    // The value now: an upgrade queues its callbacks with the values the attributes had before
    // the constructor, which may have set them since (upgradeProperties).
    const raw = this.getAttribute(name);
    if (name === 'alt') {
      this.setAttribute('aria-label', raw ?? DEFAULT_LABEL);
      return;
    }
    const p = parseAttribute(this.values, name, raw, this.warnings);
    if (!p) return;
    this.scenes.attributeChanged(p);
    routeAttribute(p, this.routes);
  }

  // ---- public API --------------------------------------------------------------------------

  /** Text alternative for assistive technology (like <img alt>); becomes the aria-label. */
  get alt(): string {
    return this.getAttribute('alt') ?? DEFAULT_LABEL;
  }

  set alt(value: string) {
    this.setAttribute('alt', String(value));
  }

  /**
   * The scene as one value (docs/scene-model.md#one-scene-value): the glass and background from the attributes, the
   * children's objects and lights, or the default scene's (docs/default-scene.md) where there are none, turned by the
   * trackball. Read-only; a new value after every change (the same object until then). A turn
   * set without `controls` shows in it from the next `frame` on (its code is fetched first).
   */
  get scene(): Scene {
    return this.scenes.turned;
  }

  /**
   * The trackball's rotation of the objects about the centre of their bounds, a unit quaternion
   * [x, y, z, w] (identity [0, 0, 0, 1]). Never written to an attribute; settable (normalised;
   * a value that is not four finite numbers, or zero, is ignored with a warning).
   */
  get objectRotation(): [number, number, number, number] {
    return [...this.rig.objectRotation] as [number, number, number, number];
  }

  set objectRotation(value: ArrayLike<number>) {
    if (this.rig.setObjectRotation(value)) return;
    warn(`objectRotation: expected a quaternion [x, y, z, w], ignoring ${JSON.stringify(value)?.slice(0, 60)}`);
  }

  /** Draws a frame on the next animation frame, even when nothing changed. */
  requestRender(): void {
    this.loop.request();
  }

  /**
   * RGBA8 pixels of the last frame (no argument: exactly what is on screen, read back from the
   * element's canvas without drawing) or of one pass (drawn off screen from the last frame's
   * state), at the drawing-buffer size, top row first. Null while nothing can be drawn.
   */
  capture(pass?: CapturePass): ImageData | null {
    if (!this.backend.current || this.failure.type) return null;
    if (pass === undefined) return this.events.frames > 0 ? readCanvas(this.canvas) : null;
    return this.backend.capture(this.scenes.current, this.states.last ?? this.frameState(performance.now()), pass);
  }

  /** Resolves once the picture is final (docs/refinement.md#events): after `refined`, or a frame at rest with nothing to refine. */
  whenRefined(): Promise<void> {
    return this.events.whenRefined();
  }

  /** Frames, passes run and skipped, draw calls, compiled programs, live GL resources and scene builds. */
  get stats(): RenderStats {
    const s = this.backend.stats();
    this.events.count(s);
    s.sceneBuilds = this.scenes.builds;
    return s;
  }

  /** @internal AttributeHost: the parsed value, or the live pose for the flown camera. */
  readAttributeValue(property: keyof SceneAttributes): unknown {
    return this.rig.liveValue(property) ?? this.values[property];
  }

  /**
   * One frame, `refinement` of a still view (docs/refinement.md#at-rest): the controls advance, then the backend draws, unless
   * its last frame is still on its way or a lazy part the frame needs is (dirty stays set: a frame is asked for when it lands).
   */
  private drawFrame(now: number, refinement: number): boolean {
    this.rig.step();
    const backend = this.backend.current!;
    if (backend.busy) return false;
    const scene = this.scenes.current;
    if (this.clientWidth === 0 || this.clientHeight === 0) return (this.loop.dirty = false); // nothing to show
    const state = this.frameState(now, refinement);
    // The frame's one question, to the element's parts and the renderer's: both start what they lack.
    const held = this.parts.request() !== null;
    if (backend.waitsFor(scene, state) || held) return false;
    this.loop.dirty = false;
    this.images?.sync(scene);
    this.events.started();
    backend.draw(scene, state);
    return true;
  }

  /** The attributes' part of the frame, then the camera's (which reads the scene for a course camera). */
  private frameState(now: number, refinement = 0): FrameState {
    const s = this.states.fill(this.values, now, this.canvas.width, this.canvas.height, this.effectiveSpin(), this.scenes.current, refinement);
    this.rig.aim(s, this.scenes.current);
    return s;
  }

  /** Spin counts unless reduced motion is asked for and the page did not set `spin` itself. */
  private effectiveSpin(): number {
    return this.loop.reducedMotion && !this.hasAttribute('spin') ? 0 : this.values.spin;
  }

  /** A child was added, removed, reordered, changed, upgraded, or its model arrived; or reduced motion changed. */
  private sceneChanged(): void {
    this.scenes.contentChanged();
    this.requestRender();
  }
}

defineAttributeProperties(GlassPlaneScene.prototype);
