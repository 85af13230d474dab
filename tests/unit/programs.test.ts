// The shader-variant cache: each variant compiled once, on first use; a cached lookup (every
// frame's) builds nothing.
import { describe, expect, it } from 'vitest';
import { ProgramCache, type ClipMode, type ObjectVariant } from '../../src/render/programs';
import { SharedResources } from '../../src/render/gl/shared-resources';
import { ShaderError } from '../../src/render/gl/program';
import { FRESNEL_MODELS } from '../../src/math/fresnel';
import type { Shading } from '../../src/frame/types';
import { fakeGl } from './helpers/fake-gl';

const CLIPS: ClipMode[] = ['none', 'clip-distance', 'discard'];
const SHADINGS: Shading[] = ['phong', 'gouraud', 'flat'];
/** The default scene's draws: one-sided, one light, UV mapping. */
const V: ObjectVariant = { twoSided: false, lights: 1, pointMask: 0, mapping: 'uv', pbr: false, environment: false, normalMap: false, vertexColors: false, alphaMask: false };

describe('ProgramCache', () => {
  it('compiles each variant once and returns the same program after', () => {
    const { gl, calls } = fakeGl();
    const cache = new ProgramCache(gl, SharedResources.acquire(gl));
    const first = cache.standard('none', 'phong', V);
    expect(cache.standard('none', 'phong', V)).toBe(first);
    expect(cache.standard('discard', 'phong', V)).not.toBe(first);
    expect(cache.glass('schlick', true)).toBe(cache.glass('schlick', true));
    expect(cache.glass('schlick', true)).not.toBe(cache.glass('schlick', false));
    expect(cache.encode()).toBe(cache.encode());
    expect(cache.fullScreen('blit', 'void main() {}')).toBe(cache.fullScreen('blit', 'ignored: cached by name'));
    expect(cache.size).toBe(6);
    expect(calls.get('linkProgram')).toBe(6);
  });

  it('a cached lookup builds no header, key or array (nothing allocated per frame)', () => {
    const { gl } = fakeGl();
    const cache = new ProgramCache(gl, SharedResources.acquire(gl));
    const all = () => {
      for (const c of CLIPS) for (const s of SHADINGS) cache.standard(c, s, V);
      for (const m of FRESNEL_MODELS) for (const o of [false, true]) cache.glass(m, o);
      cache.encode();
    };
    all(); // compiles every variant
    const size = cache.size;
    // What building a header takes: upper-casing a variant name, pushing #define lines, joining
    // them. Counted by plain wrappers (a spy would itself push while recording).
    const counts = { toUpperCase: 0, push: 0, join: 0 };
    const originals = { toUpperCase: String.prototype.toUpperCase, push: Array.prototype.push, join: Array.prototype.join };
    String.prototype.toUpperCase = function (this: string) { counts.toUpperCase++; return originals.toUpperCase.call(this); };
    Array.prototype.push = function (this: unknown[], ...items: unknown[]) { counts.push++; return originals.push.apply(this, items); };
    Array.prototype.join = function (this: unknown[], sep?: string) { counts.join++; return originals.join.call(this, sep); };
    try {
      all();
    } finally {
      Object.assign(String.prototype, { toUpperCase: originals.toUpperCase });
      Object.assign(Array.prototype, { push: originals.push, join: originals.join });
    }
    expect(counts, 'calls during cached lookups').toEqual({ toUpperCase: 0, push: 0, join: 0 });
    expect(cache.size).toBe(size);
  });

  it('a glTF material is its own variant, lit per fragment whatever the shading (docs/pbr.md#the-scenes-lights)', () => {
    const { gl, sources } = fakeGl();
    const cache = new ProgramCache(gl, SharedResources.acquire(gl));
    const P = { ...V, pbr: true };
    expect(cache.hasPbr).toBe(false);
    expect(() => cache.standard('none', 'phong', P)).toThrow(/glTF material's program was asked for before its chunk loaded/);
    cache.setPbrSources('// the PBR part', '// the tone map part');
    expect(cache.hasPbr).toBe(true);
    const phong = cache.standard('none', 'phong', P);
    expect(phong.name).toBe('standard:none:phong:pbr:lights1/0:uv');
    expect(cache.standard('none', 'gouraud', P)).toBe(phong);
    expect(cache.standard('none', 'flat', P)).toBe(phong);
    expect(cache.standard('none', 'phong', V)).not.toBe(phong);
    const two = cache.standard('none', 'phong', { ...P, twoSided: true });
    expect(two.name).toBe('standard:none:phong:two-sided:pbr:lights1/0:uv');
    expect(new Set([phong, two, cache.standard('none', 'phong', { ...V, twoSided: true })]).size).toBe(3);
    expect(cache.size).toBe(4);
    // The part and its #define go into the PBR variants alone.
    const headers = sources.filter((src) => src.includes('// the PBR part'));
    expect(headers.length).toBeGreaterThan(0);
    expect(sources.filter((src) => src.includes('#define PBR\n')).length).toBe(headers.length);
  });

  it('a glTF material under an environment is a variant of its own, its part before the PBR part (docs/pbr.md#the-environment)', () => {
    const { gl, sources } = fakeGl();
    const cache = new ProgramCache(gl, SharedResources.acquire(gl));
    cache.setPbrSources('// the PBR part', '// the tone map part');
    const E = { ...V, pbr: true, environment: true };
    expect(() => cache.standard('none', 'phong', E)).toThrow(/environment's program was asked for before its chunk loaded/);
    cache.setEnvironmentSource('// the environment part');
    const lit = cache.standard('none', 'phong', E);
    expect(lit.name).toBe('standard:none:phong:pbr:environment:lights1/0:uv');
    const plain = cache.standard('none', 'phong', { ...V, pbr: true });
    expect(plain).not.toBe(lit);
    // Without a glTF material the flag is nothing: the Blinn-Phong variant.
    expect(cache.standard('none', 'phong', { ...V, environment: true })).toBe(cache.standard('none', 'phong', V));
    expect(new Set([lit, cache.standard('none', 'phong', { ...E, twoSided: true }), plain, cache.standard('none', 'phong', V)]).size).toBe(4);
    const withPart = sources.filter((src) => src.includes('// the environment part'));
    expect(withPart.length).toBeGreaterThan(0);
    for (const src of withPart) {
      expect(src).toContain('#define ENVIRONMENT\n');
      expect(src.indexOf('// the environment part')).toBeLessThan(src.indexOf('// the PBR part'));
    }
    expect(sources.filter((src) => src.includes('#define ENVIRONMENT\n')).length).toBe(withPart.length);
    // The variants without it take no stand-in for it either (no empty or null part).
    for (const src of sources) expect(src).not.toMatch(/^(null|undefined)$/m);
  });

  it('a glTF material\'s normal map is a variant of its own, with and without the environment, one- and two-sided (docs/gltf.md#the-normal-map)', () => {
    const { gl, sources } = fakeGl();
    const cache = new ProgramCache(gl, SharedResources.acquire(gl));
    cache.setPbrSources('// the PBR part', '// the tone map part');
    cache.setEnvironmentSource('// the environment part');
    const N = { ...V, pbr: true, normalMap: true };
    expect(cache.standard('none', 'phong', N).name).toBe('standard:none:phong:pbr:normal-map:lights1/0:uv');
    expect(cache.standard('none', 'phong', { ...N, environment: true }).name).toBe('standard:none:phong:pbr:environment:normal-map:lights1/0:uv');
    // Every combination its own program; without a glTF material the flag is nothing.
    const all = [false, true].flatMap((environment) => [false, true].flatMap((normalMap) => [false, true].map((twoSided) =>
      cache.standard('none', 'phong', { ...V, pbr: true, environment, normalMap, twoSided }))));
    expect(new Set(all).size).toBe(8);
    expect(cache.standard('none', 'phong', { ...V, normalMap: true })).toBe(cache.standard('none', 'phong', V));
    // Vertex colours: a flag of their own, combined with the others.
    expect(cache.standard('none', 'phong', { ...N, vertexColors: true }).name).toBe('standard:none:phong:pbr:normal-map:vertex-colours:lights1/0:uv');
    const withColours = [false, true].flatMap((environment) => [false, true].flatMap((normalMap) => [false, true].map((twoSided) =>
      cache.standard('none', 'phong', { ...V, pbr: true, environment, normalMap, twoSided, vertexColors: true }))));
    expect(new Set([...all, ...withColours]).size).toBe(16);
    expect(cache.standard('none', 'phong', { ...V, vertexColors: true })).toBe(cache.standard('none', 'phong', V));
    const defined = sources.filter((src) => src.includes('#define NORMAL_MAP\n'));
    expect(defined.length).toBe(2 * 8); // eight programs (four without vertex colours, four with), a vertex and a fragment shader each
    for (const src of defined) expect(src).toContain('// the PBR part');
  });

  it('a glTF material\'s alpha mask is a variant of its own, combined with every other, at every light count and mapping (docs/gltf.md#alpha)', () => {
    const { gl, sources } = fakeGl();
    const cache = new ProgramCache(gl, SharedResources.acquire(gl));
    cache.setPbrSources('// the PBR part', '// the tone map part');
    cache.setEnvironmentSource('// the environment part');
    const M = { ...V, pbr: true, alphaMask: true };
    expect(cache.standard('none', 'phong', M).name).toBe('standard:none:phong:pbr:alpha-mask:lights1/0:uv');
    const flags = [false, true];
    const all = flags.flatMap((environment) => flags.flatMap((normalMap) => flags.flatMap((vertexColors) => flags.flatMap((alphaMask) =>
      flags.map((twoSided) => cache.standard('none', 'phong', { ...V, pbr: true, environment, normalMap, vertexColors, alphaMask, twoSided }))))));
    expect(new Set(all).size).toBe(32);
    // The index leaves no gap and no overlap with the next light count or mapping.
    const lit = [1, 2].flatMap((lights) => (['uv', 'triplanar'] as const).map((mapping) => cache.standard('none', 'phong', { ...M, lights, mapping, environment: true, normalMap: true, vertexColors: true, twoSided: true })));
    expect(new Set([...all, ...lit]).size).toBe(32 + 3);
    expect(cache.standard('none', 'phong', { ...V, alphaMask: true })).toBe(cache.standard('none', 'phong', V));
    expect(sources.filter((src) => src.includes('#define ALPHA_MASK\n')).length).toBe(2 * (16 + 3));
  });

  it('dispose deletes every program and shader', () => {
    const { gl } = fakeGl();
    const shared = SharedResources.acquire(gl);
    const counter = shared.counter;
    const cache = new ProgramCache(gl, shared);
    cache.standard('clip-distance', 'flat', V);
    cache.glass('exact', false);
    expect(counter.counts.programs).toBe(2);
    cache.dispose();
    expect(cache.size).toBe(0);
    expect(counter.total).toBe(0);
    expect(cache.standard('clip-distance', 'flat', V)).toBeDefined(); // rebuilt on demand
    expect(cache.size).toBe(1);
  });
});

describe('ProgramCache with a variant that does not compile', () => {
  it('throws the same error again without compiling again; other variants still compile; dispose forgets it', () => {
    const fake = fakeGl();
    fake.failCompile = (src) => src.includes('#define FRESNEL_SCHLICK');
    const shared = SharedResources.acquire(fake.gl);
    const counter = shared.counter;
    const cache = new ProgramCache(fake.gl, shared);
    let first: unknown;
    try { cache.glass('schlick', false); } catch (e) { first = e; }
    expect(first).toBeInstanceOf(ShaderError);
    expect((first as Error).message).toMatch(/^glass-plane-scene: .*"glass:schlick:false" failed to compile/);
    const compiles = fake.calls.get('compileShader');
    expect(() => cache.glass('schlick', false)).toThrow(first as Error);
    expect(fake.calls.get('compileShader'), 'not compiled again').toBe(compiles);
    expect(cache.glass('exact', false)).toBeDefined();
    expect(counter.counts.shaders, 'the failed shaders were deleted').toBe(2);
    cache.dispose();
    fake.failCompile = () => false;
    expect(cache.glass('schlick', false)).toBeDefined();
  });

  it('renderers on one context share each compiled program; the last to let go deletes it', () => {
    const { gl, calls } = fakeGl();
    const a = new ProgramCache(gl, SharedResources.acquire(gl));
    const sharedB = SharedResources.acquire(gl);
    const b = new ProgramCache(gl, sharedB);
    expect(b.standard('none', 'phong', V)).toBe(a.standard('none', 'phong', V));
    expect(calls.get('linkProgram'), 'compiled once for both').toBe(1);
    expect([a.size, b.size], 'each counts what it uses').toEqual([1, 1]);
    a.dispose();
    expect(calls.get('deleteProgram') ?? 0, 'still used by b').toBe(0);
    b.dispose();
    expect(calls.get('deleteProgram'), 'freed with its last user').toBe(1);
    sharedB.release();
  });
});
