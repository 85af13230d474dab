// Shader variants, compiled on first use only (docs/knobs.md#shader-variants), keyed by their #define header.
import standardVert from '../../shaders/standard.vert?raw';
import standardFrag from '../../shaders/standard.frag?raw';
import glassVert from '../../shaders/glass.vert?raw';
import glassFrag from '../../shaders/glass.frag?raw';
import blitVert from '../../shaders/blit.vert?raw';
import encodeFrag from '../../shaders/encode.frag?raw';
import lighting from '../../shaders/lighting.glsl?raw';
import footprint from '../../shaders/footprint.glsl?raw';
import type { FresnelModel } from '../math/fresnel';
import type { ToneMapping } from '../math/tone-map';
import type { Shading } from '../frame/types';
import { MAPPINGS, MAX_LIGHTS, type Mapping } from '../scene/scene';
import { Program, ShaderError } from './gl/program';
import type { SharedResources } from './gl/shared-resources';

export type ClipMode = 'none' | 'clip-distance' | 'discard';

/** A lazy chunk's shader part, or the error of a program asked for before it loaded. */
function loaded(source: string | null, whose: string): string {
  if (source === null) throw new Error(`glass-plane-scene: ${whose} program was asked for before its chunk loaded`);
  return source;
}

/** The tone-mapped encodes' names (built once: no string is made in a frame). */
const ENCODES: Record<ToneMapping, string> = { neutral: 'encode:neutral', aces: 'encode:aces', none: 'encode:none' };

/** What an object's draw needs beyond clip and shading; each a #define (docs/knobs.md#shader-variants: only what is in use). */
export interface ObjectVariant {
  /** Lit on the side facing the viewer (meshes from files, docs/scene-model.md#two-sided-lighting). */
  twoSided: boolean;
  /** 1..MAX_LIGHTS. */
  lights: number;
  /** Bit i set: light i is a point light (else directional). */
  pointMask: number;
  mapping: Mapping;
  /** A glTF material (docs/pbr.md#the-scenes-lights): lit per fragment by the glTF BRDF, whatever the shading (its chunk must be in). */
  pbr: boolean;
  /** A glTF material lit by an environment too (docs/pbr.md#the-environment; its chunk must be in). */
  environment: boolean;
  /** A glTF material's normal map on a mesh with tangents (docs/gltf.md#the-normal-map). */
  normalMap: boolean;
  /** A glTF material on a mesh with vertex colours (docs/gltf.md#vertex-colours). */
  vertexColors: boolean;
  /** A glTF material of alphaMode `mask` (docs/gltf.md#alpha): fragments under the cutoff discarded. */
  alphaMask: boolean;
}

function standardHeader(clip: ClipMode, shading: Shading, v: ObjectVariant, pbr: string | null, environment: string | null): string[] {
  const header: string[] =
    clip === 'none' ? [] :
    clip === 'clip-distance' ? ['#extension GL_ANGLE_clip_cull_distance : require', '#define CLIP_PLANE', '#define CLIP_DISTANCE'] :
    ['#define CLIP_PLANE'];
  header.push(`#define SHADING_${shading.toUpperCase()}`);
  if (v.twoSided) header.push('#define TWO_SIDED');
  if (pbr !== null) header.push('#define PBR');
  if (environment !== null) header.push('#define ENVIRONMENT');
  if (pbr !== null && v.normalMap) header.push('#define NORMAL_MAP');
  if (pbr !== null && v.vertexColors) header.push('#define VERTEX_COLORS');
  if (pbr !== null && v.alphaMask) header.push('#define ALPHA_MASK');
  header.push(`#define LIGHT_COUNT ${v.lights}`, `#define MAPPING_${v.mapping.toUpperCase()}`);
  for (let i = 0; i < MAX_LIGHTS; i++) header.push(`#define LIGHT${i}_POINT ${(v.pointMask >> i) & 1 ? 'true' : 'false'}`);
  header.push(footprint, lighting);
  if (environment !== null) header.push(environment);
  if (pbr !== null) header.push(pbr);
  return header;
}

/**
 * The marker line in glass.frag where its ROUGH variant takes rough-glass.glsl (after the
 * declarations it reads): a line of its own, not a comment, so it outlasts the build's shader
 * minification (scripts/glsl-minify.ts).
 */
const ROUGH_MARKER = /^ROUGH_GATHER_SOURCE$/m;

/**
 * Rough glass's shader parts (docs/rough-glass.md#roughness). They live in rough glass's own chunk
 * (rough-glass-gl.ts), which the renderer loads the first time a frame's glass is rough.
 */
export interface RoughSources {
  /** shaders/rough-glass.glsl: the gather, put into glass.frag at ROUGH_MARKER. */
  gather: string;
  /** shaders/distance.frag: depth → distance codes. */
  distance: string;
  /** The ROUGH variant's #define lines. */
  defines: string[];
}

function glassHeader(model: FresnelModel, outputFresnel: boolean, roughDefines: string[] = []): string[] {
  const header = [`#define FRESNEL_${model.toUpperCase()}`];
  if (outputFresnel) header.push('#define OUTPUT_FRESNEL');
  header.push(...roughDefines, footprint);
  return header;
}

/**
 * The variants one renderer uses, found without building a key in a frame that compiles
 * nothing. The programs themselves are compiled once per context and shared (SharedResources).
 */
export class ProgramCache {
  /** Every program this renderer uses, in order of first use (for size and dispose). */
  private readonly all: Program[] = [];
  // Found by their variant's parts, so a frame that compiles nothing builds no key, header or
  // array: those are made only on a miss.
  /** [clip][shading][variantIndex(v)] */
  private standards: Partial<Record<ClipMode, Partial<Record<Shading, (Program | undefined)[]>>>> = {};
  private glasses: Partial<Record<FresnelModel, { colour?: Program; fresnel?: Program; rough?: Program }>> = {};
  /** Full-screen triangles' programs by name (fullScreen). */
  private readonly screens = new Map<string, Program>();
  /** Rough glass's shader parts, once its chunk has loaded (setRoughSources). */
  private rough: RoughSources | null = null;
  /** The PBR variant's and the tone mapping's shader parts, once their chunk has loaded (setPbrSources). */
  private pbr: string | null = null;
  /** The ENVIRONMENT variant's shader part, once its chunk has loaded (setEnvironmentSource). */
  private environment: string | null = null;
  private toneMap: string | null = null;
  /**
   * Variants that failed to compile, by key: asked again (the same state drawn again), they throw
   * the same error without compiling again. A new context means a new cache, so a restore retries.
   */
  private readonly broken = new Map<string, ShaderError>();

  constructor(private readonly gl: WebGL2RenderingContext, private readonly shared: SharedResources) {}

  get size(): number {
    return this.all.length;
  }

  /** The standard program for one object's draw. A cached lookup builds no key, header or array. */
  standard(clip: ClipMode, requested: Shading, v: ObjectVariant): Program {
    // A glTF material is lit per fragment whatever the frame's shading (docs/pbr.md#the-scenes-lights).
    const shading = v.pbr ? 'phong' : requested;
    const variants = ((this.standards[clip] ??= {})[shading] ??= []);
    const lights = Math.max(1, Math.min(MAX_LIGHTS, v.lights));
    const points = v.pointMask & ((1 << lights) - 1);
    const env = v.pbr && v.environment, normalMap = v.pbr && v.normalMap, colors = v.pbr && v.vertexColors, mask = v.pbr && v.alphaMask;
    const kind = v.pbr ? 1 + (env ? 1 : 0) + (normalMap ? 2 : 0) + (colors ? 4 : 0) + (mask ? 8 : 0) : 0;
    const i = 2 * kind + (v.twoSided ? 1 : 0) + 34 * (lights - 1 + MAX_LIGHTS * (points + (1 << MAX_LIGHTS) * MAPPINGS.indexOf(v.mapping)));
    return (variants[i] ??= this.build(
      `standard:${clip}:${shading}${v.twoSided ? ':two-sided' : ''}${v.pbr ? ':pbr' : ''}${env ? ':environment' : ''}${normalMap ? ':normal-map' : ''}${colors ? ':vertex-colours' : ''}${mask ? ':alpha-mask' : ''}:lights${lights}/${points}:${v.mapping}`,
      standardVert, standardFrag,
      standardHeader(clip, shading, { ...v, lights, pointMask: points }, v.pbr ? this.pbrSource() : null, env ? this.environmentSource() : null),
    ));
  }

  /** Takes rough glass's shader parts once its chunk has loaded (ROUGH_GLASS, render/parts.ts). */
  setRoughSources(sources: RoughSources): void {
    this.rough = sources;
  }

  /** Takes the PBR variant's and the tone mapping's shader parts once their chunk has loaded (PBR_MATERIALS, render/parts.ts). */
  setPbrSources(pbr: string, toneMap: string): void {
    this.pbr = pbr;
    this.toneMap = toneMap;
  }

  /** Takes the ENVIRONMENT variant's shader part once its chunk has loaded (ENVIRONMENT_LIGHT, render/parts.ts). */
  setEnvironmentSource(source: string): void {
    this.environment = source;
  }

  private environmentSource(): string {
    return loaded(this.environment, 'an environment\'s');
  }

  /** Whether the PBR variant and the tone-mapped encodes can be built: their chunk is in. */
  get hasPbr(): boolean {
    return this.pbr !== null;
  }

  private pbrSource(): string {
    return loaded(this.pbr, 'a glTF material\'s');
  }

  private roughSources(): RoughSources {
    if (!this.rough) throw new Error('glass-plane-scene: a rough glass program was asked for before its chunk loaded');
    return this.rough;
  }

  /** `rough`: rough glass's gather (docs/rough-glass.md#the-gather) (the colour variant only; roughness 0 never asks for it). */
  glass(model: FresnelModel, outputFresnel: boolean, rough = false): Program {
    const variants = (this.glasses[model] ??= {});
    if (rough && !outputFresnel) {
      if (variants.rough) return variants.rough;
      const { gather, defines } = this.roughSources();
      return (variants.rough = this.build(
        `glass:${model}:false:rough`, glassVert, glassFrag.replace(ROUGH_MARKER, () => gather), glassHeader(model, false, defines),
      ));
    }
    return outputFresnel
      ? (variants.fresnel ??= this.build(`glass:${model}:true`, glassVert, glassFrag, glassHeader(model, true)))
      : (variants.colour ??= this.build(`glass:${model}:false`, glassVert, glassFrag, glassHeader(model, false)));
  }

  /**
   * A full-screen triangle (shaders/blit.vert) with the fragment shader `frag`, compiled the
   * first time `name` is asked for: the debug views' blit (render/debug-views.ts) and the two below.
   */
  fullScreen(name: string, frag: string, header: string[] = []): Program {
    let p = this.screens.get(name);
    if (!p) this.screens.set(name, (p = this.build(name, blitVert, frag, header)));
    return p;
  }

  /**
   * The frame's one sRGB encode (docs/colour.md#the-transfer-curve); with `curve`, a tone-mapped frame's: exposed and tone
   * mapped first (docs/pbr.md#tone-mapping; its chunk must be in).
   */
  encode(curve: ToneMapping | null = null): Program {
    if (curve === null) return this.fullScreen('encode', encodeFrag);
    const name = ENCODES[curve];
    return this.screens.get(name) ?? this.fullScreen(name, encodeFrag, [`#define TONE_${curve.toUpperCase()}`, this.toneMapSource()]);
  }

  /** The frame copied as it is, linear and unclamped: what refinement averages (docs/refinement.md#averaging). */
  copy(): Program {
    return this.fullScreen('copy', encodeFrag, ['#define COPY']);
  }

  private toneMapSource(): string {
    if (this.toneMap === null) throw new Error('glass-plane-scene: a tone-mapped encode was asked for before its chunk loaded');
    return this.toneMap;
  }

  /** Rough glass's distance code into a target's alpha (shaders/distance.frag). */
  distance(): Program {
    return this.screens.get('distance') ?? this.fullScreen('distance', this.roughSources().distance);
  }

  private build(key: string, vert: string, frag: string, header: string[]): Program {
    const known = this.broken.get(key);
    if (known) throw known;
    try {
      const p = this.shared.program(key, (counter) => new Program(this.gl, counter, key, vert, frag, header));
      this.all.push(p);
      return p;
    } catch (e) {
      if (e instanceof ShaderError) this.broken.set(key, e);
      throw e;
    }
  }

  dispose(): void {
    for (const p of this.all) this.shared.releaseProgram(p.name);
    this.all.length = 0;
    this.standards = {};
    this.glasses = {};
    this.screens.clear();
    this.broken.clear();
  }
}
