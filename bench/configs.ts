// Bench configurations: a high-quality baseline, one knob at a time from it, and the grids
// shading × tessellation and reflection-scale × samples (deduplicated), all in linear light
// (color-space srgb, the element's default), and the baseline and the defaults with values as
// stored (color-space none) beside them. Each row is scored against the reference in its own
// colour space, so rows of different spaces are not on one Pareto front.
import type { FresnelModel } from '../src/math/fresnel';
import type { ColorSpace, ReflectionFormat, Shading } from '../src/frame/types';

export interface BenchConfig {
  name: string;
  reflectionScale: number;
  samples: 0 | 2 | 4;
  fresnel: FresnelModel;
  shading: Shading;
  tessellation: number | 'auto';
  pixelRatio: number;
  reflectionFormat: ReflectionFormat;
  colorSpace: ColorSpace;
}

export type Knobs = Omit<BenchConfig, 'name'>;

export const BASELINE: Knobs = {
  reflectionScale: 1, samples: 4, fresnel: 'exact', shading: 'phong', tessellation: 128, pixelRatio: 1, reflectionFormat: 'rgba8',
  colorSpace: 'srgb',
};

/** The element's defaults (src/element/attributes.ts), at pixel-ratio 1 like every row. */
export const DEFAULTS: Knobs = {
  reflectionScale: 1, samples: 4, fresnel: 'exact', shading: 'phong', tessellation: 'auto', pixelRatio: 1, reflectionFormat: 'rgba8',
  colorSpace: 'srgb',
};

/** Short, stable name: only the knobs that differ from the baseline. */
export function configName(k: Knobs): string {
  const parts: string[] = [];
  if (k.reflectionScale !== BASELINE.reflectionScale) parts.push(`reflection-scale ${k.reflectionScale}`);
  if (k.samples !== BASELINE.samples) parts.push(`samples ${k.samples}`);
  if (k.fresnel !== BASELINE.fresnel) parts.push(`fresnel ${k.fresnel}`);
  if (k.shading !== BASELINE.shading) parts.push(`shading ${k.shading}`);
  if (k.tessellation !== BASELINE.tessellation) parts.push(`tessellation ${k.tessellation}`);
  if (k.pixelRatio !== BASELINE.pixelRatio) parts.push(`pixel-ratio ${k.pixelRatio}`);
  if (k.reflectionFormat !== BASELINE.reflectionFormat) parts.push(`reflection-format ${k.reflectionFormat}`);
  if (k.colorSpace !== BASELINE.colorSpace) parts.push(`color-space ${k.colorSpace}`);
  return parts.length ? parts.join(', ') : 'baseline';
}

function build(): BenchConfig[] {
  const list: Knobs[] = [BASELINE];
  const one = <K extends keyof Knobs>(key: K, values: Knobs[K][]) => {
    for (const v of values) list.push({ ...BASELINE, [key]: v });
  };
  one('reflectionScale', [0.125, 0.25, 0.5, 2]);
  one('samples', [0, 2]);
  one('fresnel', ['schlick', 'classic']);
  one('shading', ['gouraud', 'flat']);
  one('tessellation', [8, 16, 32, 64, 256, 'auto']);
  one('pixelRatio', [0.5, 0.75, 1.5, 2]);
  one('reflectionFormat', ['rgba16f']);
  list.push({ ...DEFAULTS, reflectionFormat: 'rgba16f' }, { ...DEFAULTS, samples: 0, reflectionFormat: 'rgba16f' });
  for (const shading of ['phong', 'gouraud', 'flat'] as const) {
    for (const tessellation of [16, 32, 'auto'] as const) list.push({ ...BASELINE, shading, tessellation });
  }
  for (const reflectionScale of [0.25, 0.5, 1]) {
    for (const samples of [0, 2, 4] as const) list.push({ ...BASELINE, reflectionScale, samples, tessellation: 'auto' });
  }
  // Values as stored (the course's convention, and every row before color-space existed), scored against the none reference.
  list.push({ ...BASELINE, colorSpace: 'none' }, { ...DEFAULTS, colorSpace: 'none' });
  const seen = new Map<string, BenchConfig>();
  for (const k of list) {
    const name = configName(k);
    if (!seen.has(name)) seen.set(name, { name, ...k });
  }
  return [...seen.values()];
}

export const CONFIGS: readonly BenchConfig[] = build();
