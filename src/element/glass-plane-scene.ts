// <glass-plane-scene>: attributes → typed properties, shadow DOM, observers, input, events.
// All GL work is the renderer's; this file turns the page's state into FrameState, decides
// when a frame is needed, and copies frames from the page's shared context to its canvas.
import { ATTRIBUTES, ATTRIBUTE_BY_NAME, DEBUG_VIEWS, defaultAttributes, type SceneAttributes } from './attributes';
import { defineAttributeProperties, upgradeProperties, type AttributeHost } from './attribute-properties';
import { AttributeWarnings, PREFIX, warn } from './warnings';
import { boundsCenter, rotateScene } from '../scene/group-rotation';
import { applyStyle } from './element-style';
import { readCanvas } from './canvas-readback';
import { SharedContext, type ContextClient, type Presenter } from './shared-context';
import { Renderer, passesFor, type ReadbackSource } from '../render/renderer';
import { SoftwareHost } from './software-host';
import { ShaderError } from '../render/gl/program';
import type { FrameReport, FrameState, RenderStats } from '../render/types';
import type { CapturePass, ErrorType, GlassPlaneSceneEventMap } from './types';
import { SceneSource } from './scene-source';
import { TextureImages } from './texture-images';
import { composeScene, sceneSpins } from './compose-scene';
import { CameraRig } from './camera-rig';
import { FrameLoop } from './frame-loop';
import type { Scene } from '../scene/scene';

const CAPTURE_SOURCES: Record<CapturePass, ReadbackSource> = { reflection: 'reflection', scene: 'scene', final: 'final' };
const DEFAULT_LABEL = 'A dark glass plane reflecting a cube, with a sphere behind it';
const MESSAGES: Record<ErrorType, string> = {
  'webgl2-unavailable': 'WebGL2 is not available here, so the glass scene cannot be shown.',
  shader: 'The glass scene could not be drawn: a shader failed to compile.',
  'context-lost': 'The graphics context was lost; waiting for it to come back.',
  load: 'The glass scene could not be loaded.',
};
/** Largest side of a software frame (the CPU's cost grows with the pixels; 4096 is a 4K canvas's side). */
const SOFTWARE_MAX_SIZE = 4096;

// Lets the module load where HTMLElement does not exist (server-side rendering, Node tests).
const Base = (typeof HTMLElement === 'undefined' ? class {} : HTMLElement) as typeof HTMLElement;

function emptyStats(): RenderStats {
  const zero = { reflection: 0, scene: 0, glass: 0 };
  return {
    frames: 0, programs: 0, sphereSegments: 0, passesRun: { ...zero }, passesSkipped: { ...zero }, drawCalls: 0, triangles: { scene: 0, reflection: 0 },
    resources: { buffers: 0, textures: 0, framebuffers: 0, renderbuffers: 0, vertexArrays: 0, programs: 0, shaders: 0, total: 0 },
  };
}

function checksEnabled(): boolean {
  return (globalThis as { __GLASS_PLANE_SCENE_CHECKS__?: unknown }).__GLASS_PLANE_SCENE_CHECKS__ === true;
}

export interface GlassPlaneScene extends SceneAttributes {}

/**
 * A plane of dark glass that reflects the viewer's side and lets through what is behind it,
 * with Fresnel (SPEC §1–§3); `<glass-object>` and `<glass-light>` children replace the default
 * objects and light (SPEC §9). Every attribute is also a camelCase property.
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
 * @attr {0 | 2 | 4} [samples=4] - MSAA samples of the reflection and scene passes
 * @attr {'phong' | 'gouraud' | 'flat'} [shading="phong"] - per-fragment phong, per-vertex gouraud, or flat
 * @attr {number | 'auto'} [tessellation="auto"] - sphere segments 4..512, or auto (from the sphere's size on screen)
 * @attr {number | 'auto'} [pixel-ratio="auto"] - drawing-buffer pixels per CSS pixel 0.25..4, or auto (devicePixelRatio)
 * @attr {'rgba8' | 'rgba16f'} [reflection-format="rgba8"] - reflection storage (rgba16f: half float, where supported)
 * @attr {string} [glass-center="0 1 0"] - "x y z": centre of the glass rectangle
 * @attr {string} [glass-normal="0 0 1"] - "x y z": normal of the glass; "0 1 0" makes a glass floor
 * @attr {string} [glass-size="8 4"] - "w h": width and height of the glass; "0 0" means no glass
 * @attr {string} [background="0.1 0.1 0.1"] - any CSS colour, or "r g b" in 0..1: the clear colour, also of the reflection
 * @attr {string} [alt="A dark glass plane reflecting a cube, with a sphere behind it"] - text alternative; becomes the aria-label
 * @fires {CustomEvent<FrameReport>} ready - once, after the first frame is on the canvas
 * @fires {CustomEvent<FrameReport>} frame - after every frame drawn
 * @fires {CustomEvent<GlassPlaneSceneErrorDetail>} error - WebGL2 unavailable, a shader failed, the context was lost, or a load failed
 * @fires {CustomEvent<CameraChangeDetail>} camera-change - after a gesture moved the camera, or the page set a camera attribute
 * @csspart canvas - the canvas the scene is drawn on
 * @csspart message - the message shown when the scene cannot be drawn
 */
export class GlassPlaneScene extends Base implements ContextClient, AttributeHost {
  static get observedAttributes(): string[] {
    return [...ATTRIBUTES.map((a) => a.attribute), 'alt'];
  }

  private readonly values: SceneAttributes = defaultAttributes();
  private readonly canvas: HTMLCanvasElement;
  private readonly message: HTMLElement;
  /** The camera, its controls, the trackball and the course camera. */
  private readonly rig: CameraRig;
  private readonly warnings = new AttributeWarnings();
  /** The light-DOM children (<glass-object>, <glass-light>) as parts of the scene. */
  private readonly source = new SceneSource({ element: this, partsChanged: () => this.sceneChanged() });
  /** Image textures the scene names, decoded once per URL per page, given to the renderer. */
  private readonly images = new TextureImages({ sink: () => this.glRenderer ?? this.software, loaded: () => this.requestRender() });
  /** The scene value, built on demand and kept until an attribute or a child changes. */
  private sceneValue: Scene | null = null;
  private shared: SharedContext | null = null;
  private output: Presenter | null = null;
  private glRenderer: Renderer | null = null;
  /** The software renderer (renderer="software", or "auto" without WebGL2), once loaded. */
  private software: SoftwareHost | null = null;
  /** Counts software starts, so a start overtaken by a change or a disconnection is dropped. */
  private softwareGeneration = 0;
  private softwareStarting = false;
  /** A software frame is drawing; another is wanted when it is back. */
  private softwareBusy = false;
  /** How software frames reach the canvas: a 2D context, or (after WebGL used it) a bitmap renderer. */
  private softwareOut: CanvasRenderingContext2D | ImageBitmapRenderingContext | null = null;
  /** When frames are drawn: on demand, in view, with the page shown. */
  private readonly loop: FrameLoop;
  private clockStart = -1;
  private failed: ErrorType | null = null;
  /** The shader error last reported: the same one again (the same broken variant) is not news. */
  private reportedShaderError: unknown = null;
  private readyFired = false;
  /** The state of the last frame drawn (what capture(pass) draws a pass of); filled in place. */
  private lastState: FrameState | null = null;
  private readonly lastPosition: [number, number, number] = [0, 0, 0];
  private totals = emptyStats();
  private frames = 0;
  private readonly state: FrameState = {
    width: 1, height: 1, time: 0, spin: 0, cubeDistance: 0, transparency: 0, ior: 1, fresnel: 'exact',
    fov: 60, cameraPosition: [0, 0, 0], yaw: 0, pitch: 0, view: 'final',
    reflectionScale: 1, samples: 4, shading: 'phong', tessellation: 'auto', reflectionFormat: 'rgba8',
    projection: 'perspective', target: null,
  };

  constructor() {
    super();
    const root = this.attachShadow({ mode: 'open' });
    applyStyle(root);
    this.canvas = document.createElement('canvas');
    this.canvas.setAttribute('part', 'canvas');
    this.message = document.createElement('div');
    this.message.setAttribute('part', 'message');
    this.message.setAttribute('role', 'alert');
    this.message.hidden = true;
    root.append(this.canvas, this.message);
    this.rig = new CameraRig({
      element: this, canvas: this.canvas, values: this.values,
      requestRender: () => this.requestRender(),
      poseChanged: () => { this.sceneValue = null; },
      flybyMoved: () => { this.loop.dirty = true; },
      objectsCenter: () => boundsCenter(this.scene.objects),
      cycleDebugView: () => {
        this.debugView = DEBUG_VIEWS[(DEBUG_VIEWS.indexOf(this.values.debugView) + 1) % DEBUG_VIEWS.length];
      },
    });
    this.loop = new FrameLoop({
      element: this,
      canDraw: () => (this.glRenderer !== null || this.software !== null) && !this.failed,
      animating: () => this.animating(),
      frame: (now) => this.onFrame(now),
      paused: () => this.rig.paused(),
      idle: () => this.rig.idle(),
      resize: () => this.resizeCanvas(),
      motionPreferenceChanged: () => {
        this.sceneValue = null;
        this.requestRender();
      },
    });
  }

  // ---- lifecycle -------------------------------------------------------------------------

  connectedCallback(): void {
    upgradeProperties(this);
    if (!this.hasAttribute('tabindex')) this.tabIndex = 0;
    if (!this.hasAttribute('role')) this.setAttribute('role', 'img');
    if (!this.hasAttribute('aria-label')) this.setAttribute('aria-label', this.alt);
    this.rig.hostConnected();
    this.loop.hostConnected();
    this.source.hostConnected();
    this.start();
  }

  disconnectedCallback(): void {
    this.loop.hostDisconnected();
    this.source.hostDisconnected();
    this.rig.hostDisconnected();
    this.disposeRenderer();
    this.disposeSoftware();
    this.shared?.release(this);
    this.shared = null;
  }

  attributeChangedCallback(name: string, _old: string | null, raw: string | null): void {
    if (name === 'alt') {
      this.setAttribute('aria-label', raw ?? DEFAULT_LABEL);
      return;
    }
    const spec = ATTRIBUTE_BY_NAME.get(name);
    if (!spec) return;
    const parsed = spec.parse(raw);
    if (parsed.problem) this.warnings.report(spec, raw ?? '', parsed.problem);
    (this.values as unknown as Record<string, unknown>)[spec.property] = parsed.value;
    this.sceneValue = null;
    // The pose written back at rest is the one just drawn: nothing to move, nothing to draw.
    if (this.rig.writingBack) return;
    const p = spec.property;
    if (p === 'cameraPosition' || p === 'cameraRotation' || p === 'cameraTarget') this.rig.cameraAttributeChanged();
    if (p === 'controls') this.rig.controlsChanged();
    if (p === 'renderer' && this.isConnected) this.switchRenderer();
    if (p === 'cameraSrc') this.rig.cameraSource.srcChanged();
    // Resize only: drawing here, mid-way through a script's batch of attribute changes, would
    // show a frame with half of them applied (the next animation frame comes before paint).
    if (p === 'pixelRatio') this.resizeCanvas();
    // A shader failure is not final: the change may select a variant that compiles. The message
    // stays up until a frame is drawn.
    if (this.failed === 'shader') this.failed = null;
    this.requestRender();
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
   * The scene as one value (SPEC §9): the glass and background from the attributes, the
   * children's objects and lights, or SPEC §3's defaults where there are none. Read-only; a
   * new value after every change (the same object until then).
   */
  get scene(): Scene {
    return (this.sceneValue ??= rotateScene(
      composeScene({ ...this.values, spin: this.effectiveSpin() }, this.source.current()),
      this.rig.pointer.objectRotation, this.rig.pointer.lightRotation,
    ));
  }

  /**
   * The trackball's rotation of the objects about the centre of their bounds, a unit quaternion
   * [x, y, z, w] (identity [0, 0, 0, 1]). Never written to an attribute; settable (normalised;
   * a value that is not four finite numbers, or zero, is ignored with a warning).
   */
  get objectRotation(): [number, number, number, number] {
    const q = this.rig.pointer.objectRotation;
    return [q[0], q[1], q[2], q[3]];
  }

  set objectRotation(value: ArrayLike<number>) {
    const q = Array.from(value ?? [], Number);
    const len = Math.hypot(...q);
    if (q.length !== 4 || !Number.isFinite(len) || len === 0) {
      warn(`objectRotation: expected a quaternion [x, y, z, w], ignoring ${JSON.stringify(value)?.slice(0, 60)}`);
      return;
    }
    const r = this.rig.pointer.objectRotation;
    for (let i = 0; i < 4; i++) r[i] = q[i] / len;
    this.sceneValue = null;
    this.requestRender();
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
    if ((!this.glRenderer && !this.software) || this.failed) return null;
    if (pass === undefined) return this.frames > 0 ? readCanvas(this.canvas) : null;
    const source: ReadbackSource = CAPTURE_SOURCES[pass as CapturePass] ?? 'final';
    if (!(pass in CAPTURE_SOURCES)) warn(`capture("${String(pass).slice(0, 40)}") is not a pass; capturing "final"`);
    if (this.software) {
      // Drawn now, on this thread, from the last frame's state (capture is synchronous).
      const state: FrameState = { ...(this.lastState ?? this.frameState(performance.now())), view: source as FrameState['view'] };
      const pixels = this.software.renderNow(state, this.scene) as Uint8ClampedArray<ArrayBuffer>;
      return new ImageData(pixels, state.width, state.height);
    }
    try {
      this.shared!.reserve(this.canvas.width, this.canvas.height);
      const px = this.glRenderer!.read(source, this.lastState ?? this.frameState(performance.now()), this.scene);
      return new ImageData(px.data, px.width, px.height);
    } catch (e) {
      this.handleRenderError(e);
      return null;
    }
  }

  /** Frames, passes run and skipped, draw calls, compiled programs and live GL resources. */
  get stats(): RenderStats {
    const s = this.glRenderer ? this.glRenderer.stats : structuredClone(this.totals);
    s.frames = this.frames;
    s.renderer = this.glRenderer ? 'webgl' : this.software ? 'software' : null;
    if (this.software) s.thread = this.software.thread;
    return s;
  }

  // ---- typed events ------------------------------------------------------------------------

  override addEventListener<K extends keyof GlassPlaneSceneEventMap>(
    type: K, listener: (this: GlassPlaneScene, ev: GlassPlaneSceneEventMap[K]) => unknown, options?: boolean | AddEventListenerOptions): void;
  override addEventListener(type: string, listener: EventListenerOrEventListenerObject, options?: boolean | AddEventListenerOptions): void;
  override addEventListener(type: string, listener: EventListenerOrEventListenerObject, options?: boolean | AddEventListenerOptions): void {
    super.addEventListener(type, listener, options);
  }

  override removeEventListener<K extends keyof GlassPlaneSceneEventMap>(
    type: K, listener: (this: GlassPlaneScene, ev: GlassPlaneSceneEventMap[K]) => unknown, options?: boolean | EventListenerOptions): void;
  override removeEventListener(type: string, listener: EventListenerOrEventListenerObject, options?: boolean | EventListenerOptions): void;
  override removeEventListener(type: string, listener: EventListenerOrEventListenerObject, options?: boolean | EventListenerOptions): void {
    super.removeEventListener(type, listener, options);
  }

  /** @internal AttributeHost: the parsed value, or the live pose for the flown camera. */
  readAttributeValue(property: keyof SceneAttributes): unknown {
    const pose = this.rig.flyby.pose;
    if (property === 'cameraPosition') return pose.position;
    if (property === 'cameraRotation') return [pose.yaw, pose.pitch];
    return this.values[property];
  }

  // ---- the shared context ------------------------------------------------------------------

  /** @internal ContextClient: every GL object died with the context. */
  contextLost(): void {
    this.loop.cancel();
    this.disposeRenderer();
    this.fail('context-lost', new Error('WebGL context lost'));
  }

  /** @internal ContextClient: rebuild on the restored context and draw. */
  contextRestored(): void {
    if (this.failed !== 'context-lost') return;
    this.failed = null;
    this.message.hidden = true;
    this.canvas.hidden = false;
    this.start();
  }

  private start(): void {
    if (this.glRenderer || this.software || this.softwareStarting || (this.failed && this.failed !== 'context-lost')) return;
    const choice = this.values.renderer;
    if (choice === 'software') return this.startSoftware();
    this.shared ??= SharedContext.acquire(this);
    if (!this.shared) {
      // auto: no WebGL2 here, so the CPU draws the scene; nothing to report.
      if (choice === 'auto') return this.startSoftware();
      this.fail('webgl2-unavailable', new Error('WebGL2 is not available in this browser, so this scene cannot be shown.'));
      return;
    }
    if (this.shared.lost || this.shared.gl.isContextLost()) return;
    this.output ??= this.shared.presenterFor(this.canvas);
    try {
      this.glRenderer = new Renderer(this.shared.gl, { checks: checksEnabled() });
      this.images.feed(this.glRenderer);
    } catch (e) {
      this.handleRenderError(e);
      return;
    }
    this.resizeCanvas();
    this.requestRender();
  }

  /** The software renderer, loaded as a chunk of its own; `error` only if it cannot start either. */
  private startSoftware(): void {
    const generation = ++this.softwareGeneration;
    this.softwareStarting = true;
    SoftwareHost.create().then((host) => {
      this.softwareStarting = false;
      if (generation !== this.softwareGeneration || !this.isConnected) return host.dispose();
      this.software = host;
      this.images.feed(host);
      this.softwareOut = this.canvas.getContext('2d', { alpha: false }) ?? this.canvas.getContext('bitmaprenderer');
      this.resizeCanvas();
      this.requestRender();
    }, (e: unknown) => {
      this.softwareStarting = false;
      if (generation !== this.softwareGeneration) return;
      const why = e instanceof Error ? e.message : String(e);
      this.fail('webgl2-unavailable', new Error(`Neither WebGL2 nor the software renderer is available here (${why}), so this scene cannot be shown.`));
    });
  }

  private disposeSoftware(): void {
    this.softwareGeneration++;
    this.softwareStarting = false;
    this.softwareBusy = false;
    this.software?.dispose();
    this.software = null;
  }

  /** `renderer` changed: let go of the renderer in use and start the one now asked for. */
  private switchRenderer(): void {
    const wantSoftware = this.values.renderer === 'software' || (this.values.renderer === 'auto' && !this.glRenderer && !this.shared);
    if ((wantSoftware && (this.software || this.softwareStarting)) || (!wantSoftware && this.glRenderer)) return;
    this.loop.cancel();
    this.disposeRenderer();
    this.disposeSoftware();
    if (this.failed !== 'context-lost') {
      this.failed = null;
      this.message.hidden = true;
      this.canvas.hidden = false;
    }
    this.start();
  }

  private disposeRenderer(): void {
    if (!this.glRenderer) return;
    this.totals = this.glRenderer.stats;
    this.glRenderer.dispose();
    this.totals.resources = emptyStats().resources;
    this.glRenderer = null;
  }

  // ---- frames ------------------------------------------------------------------------------

  private onFrame(now: number): void {
    this.rig.step();
    this.draw(now);
  }

  private draw(now: number): void {
    if (this.software) return this.drawSoftware(now);
    const renderer = this.glRenderer!;
    this.loop.dirty = false;
    const { width, height } = this.canvas;
    if (this.clientWidth === 0 || this.clientHeight === 0) return; // nothing to show
    const state = this.frameState(now);
    let report: FrameReport;
    try {
      this.shared!.reserve(width, height);
      const scene = this.scene;
      this.images.sync(scene);
      report = renderer.render(state, scene);
      this.output!.present(width, height);
    } catch (e) {
      this.handleRenderError(e);
      return;
    }
    this.frameDrawn(state, report.time, report.width, report.height, report.drawCalls, report.passes);
  }

  /**
   * A software frame: drawn in the worker while the page goes on; one at a time (a change while
   * it draws is drawn next). The pixels reach the canvas in one piece when the frame is complete.
   */
  private drawSoftware(now: number): void {
    const host = this.software!;
    if (this.softwareBusy) return; // dirty stays set: drawn when this one is back
    this.loop.dirty = false;
    const { width, height } = this.canvas;
    if (this.clientWidth === 0 || this.clientHeight === 0) return;
    const state = this.frameState(now);
    const scene = this.scene;
    this.images.sync(scene);
    const generation = this.softwareGeneration;
    this.softwareBusy = true;
    const frozen: FrameState = { ...state };
    void host.render(frozen, scene).then((pixels) => {
      if (generation !== this.softwareGeneration) return;
      this.softwareBusy = false;
      if (this.canvas.width !== width || this.canvas.height !== height) {
        this.requestRender(); // resized while it drew: draw again at the new size
        return;
      }
      const image = new ImageData(pixels as Uint8ClampedArray<ArrayBuffer>, width, height);
      const out = this.softwareOut;
      const glassSkip = state.view === 'final' && !scene.glass ? 'no glass' : undefined;
      const done = () => {
        if (generation !== this.softwareGeneration) return;
        this.frameDrawn(frozen, frozen.time, width, height, 0, passesFor(frozen.view, glassSkip));
        this.loop.resume();
      };
      if (out && 'putImageData' in out) {
        out.putImageData(image, 0, 0);
        done();
      } else if (out) {
        // The canvas held WebGL's frames (a bitmap renderer): the frame counts once it is shown.
        void createImageBitmap(image).then((b) => {
          if (generation === this.softwareGeneration) (out as ImageBitmapRenderingContext).transferFromImageBitmap(b);
          done();
        });
      } else done();
    });
  }

  /** After a frame is on the canvas: counts, the last state (for capture), `ready` and `frame`. */
  private frameDrawn(state: FrameState, time: number, width: number, height: number, drawCalls: number, passes: FrameReport['passes']): void {
    this.frames++;
    if (!this.message.hidden) this.message.hidden = true; // drawn again after a shader failure
    this.reportedShaderError = null;
    const last = (this.lastState ??= { ...state });
    Object.assign(last, state);
    this.lastPosition[0] = state.cameraPosition[0];
    this.lastPosition[1] = state.cameraPosition[1];
    this.lastPosition[2] = state.cameraPosition[2];
    last.cameraPosition = this.lastPosition;
    // One small frozen object per frame (the event is one anyway), its passes shared frozen
    // records: listeners may keep it, and nothing later changes it. A deep copy per frame
    // (structuredClone) is what it replaces.
    const detail: FrameReport = Object.freeze({ frame: this.frames, time, width, height, drawCalls, passes });
    // `ready` waits for the models of the children: loaded or failed (SPEC §2).
    if (!this.readyFired && !this.source.loading && !this.rig.loading) {
      this.readyFired = true;
      this.dispatchEvent(new CustomEvent('ready', { detail }));
    }
    this.dispatchEvent(new CustomEvent('frame', { detail }));
  }

  /** Spin counts unless reduced motion is asked for and the page did not set `spin` itself. */
  private effectiveSpin(): number {
    return this.loop.reducedMotion && !this.hasAttribute('spin') ? 0 : this.values.spin;
  }

  /** Frames keep coming while the clock turns something in the scene, or the camera moves. */
  private animating(): boolean {
    return (this.values.time === null && sceneSpins(this.scene)) || this.rig.moving;
  }

  private frameState(now: number): FrameState {
    const s = this.state;
    const v = this.values;
    if (this.clockStart < 0) this.clockStart = now;
    s.width = this.canvas.width;
    s.height = this.canvas.height;
    s.time = v.time ?? (now - this.clockStart) / 1000;
    s.spin = this.effectiveSpin();
    s.cubeDistance = v.cubeDistance;
    s.transparency = v.transparency;
    s.ior = v.ior;
    s.fresnel = v.fresnel;
    s.view = v.debugView === 'none' ? 'final' : v.debugView;
    s.reflectionScale = v.reflectionScale;
    s.samples = v.samples;
    s.shading = v.shading;
    s.tessellation = v.tessellation;
    s.reflectionFormat = v.reflectionFormat;
    this.rig.aim(s, this.scene);
    return s;
  }

  // ---- canvas and scene ----------------------------------------------------------------------

  /** Drawing buffer = CSS box × pixel ratio, within the GL limits. Returns true if it changed. */
  private resizeCanvas(): boolean {
    if (!this.shared && !this.software) return false;
    const ratio = this.values.pixelRatio === 'auto' ? window.devicePixelRatio || 1 : this.values.pixelRatio;
    const limit = this.shared ? this.shared.maxSize : SOFTWARE_MAX_SIZE;
    const w = Math.max(1, Math.min(limit, Math.round(this.clientWidth * ratio)));
    const h = Math.max(1, Math.min(limit, Math.round(this.clientHeight * ratio)));
    if (w === this.canvas.width && h === this.canvas.height) return false;
    this.canvas.width = w;
    this.canvas.height = h;
    return true;
  }

  /** A child was added, removed, reordered, changed, upgraded, or its model arrived. */
  private sceneChanged(): void {
    this.sceneValue = null;
    this.requestRender();
  }

  // ---- failures ----------------------------------------------------------------------------

  private handleRenderError(e: unknown): void {
    if (e instanceof ShaderError) this.fail('shader', e);
    else if (this.shared?.gl.isContextLost()) this.contextLost();
    else throw e;
  }

  private fail(type: ErrorType, error: unknown): void {
    const message = error instanceof Error ? error.message : String(error);
    this.failed = type;
    // The renderer stays after a shader failure: everything else in it works, and its program
    // cache remembers the broken variant, so drawing the same state again fails without compiling.
    if (type !== 'context-lost' && type !== 'shader') this.disposeRenderer();
    this.message.textContent = MESSAGES[type];
    this.message.hidden = false;
    this.canvas.hidden = type === 'webgl2-unavailable';
    if (type === 'shader') {
      if (error === this.reportedShaderError) return;
      this.reportedShaderError = error;
    }
    // A broken shader is a bug worth a console line (with the annotated source); a missing
    // WebGL2 or a lost context is a state of the machine, reported through the event only.
    if (type === 'shader') console.error(message.startsWith(PREFIX) ? message : `${PREFIX} ${message}`);
    queueMicrotask(() => this.dispatchEvent(new CustomEvent('error', { detail: { type, message } })));
  }
}

defineAttributeProperties(GlassPlaneScene.prototype);
