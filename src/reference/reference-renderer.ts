// The float64 CPU reference image of a frame: stratified samples per pixel, box-filtered, plus regions.
import { defaultScene } from '../scene/default-scene';
import type { Scene } from '../scene/scene';
import type { SceneImages } from '../scene/decoded-image';
import { regionMap, regionOfCodes } from './regions';
import type { ReferenceState, ViewState } from './reference-state';
import { SampleTracer, type TextureFilter } from './sample-tracer';
import type { SurfaceCodes } from './surface-codes';
import { linearToSrgb } from '../math/srgb';
import { toneMap } from '../math/tone-map';
import { colourCeiling } from './reference-state';
import { HashStream, MicrofacetSamples } from './microfacet-samples';
import { STUDIO_LIGHT } from './pbr-light';
import { imageLight } from './image-light';

export interface ReferenceOptions {
  /**
   * Samples per pixel along each axis, at the centres of an n×n grid of equal strata, box
   * filtered (averaged). 1 → one sample at the pixel centre (shading error), 8 → 64 spp
   * (edge error). Default 1.
   */
  samplesPerAxis?: number;
  /**
   * How each sample reads the texture. 'point': bilinear at its UV (GL LINEAR at mip 0, the
   * GPU's closest analogue at one sample per pixel). 'box': the exact mean of the bilinear
   * texture over the sample's footprint (its stratum mapped onto the surface), so texture
   * detail smaller than a stratum is integrated, not aliased. Default: 'point' for 1 spp,
   * 'box' when supersampling.
   */
  textureFilter?: TextureFilter;
  /**
   * Rough glass (docs/rough-glass.md#reference-monte-carlo): microfacet normals per pixel for its Monte Carlo, rounded up to a
   * whole number per sample (each sample averages its share). Default 256. Unused when the
   * state's roughness is 0.
   */
  microfacetSamples?: number;
  /**
   * Light from the scene's environment on glTF materials (docs/pbr.md#the-reference): directions per pixel for its Monte Carlo,
   * rounded up to a whole number per sample (each shading in that sample draws them). Default 256. Unused without an environment.
   */
  environmentSamples?: number;
}

/** The default of ReferenceOptions.environmentSamples. */
export const DEFAULT_ENVIRONMENT_SAMPLES = 256;

/**
 * The default of docs/rough-glass.md#reference-monte-carlo. Measured on the bench's rough floor (cube on the glass, sphere 1.5 above,
 * ior 10, 160×90, 4×4 samples per pixel), glass PSNR of the reference against itself at 4096:
 * roughness 0.3: 56.8 dB at 256, 57.6 at 512; roughness 0.6: 54.2 and 55.8 (at 64: 51.4 and
 * 46.3). Its noise then sits ≥ 54 dB down, so doubling it moves a renderer's figure under
 * ~47 dB by well under 0.5 dB (the bench reports that check).
 */
export const DEFAULT_MICROFACET_SAMPLES = 256;

export interface ReferenceImage {
  width: number;
  height: number;
  view: ViewState['view'];
  samplesPerAxis: number;
  textureFilter: TextureFilter;
  /** RGBA8, top row first, round(c·255) of `rgb`, alpha 255 — comparable with `capture()`. */
  rgba: Uint8ClampedArray;
  /**
   * RGB in 0..1, float64, top row first: the reference itself, before quantisation. What the
   * page shows: sRGB-encoded with colorSpace 'srgb' (docs/colour.md#debug-views; the fresnel view excepted), as
   * computed with 'none'.
   */
  rgb: Float64Array;
  /**
   * Per pixel: 0 background, 1 cube (any box), 2 sphere (any other object), 3 glass, 4 edge
   * band (regions.ts).
   */
  regions: Uint8Array;
  /**
   * Per pixel, the key of its first sample: the surfaces it saw, primary + 9·behind +
   * 81·reflected in the default scene (sample-tracer.ts; `codes.base` in general). Geometry,
   * not colour: `glassReflectsCube` reads it.
   */
  keys: Int32Array;
  /** The surface codes the keys are written in: which object each code names (renderScene sets it). */
  codes?: SurfaceCodes;
  /** Microfacet normals averaged per pixel for rough glass (docs/rough-glass.md#reference-monte-carlo); 0 when the glass is polished. */
  microfacetSamples?: number;
  /** Environment directions per pixel (docs/pbr.md#the-reference); 0 without an environment. */
  environmentSamples?: number;
}

/**
 * renderScene of the default scene (docs/default-scene.md) with the cube at `state.cubeDistance`,
 * turning at `state.spin`, and no images: the reference's counterpart of the other renderers' null scene.
 */
export function renderReference(state: ReferenceState, options: ReferenceOptions = {}): ReferenceImage {
  return renderScene(defaultScene(state.cubeDistance, state.spin), state, null, options);
}

/**
 * Renders `state.view` ('final', 'scene', 'reflection' or 'fresnel') of `scene` as the GPU
 * path would with exact geometry, shading and texture filtering, in `state.colorSpace`. Pure:
 * no DOM, no Node APIs; runs in a browser, a worker or Node. The renderer contract
 * (ARCHITECTURE.md, "How a frame flows"), then the reference's own options: `images` are the
 * decoded images the scene names, by URL (a material whose image is missing is drawn with the
 * procedural texture); `scene` is required (renderReference draws the default one).
 */
export function renderScene(scene: Scene, state: ViewState, images?: SceneImages | null, options: ReferenceOptions = {}): ReferenceImage {
  if (state.view === 'passes') {
    throw new Error('glass-plane-scene: the reference renderer draws one view at a time, not "passes"');
  }
  const n = Math.max(1, Math.floor(options.samplesPerAxis ?? 1));
  const textureFilter = options.textureFilter ?? (n === 1 ? 'point' : 'box');
  const width = Math.max(0, Math.floor(state.width));
  const height = Math.max(0, Math.floor(state.height));
  const tracer = new SampleTracer(scene, state, textureFilter, images ?? undefined);
  // docs/rough-glass.md#reference-monte-carlo: each sample takes `perSample` of the pixel's stratified microfacet normals.
  const rough = (state.roughness ?? 0) > 0;
  const perSample = rough ? Math.max(1, Math.ceil((options.microfacetSamples ?? DEFAULT_MICROFACET_SAMPLES) / (n * n))) : 0;
  const facets = rough ? new MicrofacetSamples(perSample * n * n) : null;
  tracer.microfacets = facets ? { xi1: facets.xi1, xi2: facets.xi2, first: 0, count: perSample } : null;
  // docs/pbr.md#the-reference: each sample's shadings draw `envSamples` directions from a stream keyed by pixel and sample.
  const env = scene.environment ?? null, stream = new HashStream();
  const envSamples = env ? Math.max(1, Math.ceil((options.environmentSamples ?? DEFAULT_ENVIRONMENT_SAMPLES) / (n * n))) : 0;
  const light = env ? (env.kind === 'image' ? imageLight(env.image) : STUDIO_LIGHT) : null;
  tracer.environment = env && light ? { light, intensity: env.intensity, samples: envSamples, random: stream.next } : null;
  const codes = tracer.scene.codes;
  const rgb = new Float64Array(width * height * 3);
  const rgba = new Uint8ClampedArray(width * height * 4);
  const keys = new Int32Array(width * height);
  const mixed = new Uint8Array(width * height);
  const colour = new Float64Array(3);
  const sum = new Float64Array(3);
  // docs/colour.md#srgb: samples are linear light with srgb, averaged as light, then encoded once; the
  // fresnel view shows its number F unencoded.
  const encode = state.colorSpace === 'srgb' && state.view !== 'fresnel';
  // docs/pbr.md#tone-mapping: a tone-mapped frame's mean is exposed and tone mapped before the encode.
  const toneMapped = colourCeiling(state) === Infinity, exposure = state.exposure ?? 1, curve = state.toneMapping ?? 'none';
  // NDC size of one stratum; NDC y points up while rows go down (the camera accounts for it).
  const fx = 2 / (width * n);
  const fy = 2 / (height * n);
  const weight = 1 / (n * n);

  for (let py = 0; py < height; py++) {
    for (let px = 0; px < width; px++) {
      const i = py * width + px;
      let first = 0;
      sum.fill(0);
      facets?.fill(i);
      for (let sy = 0; sy < n; sy++) {
        const y = 1 - (py + (sy + 0.5) / n) * (2 / height);
        for (let sx = 0; sx < n; sx++) {
          const x = (px + (sx + 0.5) / n) * (2 / width) - 1;
          if (tracer.microfacets) tracer.microfacets.first = (sy * n + sx) * perSample;
          stream.restart((i * n + sy) * n + sx);
          const key = tracer.sample(x, y, fx, fy, colour);
          if (sx === 0 && sy === 0) first = key;
          else if (key !== first) mixed[i] = 1;
          // Stryker disable next-line EqualityOperator: sum[3] is past the end of sum (Float64Array(3)): dropped
          for (let k = 0; k < 3; k++) sum[k] += colour[k];
        }
      }
      keys[i] = first;
      if (toneMapped) toneMap(curve, sum, sum[0] * weight * exposure, sum[1] * weight * exposure, sum[2] * weight * exposure);
      // Stryker disable next-line EqualityOperator: k = 3 writes the next pixel's red and alpha, both written again (or past the end)
      for (let k = 0; k < 3; k++) {
        const mean = toneMapped ? sum[k] : sum[k] * weight;
        const c = encode ? linearToSrgb(mean) : mean;
        rgb[3 * i + k] = c;
        rgba[4 * i + k] = Math.round(c * 255);
      }
      rgba[4 * i + 3] = 255;
    }
  }
  return {
    width, height, view: state.view, samplesPerAxis: n, textureFilter,
    rgba, rgb, regions: regionMap(keys, mixed, width, height, regionOfCodes(scene, codes)), keys, codes,
    microfacetSamples: perSample * n * n, environmentSamples: envSamples * n * n,
  };
}
