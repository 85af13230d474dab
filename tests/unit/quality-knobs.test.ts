// The quality knobs of docs/knobs.md#the-knobs in the attribute table, and the sphere's auto tessellation.
import { describe, expect, it } from 'vitest';
import { ATTRIBUTE_BY_NAME } from '../../src/element/attributes';
import { segmentsForScreenRadius, MAX_SEGMENTS, MIN_SEGMENTS } from '../../src/scene/geometry/sphere';
import { sphereScreenRadius } from '../../src/frame/sphere-screen';
import { SPHERE } from '../../src/scene/default-scene';
import type { FrameState } from '../../src/frame/types';
import { defaultFrameState } from './helpers/frame-state';

const parse = (attr: string, raw: string | null) => ATTRIBUTE_BY_NAME.get(attr)!.parse(raw);

describe('reflection-scale', () => {
  it('defaults to 1 (from the bench, in the default view) and clamps to 0.125..2 with a problem', () => {
    expect(parse('reflection-scale', null)).toEqual({ value: 1 });
    expect(parse('reflection-scale', '0.5')).toEqual({ value: 0.5 });
    expect(parse('reflection-scale', '0.01').value).toBe(0.125);
    expect(parse('reflection-scale', '0.01').problem).toBeTruthy();
    expect(parse('reflection-scale', '9').value).toBe(2);
    expect(parse('reflection-scale', 'big').value).toBe(1);
    expect(parse('reflection-scale', 'big').problem).toBeTruthy();
  });
});

describe('samples', () => {
  it('accepts 0, 2, 4 and rounds anything else down to one of them, with a problem', () => {
    for (const n of [0, 2, 4]) expect(parse('samples', String(n))).toEqual({ value: n });
    expect(parse('samples', '3')).toMatchObject({ value: 2 });
    expect(parse('samples', '3').problem).toBeTruthy();
    expect(parse('samples', '16').value).toBe(4);
    expect(parse('samples', '1').value).toBe(0);
    expect(parse('samples', '-5').value).toBe(0);
    expect(parse('samples', null)).toEqual({ value: 4 });
    expect(parse('samples', 'many')).toMatchObject({ value: 4 });
    expect(parse('samples', 'many').problem).toBeTruthy();
  });
});

describe('shading', () => {
  it('is phong by default and takes flat / gouraud', () => {
    expect(parse('shading', null).value).toBe('phong');
    expect(parse('shading', 'Gouraud')).toEqual({ value: 'gouraud' });
    expect(parse('shading', 'flat')).toEqual({ value: 'flat' });
    expect(parse('shading', 'toon').value).toBe('phong');
    expect(parse('shading', 'toon').problem).toBeTruthy();
  });
});

describe('tessellation and pixel-ratio', () => {
  it('take auto or a clamped number', () => {
    expect(parse('tessellation', null).value).toBe('auto');
    expect(parse('tessellation', 'AUTO')).toEqual({ value: 'auto' });
    expect(parse('tessellation', '33.4')).toEqual({ value: 33 });
    expect(parse('tessellation', '2').value).toBe(4);
    expect(parse('tessellation', '100000').value).toBe(512);
    expect(parse('tessellation', 'x')).toMatchObject({ value: 'auto' });
    expect(parse('tessellation', 'x').problem).toBeTruthy();
    expect(parse('pixel-ratio', null).value).toBe('auto');
    expect(parse('pixel-ratio', '1.5')).toEqual({ value: 1.5 });
    expect(parse('pixel-ratio', '0').value).toBe(0.25);
    expect(parse('pixel-ratio', '10').value).toBe(4);
  });
});

describe('reflection-format', () => {
  it('is rgba8 by default (from the bench) and takes rgba16f', () => {
    expect(parse('reflection-format', null).value).toBe('rgba8');
    expect(parse('reflection-format', 'RGBA16F')).toEqual({ value: 'rgba16f' });
    expect(parse('reflection-format', 'float')).toMatchObject({ value: 'rgba8' });
    expect(parse('reflection-format', 'float').problem).toBeTruthy();
  });
});

describe('auto tessellation', () => {
  const state = (z: number, height = 360): FrameState => defaultFrameState({
    height, spin: 0, cubeDistance: 2.5, cameraPosition: [1, 1, z], yaw: -90, pitch: 0, colorSpace: 'none', samples: 0,
  });

  it('measures the sphere on screen: nearer and taller buffers make it bigger', () => {
    const at = (s: FrameState) => sphereScreenRadius(s, SPHERE.centre, SPHERE.radius);
    const far = at(state(10));
    const near = at(state(2));
    expect(near).toBeGreaterThan(far);
    expect(at(state(10, 720))).toBeCloseTo(2 * far, 6);
    // Distance 11.5 from the centre, radius 0.75, fov 60 at 360 px: focal = 180/tan 30°.
    const focal = 180 / Math.tan(Math.PI / 6);
    expect(far).toBeCloseTo(focal * Math.tan(Math.asin(0.75 / 11.5)), 9);
    expect(at(state(-1.5))).toBe(Number.POSITIVE_INFINITY); // inside
  });

  it('keeps the silhouette error under half a pixel, within the segment bounds', () => {
    for (const r of [1, 10, 50, 200, 1000]) {
      const n = segmentsForScreenRadius(r);
      expect(n).toBeGreaterThanOrEqual(MIN_SEGMENTS);
      expect(n).toBeLessThanOrEqual(MAX_SEGMENTS);
      if (n < MAX_SEGMENTS) expect(r * (1 - Math.cos(Math.PI / n))).toBeLessThanOrEqual(0.5);
    }
    expect(segmentsForScreenRadius(1e9)).toBe(MAX_SEGMENTS);
    expect(segmentsForScreenRadius(0)).toBe(MIN_SEGMENTS);
  });
});
