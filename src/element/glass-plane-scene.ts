// <glass-plane-scene>: attributes → typed properties, shadow DOM, observers, input, events.
// All GL work is the renderer's; this file only turns the page's state into FrameState.
import { ATTRIBUTES, ATTRIBUTE_BY_NAME, defaultAttributes, propertyToRaw, type AttributeSpec, type SceneAttributes } from './attributes';
import { FlybyController } from './flyby-controller';
import { applyStyle } from './element-style';
import { Renderer, type ReadbackSource } from '../render/renderer';
import { ShaderError } from '../render/gl/program';
import type { FrameReport, FrameState, RenderStats } from '../render/types';
import type { CapturePass, ErrorType, GlassPlaneSceneEventMap } from './types';

const PREFIX = 'glass-plane-scene:';
const MAX_WARNINGS = 200;
const CAPTURE_SOURCES: Record<CapturePass, ReadbackSource> = { reflection: 'reflection', scene: 'scene', final: 'final' };
const DEBUG_KEY = 'KeyF';
const DEFAULT_LABEL = 'A dark glass plane reflecting a cube, with a sphere behind it';

// Lets the module load where HTMLElement does not exist (server-side rendering, Node tests).
const Base = (typeof HTMLElement === 'undefined' ? class {} : HTMLElement) as typeof HTMLElement;

function emptyStats(): RenderStats {
  const zero = { reflection: 0, scene: 0, glass: 0 };
  return {
    frames: 0, programs: 0, sphereSegments: 0, passesRun: { ...zero }, passesSkipped: { ...zero }, drawCalls: 0,
    resources: { buffers: 0, textures: 0, framebuffers: 0, renderbuffers: 0, vertexArrays: 0, programs: 0, shaders: 0, total: 0 },
  };
}

function checksEnabled(): boolean {
  return (globalThis as { __GLASS_PLANE_SCENE_CHECKS__?: unknown }).__GLASS_PLANE_SCENE_CHECKS__ === true;
}

export interface GlassPlaneScene extends SceneAttributes {}

export class GlassPlaneScene extends Base {
  static get observedAttributes(): string[] {
    return [...ATTRIBUTES.map((a) => a.attribute), 'alt'];
  }

  /** Text alternative for assistive technology (like <img alt>); becomes the aria-label. */
  get alt(): string {
    return this.getAttribute('alt') ?? DEFAULT_LABEL;
  }

  set alt(value: string) {
    this.setAttribute('alt', String(value));
  }

  private readonly values: SceneAttributes = defaultAttributes();
  private readonly canvas: HTMLCanvasElement;
  private readonly message: HTMLElement;
  private readonly flyby = new FlybyController();
  private readonly warned = new Set<string>();
  private gl: WebGL2RenderingContext | null = null;
  private renderer: Renderer | null = null;
  private resizeObserver: ResizeObserver | null = null;
  private rafId = 0;
  private lastNow = 0;
  private clockStart = -1;
  private failed = false;
  private readyFired = false;
  private lastState: FrameState | null = null;
  private totals = emptyStats();
  private cameraDirty = false;
  private readonly state: FrameState = {
    width: 1, height: 1, time: 0, spin: 0, cubeDistance: 0, transparency: 0, ior: 1, fresnel: 'exact',
    fov: 60, cameraPosition: [0, 0, 0], yaw: 0, pitch: 0, view: 'final',
    reflectionScale: 0.5, samples: 4, shading: 'phong', tessellation: 'auto',
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
    this.flyby.setPose(this.values.cameraPosition, this.values.cameraRotation[0], this.values.cameraRotation[1]);
  }

  // ---- lifecycle -------------------------------------------------------------------------

  connectedCallback(): void {
    for (const spec of ATTRIBUTES) this.upgradeProperty(spec.property);
    if (!this.hasAttribute('tabindex')) this.tabIndex = 0;
    if (!this.hasAttribute('role')) this.setAttribute('role', 'img');
    if (!this.hasAttribute('aria-label')) this.setAttribute('aria-label', this.alt);
    this.addEventListener('keydown', this.onKeyDown);
    this.addEventListener('keyup', this.onKeyUp);
    this.addEventListener('blur', this.onBlur);
    this.canvas.addEventListener('click', this.onClick);
    this.canvas.addEventListener('mousemove', this.onMouseMove);
    this.canvas.addEventListener('webglcontextlost', this.onContextLost);
    this.canvas.addEventListener('webglcontextrestored', this.onContextRestored);
    this.resizeObserver = new ResizeObserver(this.onResize);
    this.resizeObserver.observe(this);
    this.start();
  }

  disconnectedCallback(): void {
    cancelAnimationFrame(this.rafId);
    this.rafId = 0;
    this.resizeObserver?.disconnect();
    this.resizeObserver = null;
    this.removeEventListener('keydown', this.onKeyDown);
    this.removeEventListener('keyup', this.onKeyUp);
    this.removeEventListener('blur', this.onBlur);
    this.canvas.removeEventListener('click', this.onClick);
    this.canvas.removeEventListener('mousemove', this.onMouseMove);
    this.canvas.removeEventListener('webglcontextlost', this.onContextLost);
    this.canvas.removeEventListener('webglcontextrestored', this.onContextRestored);
    this.flyby.releaseAll();
    this.disposeRenderer();
  }

  attributeChangedCallback(name: string, _old: string | null, raw: string | null): void {
    if (name === 'alt') {
      this.setAttribute('aria-label', raw ?? DEFAULT_LABEL);
      return;
    }
    const spec = ATTRIBUTE_BY_NAME.get(name);
    if (!spec) return;
    const parsed = spec.parse(raw);
    if (parsed.problem) this.warnOnce(spec, raw ?? '', parsed.problem);
    (this.values as unknown as Record<string, unknown>)[spec.property] = parsed.value;
    if (spec.property === 'cameraPosition' || spec.property === 'cameraRotation') {
      const [yaw, pitch] = this.values.cameraRotation;
      this.flyby.setPose(this.values.cameraPosition, yaw, pitch);
    }
    if (spec.property === 'pixelRatio') this.onResize();
    this.requestRender();
  }

  // ---- public API --------------------------------------------------------------------------

  /** Draws a frame soon (on the next animation frame), even when nothing changed. */
  requestRender(): void {
    if (this.rafId === 0 && this.renderer && !this.failed) this.rafId = requestAnimationFrame(this.onFrame);
  }

  /**
   * RGBA8 pixels of the last frame (no argument: exactly what is on screen) or of one pass,
   * at the drawing-buffer size, top row first. Null while nothing can be drawn.
   */
  capture(pass?: CapturePass): ImageData | null {
    if (!this.renderer || this.failed) return null;
    let source: ReadbackSource = 'screen';
    if (pass !== undefined) {
      source = CAPTURE_SOURCES[pass as CapturePass] ?? 'final';
      if (!(pass in CAPTURE_SOURCES)) this.warn(`capture("${String(pass).slice(0, 40)}") is not a pass; capturing "final"`);
    }
    try {
      const px = this.renderer.read(source, this.lastState ?? this.frameState(performance.now()));
      return new ImageData(px.data, px.width, px.height);
    } catch (e) {
      this.fail(e instanceof ShaderError ? 'shader' : 'context-lost', e);
      return null;
    }
  }

  /** Frames, passes run and skipped, draw calls and live GL resources. */
  get stats(): RenderStats {
    if (!this.renderer) return structuredClone(this.totals);
    return this.renderer.stats;
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

  // ---- rendering ---------------------------------------------------------------------------

  private start(): void {
    if (this.renderer || this.failed) return;
    if (!this.gl) {
      // alpha: true so the canvas is RGBA8 like our multisampled targets (a multisample
      // resolve cannot convert formats); every pass writes alpha 1, so it stays opaque.
      const gl = this.canvas.getContext('webgl2', {
        alpha: true, antialias: false, depth: true, stencil: false, premultipliedAlpha: true, preserveDrawingBuffer: false,
      });
      if (!gl) {
        this.fail('webgl2-unavailable', new Error('WebGL2 is not available in this browser, so this scene cannot be shown.'));
        return;
      }
      this.gl = gl;
    }
    if (this.gl.isContextLost()) return;
    try {
      this.renderer = new Renderer(this.gl, { checks: checksEnabled() });
    } catch (e) {
      this.fail(e instanceof ShaderError ? 'shader' : 'context-lost', e);
      return;
    }
    this.resizeCanvas();
    this.requestRender();
  }

  private disposeRenderer(): void {
    if (!this.renderer) return;
    this.totals = this.renderer.stats;
    this.renderer.dispose();
    this.totals.resources = emptyStats().resources;
    this.renderer = null;
  }

  private readonly onFrame = (now: number): void => {
    this.rafId = 0;
    const renderer = this.renderer;
    if (!renderer || this.failed) return;
    const dt = this.lastNow ? (now - this.lastNow) / 1000 : 0;
    this.lastNow = now;
    if (this.flyby.update(dt)) this.cameraMoved();
    const state = this.frameState(now);
    let report: FrameReport;
    try {
      report = renderer.render(state);
    } catch (e) {
      this.fail(e instanceof ShaderError ? 'shader' : 'context-lost', e);
      return;
    }
    this.lastState = { ...state, cameraPosition: [...state.cameraPosition] };
    const detail = structuredClone(report);
    if (!this.readyFired) {
      this.readyFired = true;
      this.dispatchEvent(new CustomEvent('ready', { detail }));
    }
    this.dispatchEvent(new CustomEvent('frame', { detail }));
    if (this.animating()) this.requestRender();
    else {
      this.lastNow = 0;
      if (this.cameraDirty) this.reflectCamera();
    }
  };

  private animating(): boolean {
    return (this.values.spin !== 0 && this.values.time === null) || this.flyby.active;
  }

  private frameState(now: number): FrameState {
    const s = this.state;
    const v = this.values;
    if (this.clockStart < 0) this.clockStart = now;
    s.width = this.canvas.width;
    s.height = this.canvas.height;
    s.time = v.time ?? (now - this.clockStart) / 1000;
    s.spin = v.spin;
    s.cubeDistance = v.cubeDistance;
    s.transparency = v.transparency;
    s.ior = v.ior;
    s.fresnel = v.fresnel;
    s.fov = v.fov;
    s.cameraPosition = this.flyby.pose.position;
    s.yaw = this.flyby.pose.yaw;
    s.pitch = this.flyby.pose.pitch;
    s.view = v.debugView === 'none' ? 'final' : v.debugView;
    s.reflectionScale = v.reflectionScale;
    s.samples = v.samples;
    s.shading = v.shading;
    s.tessellation = v.tessellation;
    return s;
  }

  private readonly onResize = (): void => {
    if (this.resizeCanvas()) {
      // Resizing clears the canvas: draw now rather than show an empty frame.
      cancelAnimationFrame(this.rafId);
      this.rafId = 0;
      if (this.renderer) this.onFrame(performance.now());
    }
  };

  /** Drawing buffer = CSS box × devicePixelRatio, within the GL limits. Returns true if it changed. */
  private resizeCanvas(): boolean {
    const gl = this.gl;
    if (!gl) return false;
    const dpr = this.values.pixelRatio === 'auto' ? window.devicePixelRatio || 1 : this.values.pixelRatio;
    const max = gl.getParameter(gl.MAX_VIEWPORT_DIMS) as Int32Array;
    const limit = Math.min(max[0], max[1], gl.getParameter(gl.MAX_TEXTURE_SIZE) as number, gl.getParameter(gl.MAX_RENDERBUFFER_SIZE) as number);
    const w = Math.max(1, Math.min(limit, Math.round(this.clientWidth * dpr)));
    const h = Math.max(1, Math.min(limit, Math.round(this.clientHeight * dpr)));
    if (w === this.canvas.width && h === this.canvas.height) return false;
    this.canvas.width = w;
    this.canvas.height = h;
    return true;
  }

  // ---- failures ----------------------------------------------------------------------------

  private fail(type: ErrorType, error: unknown): void {
    const message = error instanceof Error ? error.message : String(error);
    this.failed = type !== 'context-lost';
    if (type !== 'context-lost') this.disposeRenderer();
    this.message.textContent = type === 'webgl2-unavailable'
      ? 'WebGL2 is not available here, so the glass scene cannot be shown.'
      : type === 'shader' ? 'The glass scene could not be drawn: a shader failed to compile.' : 'The graphics context was lost; waiting for it to come back.';
    this.message.hidden = false;
    this.canvas.hidden = type === 'webgl2-unavailable';
    // A broken shader is a bug worth a console line (with the annotated source); a missing
    // WebGL2 or a lost context is a state of the machine, reported through the event only.
    if (type === 'shader') console.error(`${PREFIX} ${message}`);
    queueMicrotask(() => this.dispatchEvent(new CustomEvent('error', { detail: { type, message } })));
  }

  private readonly onContextLost = (e: Event): void => {
    e.preventDefault(); // tells the browser we will restore
    cancelAnimationFrame(this.rafId);
    this.rafId = 0;
    this.disposeRenderer();
    this.fail('context-lost', new Error('WebGL context lost'));
  };

  private readonly onContextRestored = (): void => {
    this.message.hidden = true;
    this.canvas.hidden = false;
    this.failed = false;
    this.start();
  };

  // ---- warnings ----------------------------------------------------------------------------

  private warnOnce(spec: AttributeSpec, raw: string, problem: string): void {
    const key = `${spec.attribute}\u0000${raw}`;
    if (this.warned.has(key) || this.warned.size >= MAX_WARNINGS) return;
    this.warned.add(key);
    const shown = raw.length > 40 ? `${raw.slice(0, 40)}…` : raw;
    this.warn(`${spec.attribute}=${JSON.stringify(shown)}: ${problem}`);
    if (this.warned.size === MAX_WARNINGS) this.warn('further attribute warnings are suppressed');
  }

  private warn(text: string): void {
    console.warn(`${PREFIX} ${text}`);
  }

  // ---- input -------------------------------------------------------------------------------

  private readonly onKeyDown = (e: KeyboardEvent): void => {
    if (!this.values.controls || e.altKey || e.ctrlKey || e.metaKey) return;
    if (e.code === DEBUG_KEY && !e.repeat) {
      const views = ['none', 'reflection', 'scene', 'fresnel', 'passes'];
      this.debugView = views[(views.indexOf(this.values.debugView) + 1) % views.length] as SceneAttributes['debugView'];
      return;
    }
    if (this.flyby.keyDown(e.code)) {
      e.preventDefault();
      this.requestRender();
    }
  };

  private readonly onKeyUp = (e: KeyboardEvent): void => {
    if (this.flyby.keyUp(e.code)) e.preventDefault();
  };

  private readonly onBlur = (): void => {
    this.flyby.releaseAll();
  };

  private readonly onClick = (): void => {
    if (!this.values.controls || this.shadowRoot?.pointerLockElement === this.canvas) return;
    this.focus();
    try {
      // Refusal (headless, iframes without allow-pointer-lock) leaves keyboard look working.
      const p = this.canvas.requestPointerLock() as unknown as Promise<void> | undefined;
      p?.catch?.(() => {});
    } catch { /* pointer lock unavailable */ }
  };

  private readonly onMouseMove = (e: MouseEvent): void => {
    if (!this.values.controls || this.shadowRoot?.pointerLockElement !== this.canvas) return;
    if (this.flyby.look(e.movementX, e.movementY)) {
      this.cameraMoved();
      this.cameraDirty = true;
      this.requestRender();
    }
  };

  private cameraMoved(): void {
    this.cameraDirty = true;
    const { position, yaw, pitch } = this.flyby.pose;
    this.dispatchEvent(new CustomEvent('camera-change', { detail: { position: [...position], rotation: [yaw, pitch] } }));
  }

  /** Writes the flown pose back to camera-position / camera-rotation once movement stops. */
  private reflectCamera(): void {
    this.cameraDirty = false;
    const { position, yaw, pitch } = this.flyby.pose;
    const p: [number, number, number] = [position[0], position[1], position[2]];
    this.setAttribute('camera-position', p.join(' '));
    this.setAttribute('camera-rotation', `${yaw} ${pitch}`);
  }

  private upgradeProperty(prop: keyof SceneAttributes): void {
    // A property set before the element was defined shadows the accessor: replay it.
    if (Object.prototype.hasOwnProperty.call(this, prop)) {
      const value = (this as unknown as Record<string, unknown>)[prop];
      delete (this as unknown as Record<string, unknown>)[prop];
      (this as unknown as Record<string, unknown>)[prop] = value;
    }
  }
}

// One accessor per row of the attribute table: the getter returns the parsed value (the
// live pose for the camera), the setter writes the attribute, which parses and re-renders.
for (const spec of ATTRIBUTES) {
  Object.defineProperty(GlassPlaneScene.prototype, spec.property, {
    configurable: true,
    enumerable: true,
    get(this: GlassPlaneScene) {
      const self = this as unknown as { values: SceneAttributes; flyby: FlybyController };
      if (spec.property === 'cameraPosition') return [...self.flyby.pose.position];
      if (spec.property === 'cameraRotation') return [self.flyby.pose.yaw, self.flyby.pose.pitch];
      const v = self.values[spec.property];
      return Array.isArray(v) ? [...v] : v;
    },
    set(this: GlassPlaneScene, value: unknown) {
      const raw = propertyToRaw(spec, value);
      if (raw === null) this.removeAttribute(spec.attribute);
      else this.setAttribute(spec.attribute, raw);
    },
  });
}
