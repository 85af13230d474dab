// THE attribute table: name, type, default, range and fallback of every attribute (docs/element.md#attribute-table).
// Parsing, property reflection, README and fuzz tests all read it; nothing here throws.
import { FRESNEL_MODELS, type FresnelModel } from '../math/fresnel';
import { COLOR_SPACES, type ColorSpace } from '../math/srgb';
import type { ToneMapping } from '../math/tone-map';
import { clampPitch, wrapYaw, type Projection } from '../math/camera';
import type { RoughnessQuality } from '../frame/rough-glass';
import { browserCssColor, parseCssColor } from './css-color';
import { MAX_REFINEMENT } from '../frame/refinement';

/** `refine`'s default (docs/refinement.md#the-attribute), from bench/refine.md: 10 frames give 52.7 dB, 82 give 54.3 in 8× the time. */
export const REFINE_DEFAULT = 10;

export const DEBUG_VIEWS = ['none', 'reflection', 'scene', 'fresnel', 'passes'] as const;
export type DebugView = (typeof DEBUG_VIEWS)[number];

export const SHADINGS = ['phong', 'gouraud', 'flat'] as const;
export type Shading = (typeof SHADINGS)[number];
export const SAMPLE_COUNTS = [0, 2, 4] as const;
export const PROJECTIONS: readonly Projection[] = ['perspective', 'orthographic'];

export type Vec3Tuple = [number, number, number];

export const RENDERERS = ['auto', 'webgl', 'software'] as const;
/** docs/element.md#attribute-table: `auto` = WebGL2 where it is available, else the software renderer. */
export type RendererChoice = (typeof RENDERERS)[number];

export const CONTROLS_MODES = ['flyby', 'orbit', 'trackball'] as const;
/** Which input the element listens to (docs/interaction.md#controls); the bare `controls` attribute means flyby. */
export type ControlsMode = (typeof CONTROLS_MODES)[number];
export type YawPitch = [number, number];

/** Every attribute's parsed value, by property name. */
export interface SceneAttributes {
  transparency: number;
  cubeDistance: number;
  ior: number;
  fresnel: FresnelModel;
  cameraPosition: Vec3Tuple;
  cameraRotation: YawPitch;
  fov: number;
  /** Perspective, or orthographic sized at the target or glass centre (docs/interaction.md#orthographic-size). */
  projection: Projection;
  /** The input mode, or null without the attribute (no input). */
  controls: ControlsMode | null;
  /** Which renderer draws: WebGL2 where it works else the CPU (auto), or one of them. */
  renderer: RendererChoice;
  /** The point the camera looks at (overriding camera-rotation) and orbit turns about, or null. */
  cameraTarget: Vec3Tuple | null;
  /** URL of a course camera file (docs/course-files.md#camera-cfg); while its camera is in force it is the view. */
  cameraSrc: string | null;
  spin: number;
  /** Fixed scene clock in seconds, or null for the live clock. */
  time: number | null;
  debugView: DebugView;
  /** Reflection framebuffer size ÷ drawing-buffer size. */
  reflectionScale: number;
  /** MSAA samples for the reflection and scene passes: 0, 2 or 4 (software: 2 and 4 as 2×2 per pixel). */
  samples: number;
  /** Frames a still view draws to converge (docs/refinement.md): 0 off; else moving frames draw with one sample. */
  refine: number;
  shading: Shading;
  /** Sphere segments 4..512, or 'auto' (from the sphere's size on screen). */
  tessellation: number | 'auto';
  /** Drawing buffer ÷ CSS pixels, or 'auto' (devicePixelRatio). */
  pixelRatio: number | 'auto';
  /** Storage of the reflection framebuffer. */
  reflectionFormat: 'rgba8' | 'rgba16f';
  /** Linear light with sRGB in and out, or values used as stored (docs/colour.md#srgb). */
  colorSpace: ColorSpace;
  /**
   * The curve that brings light to the screen (docs/pbr.md#tone-mapping): `auto` is `neutral` for a scene with a glTF
   * material, else `none` (today's frames exactly).
   */
  toneMapping: ToneMapping | 'auto';
  /** A factor on the frame's light before tone mapping (docs/pbr.md#tone-mapping). */
  exposure: number;
  /**
   * The light from all around that glTF materials are lit by (docs/pbr.md#the-environment): the studio, none, or the URL of an
   * equirectangular image (docs/pbr.md#an-image: Radiance .hdr, PNG or JPEG).
   */
  environment: 'neutral' | 'none' | (string & {});
  /** A factor on the environment's light. */
  environmentIntensity: number;
  /** The glass's roughness, 0..1 (docs/rough-glass.md#roughness): 0 polished. */
  roughness: number;
  /** How many neighbours rough glass gathers per pixel (frame/rough-glass.ts). */
  roughnessQuality: RoughnessQuality;
  /** Centre of the glass rectangle. */
  glassCenter: Vec3Tuple;
  /** Unit normal of the glass. */
  glassNormal: Vec3Tuple;
  /** Width and height of the glass; a zero side means no glass. */
  glassSize: [number, number];
  /** Clear colour (also of the reflection), RGB in 0..1. */
  background: Vec3Tuple;
  /** URL of an image shown until the first frame with the content is drawn (docs/element.md#loading-a-person-can-see). */
  poster: string | null;
}

export type AttributeName = keyof SceneAttributes;

/** The outcome of parsing one raw value: the value to use, and a reason when it is a fallback. */
export interface Parsed<T> {
  value: T;
  problem?: string;
}

export interface AttributeSpec<K extends AttributeName = AttributeName> {
  property: K;
  attribute: string;
  default: SceneAttributes[K];
  parse(raw: string | null): Parsed<SceneAttributes[K]>;
  format(value: SceneAttributes[K]): string | null;
}

/**
 * Default view: the glass at grazing incidence (it passes 0.2 in front of the plane, where the
 * exact Fresnel term climbs towards 1), the cube's reflection standing beside the cube, the
 * whole sphere through the glass. From the first design's 2.5 the reflection can only be seen at
 * θ ≤ 72° (F ≤ 0.19): hence also the default cube-distance of 0.75 (docs/element.md#the-default-view).
 */
export const DEFAULT_CAMERA_POSITION: Vec3Tuple = [3.6, 2.4, 0.2];
export const DEFAULT_CAMERA_ROTATION: YawPitch = [-169, -23.6];
export const DEFAULT_CUBE_DISTANCE = 0.75;

/**
 * tone-mapping's words: `auto` and math/tone-map.ts's TONE_MAPPINGS, written out so that the core does not take that module
 * (the CPU renderers' curves) with its list (element-attributes.test.ts holds the two equal).
 */
export const TONE_MAPPING_WORDS: readonly (ToneMapping | 'auto')[] = ['auto', 'neutral', 'aces', 'none'];

const num = (s: string) => (/^\s*$/.test(s) ? NaN : Number(s));

/** A number in [min, max] or the keyword 'auto'; `integer` rounds. */
function autoOrNumberSpec<K extends AttributeName>(
  property: K, attribute: string, min: number, max: number, integer: boolean,
): AttributeSpec<K> {
  const def = 'auto' as SceneAttributes[K];
  return {
    property, attribute, default: def,
    parse(raw) {
      if (raw === null || raw.trim().toLowerCase() === 'auto') return { value: def };
      let x = num(raw);
      if (Number.isNaN(x)) return { value: def, problem: `expected a number or auto, using auto` };
      if (integer) x = Math.round(x);
      if (x < min) return { value: min as SceneAttributes[K], problem: `below ${min}, clamped` };
      if (x > max) return { value: max as SceneAttributes[K], problem: `above ${max}, clamped` };
      return { value: x as SceneAttributes[K] };
    },
    format: (v) => String(v),
  };
}

function numberSpec<K extends AttributeName>(
  property: K, attribute: string, def: number, min: number, max: number,
): AttributeSpec<K> {
  return {
    property, attribute, default: def as SceneAttributes[K],
    parse(raw) {
      if (raw === null) return { value: def as SceneAttributes[K] };
      const x = num(raw);
      if (Number.isNaN(x)) return { value: def as SceneAttributes[K], problem: `not a number, using ${def}` };
      if (x < min) return { value: min as SceneAttributes[K], problem: `below ${min}, clamped` };
      if (x > max) return { value: max as SceneAttributes[K], problem: `above ${max}, clamped` };
      return { value: x as SceneAttributes[K] };
    },
    format: (v) => String(v),
  };
}

/**
 * Finite numbers only: ±Infinity and NaN fall back to the default; magnitudes beyond `limit`
 * clamp to it (a value that is finite in float64 may overflow float32 on its way to the GPU).
 */
function finiteSpec<K extends AttributeName>(
  property: K, attribute: string, def: number, limit = Number.MAX_VALUE,
): AttributeSpec<K> {
  return {
    property, attribute, default: def as SceneAttributes[K],
    parse(raw) {
      if (raw === null) return { value: def as SceneAttributes[K] };
      const x = num(raw);
      if (!Number.isFinite(x)) return { value: def as SceneAttributes[K], problem: `not a finite number, using ${def}` };
      if (Math.abs(x) > limit) return { value: Math.sign(x) * limit as SceneAttributes[K], problem: `beyond ±${limit}, clamped` };
      return { value: x as SceneAttributes[K] };
    },
    format: (v) => String(v),
  };
}

function keywordSpec<K extends AttributeName>(
  property: K, attribute: string, words: readonly string[],
): AttributeSpec<K> {
  const def = words[0] as SceneAttributes[K];
  return {
    property, attribute, default: def,
    parse(raw) {
      if (raw === null) return { value: def };
      const w = raw.trim().toLowerCase();
      if (words.includes(w)) return { value: w as SceneAttributes[K] };
      return { value: def, problem: `expected one of ${words.join(', ')}; using ${String(def)}` };
    },
    format: (v) => String(v),
  };
}

function tupleParse(raw: string, n: number): number[] | undefined {
  const parts = raw.trim().split(/[\s,]+/);
  if (parts.length !== n) return undefined;
  const xs = parts.map(num);
  return xs.every(Number.isFinite) ? xs : undefined;
}

// Ranges of the camera position: beyond ±1e7 float64 composition still holds, but nothing
// useful is visible; the bound keeps every derived uniform finite.
const MAX_COORD = 1e7;

/** A tuple of `n` finite numbers; `check` may reject or adjust it (returning a problem). */
function tupleSpec<K extends AttributeName>(
  property: K, attribute: string, def: number[], form: string,
  check: (xs: number[]) => Parsed<number[]> = (xs) => ({ value: xs }),
): AttributeSpec<K> {
  const fallback = () => [...def] as SceneAttributes[K];
  return {
    property, attribute, default: def as SceneAttributes[K],
    parse(raw) {
      if (raw === null) return { value: fallback() };
      const xs = tupleParse(raw, def.length);
      if (!xs) return { value: fallback(), problem: `expected ${form}, using "${def.join(' ')}"` };
      const c = check(xs);
      return { value: c.value as SceneAttributes[K], problem: c.problem };
    },
    format: (v) => (v as number[]).join(' '),
  };
}

const clampCoords = (xs: number[]): Parsed<number[]> => {
  const c = xs.map((x) => Math.max(-MAX_COORD, Math.min(MAX_COORD, x)));
  return c.some((x, i) => x !== xs[i]) ? { value: c, problem: `coordinates clamped to ±${MAX_COORD}` } : { value: c };
};

/** "rgb(25.5 25.5 25.5)": exactly the 0.1 grey of docs/default-scene.md#background. */
export const DEFAULT_BACKGROUND = 'rgb(25.5 25.5 25.5)';

export const ATTRIBUTES: readonly AttributeSpec[] = [
  numberSpec('transparency', 'transparency', 0.5, 0, 1),
  finiteSpec('cubeDistance', 'cube-distance', DEFAULT_CUBE_DISTANCE, MAX_COORD),
  numberSpec('ior', 'ior', 1.5, 1, 10),
  keywordSpec('fresnel', 'fresnel', FRESNEL_MODELS),
  tupleSpec('cameraPosition', 'camera-position', DEFAULT_CAMERA_POSITION, '"x y z"', clampCoords),
  {
    property: 'cameraRotation', attribute: 'camera-rotation', default: DEFAULT_CAMERA_ROTATION,
    parse(raw) {
      if (raw === null) return { value: [...DEFAULT_CAMERA_ROTATION] };
      const xs = tupleParse(raw, 2);
      if (!xs) return { value: [...DEFAULT_CAMERA_ROTATION], problem: 'expected "yaw pitch", using the default view' };
      const yaw = wrapYaw(xs[0]);
      const pitch = clampPitch(xs[1]);
      return pitch !== xs[1] ? { value: [yaw, pitch], problem: 'pitch clamped to ±89.9' } : { value: [yaw, pitch] };
    },
    format: (v) => v.join(' '),
  } satisfies AttributeSpec<'cameraRotation'>,
  numberSpec('fov', 'fov', 60, 1, 179),
  keywordSpec('projection', 'projection', PROJECTIONS),
  {
    property: 'controls', attribute: 'controls', default: null,
    parse(raw) {
      if (raw === null) return { value: null };
      const w = raw.trim().toLowerCase();
      // The bare attribute, and the forms a boolean attribute takes in HTML and XHTML.
      if (w === '' || w === 'true' || w === 'controls') return { value: 'flyby' };
      if ((CONTROLS_MODES as readonly string[]).includes(w)) return { value: w as ControlsMode };
      return { value: 'flyby', problem: `expected one of ${CONTROLS_MODES.join(', ')}; using flyby` };
    },
    format: (v) => v ?? null,
  } satisfies AttributeSpec<'controls'>,
  keywordSpec('renderer', 'renderer', RENDERERS),
  {
    property: 'cameraTarget', attribute: 'camera-target', default: null,
    parse(raw) {
      if (raw === null) return { value: null };
      const xs = tupleParse(raw, 3);
      if (!xs) return { value: null, problem: 'expected "x y z", using no target' };
      const c = clampCoords(xs);
      return { value: c.value as Vec3Tuple, problem: c.problem };
    },
    format: (v) => (v ? v.join(' ') : null),
  } satisfies AttributeSpec<'cameraTarget'>,
  {
    property: 'cameraSrc', attribute: 'camera-src', default: null,
    parse: (raw) => ({ value: raw === null || raw.trim() === '' ? null : raw.trim() }),
    format: (v) => v,
  } satisfies AttributeSpec<'cameraSrc'>,
  {
    property: 'poster', attribute: 'poster', default: null,
    parse: (raw) => ({ value: raw === null || raw.trim() === '' ? null : raw.trim() }),
    format: (v) => v,
  } satisfies AttributeSpec<'poster'>,
  finiteSpec('spin', 'spin', 0.8),
  {
    property: 'time', attribute: 'time', default: null,
    parse(raw) {
      if (raw === null) return { value: null };
      const x = num(raw);
      if (!Number.isFinite(x)) return { value: null, problem: 'not a finite number, using the live clock' };
      return { value: x };
    },
    format: (v) => (v === null ? null : String(v)),
  } satisfies AttributeSpec<'time'>,
  keywordSpec('debugView', 'debug-view', DEBUG_VIEWS),
  // Defaults of the quality knobs come from the bench's Pareto front (README, "Speed and accuracy").
  numberSpec('reflectionScale', 'reflection-scale', 1, 0.125, 2),
  {
    property: 'samples', attribute: 'samples', default: 4,
    parse(raw) {
      if (raw === null) return { value: 4 };
      const x = num(raw);
      if (Number.isNaN(x)) return { value: 4, problem: 'expected 0, 2 or 4; using 4' };
      // The nearest allowed count at or below the request (ties never arise: 0, 2, 4).
      const value = x >= 4 ? 4 : x >= 2 ? 2 : 0;
      return value === x ? { value } : { value, problem: `expected 0, 2 or 4; using ${value}` };
    },
    format: (v) => String(v),
  } satisfies AttributeSpec<'samples'>,
  {
    // A whole number of frames, 0..MAX_REFINEMENT; 0 turns refinement off.
    property: 'refine', attribute: 'refine', default: REFINE_DEFAULT,
    parse(raw) {
      if (raw === null) return { value: REFINE_DEFAULT };
      const x = num(raw);
      if (Number.isNaN(x)) return { value: REFINE_DEFAULT, problem: `not a number, using ${REFINE_DEFAULT}` };
      const value = Math.round(Math.min(MAX_REFINEMENT, Math.max(0, x)));
      return value === x ? { value } : { value, problem: `expected a whole number of frames 0..${MAX_REFINEMENT}; using ${value}` };
    },
    format: (v) => String(v),
  } satisfies AttributeSpec<'refine'>,
  keywordSpec('shading', 'shading', SHADINGS),
  autoOrNumberSpec('tessellation', 'tessellation', 4, 512, true),
  autoOrNumberSpec('pixelRatio', 'pixel-ratio', 0.25, 4, false),
  keywordSpec('reflectionFormat', 'reflection-format', ['rgba8', 'rgba16f']),
  keywordSpec('colorSpace', 'color-space', COLOR_SPACES),
  keywordSpec('toneMapping', 'tone-mapping', TONE_MAPPING_WORDS),
  numberSpec('exposure', 'exposure', 1, 0, 64),
  {
    // A keyword (any case), else a URL as written; empty is the default.
    property: 'environment', attribute: 'environment', default: 'neutral',
    parse(raw) {
      const w = raw === null ? '' : raw.trim();
      const k = w.toLowerCase();
      return { value: w === '' || k === 'neutral' ? 'neutral' : k === 'none' ? 'none' : w };
    },
    format: (v) => v,
  } satisfies AttributeSpec<'environment'>,
  numberSpec('environmentIntensity', 'environment-intensity', 1, 0, 64),
  numberSpec('roughness', 'roughness', 0, 0, 1),
  keywordSpec('roughnessQuality', 'roughness-quality', ['medium', 'low', 'high']),
  tupleSpec('glassCenter', 'glass-center', [0, 1, 0], '"x y z"', clampCoords),
  tupleSpec('glassNormal', 'glass-normal', [0, 0, 1], '"x y z"', (xs) => {
    const l = Math.hypot(xs[0], xs[1], xs[2]);
    if (!(l > 0) || !Number.isFinite(l)) return { value: [0, 0, 1], problem: 'not a usable direction, using "0 0 1"' };
    return { value: xs.map((x) => x / l) };
  }),
  tupleSpec('glassSize', 'glass-size', [8, 4], '"w h"', (xs) => {
    const c = xs.map((x) => Math.min(MAX_COORD, Math.max(0, x)));
    const capped = xs.some((x) => x > MAX_COORD) ? `size clamped to ${MAX_COORD}` : '';
    if (xs.some((x) => x < 0)) return { value: c, problem: `negative size clamped to 0${capped && `, ${capped}`}` };
    return capped ? { value: c, problem: capped } : { value: c };
  }),
  {
    property: 'background', attribute: 'background', default: [0.1, 0.1, 0.1],
    parse(raw) {
      if (raw === null) return { value: [0.1, 0.1, 0.1] };
      const rgb = parseCssColor(raw) ?? browserCssColor(raw);
      if (!rgb) return { value: [0.1, 0.1, 0.1], problem: `not a CSS colour, using ${DEFAULT_BACKGROUND}` };
      return { value: rgb };
    },
    format: (v) => v.join(' '),
  } satisfies AttributeSpec<'background'>,
] as AttributeSpec[];

export const ATTRIBUTE_BY_NAME: ReadonlyMap<string, AttributeSpec> = new Map(ATTRIBUTES.map((s) => [s.attribute, s]));

export function defaultAttributes(): SceneAttributes {
  const out = {} as Record<string, unknown>;
  for (const s of ATTRIBUTES) out[s.property] = s.parse(null).value;
  return out as unknown as SceneAttributes;
}

/**
 * Turns whatever a script assigned to a property into the attribute string it stands for:
 * null/undefined remove it, booleans toggle presence, arrays join with spaces.
 */
export function propertyToRaw(spec: AttributeSpec, value: unknown): string | null {
  if (value === null || value === undefined) return null;
  if (spec.property === 'controls' && typeof value === 'boolean') return value ? '' : null;
  if (Array.isArray(value)) return value.map((x) => String(x)).join(' ');
  if (typeof value === 'number' || typeof value === 'string' || typeof value === 'boolean') return String(value);
  return '\u0000invalid'; // objects, symbols, functions: never usable
}
