// THE attribute table (docs/element.md#attribute-table): defaults, fallbacks with a problem, reflection, fuzz.
import { describe, expect, it } from 'vitest';
import {
  ATTRIBUTE_BY_NAME, ATTRIBUTES, DEBUG_VIEWS, defaultAttributes, propertyToRaw,
  type AttributeSpec, type Parsed,
} from '../../src/element/attributes';
import { PITCH_LIMIT } from '../../src/math/camera';
import fs from 'node:fs';

/** The element's JSDoc: `@attr {type} [name=default] - description` (custom-elements.json is made from it). */
const ATTR_DOCS = new Map(
  [...fs.readFileSync(new URL('../../src/element/glass-plane-scene.ts', import.meta.url), 'utf8')
    .matchAll(/@attr \{[^}]*\} \[([a-z-]+)(?:=[^\]]*)?\] - (.*)/g)].map((m) => [m[1], m[2].trim()]),
);

function spec(attribute: string): AttributeSpec {
  const s = ATTRIBUTE_BY_NAME.get(attribute);
  if (!s) throw new Error(`no attribute ${attribute}`);
  return s;
}
const parse = (attribute: string, raw: string | null): Parsed<unknown> => spec(attribute).parse(raw);

function expectOk(attribute: string, raw: string, value: unknown): void {
  const r = parse(attribute, raw);
  expect(r.value, `${attribute}="${raw}"`).toEqual(value);
  expect(r.problem, `${attribute}="${raw}" should have no problem`).toBeUndefined();
}

function expectFallback(attribute: string, raw: string, value: unknown): void {
  const r = parse(attribute, raw);
  expect(r.value, `${attribute}="${raw}"`).toEqual(value);
  expect(typeof r.problem, `${attribute}="${raw}" should report a problem`).toBe('string');
  expect(r.problem!.length).toBeGreaterThan(0);
}

describe('defaults', () => {
  it('has the documented default for every attribute (docs/element.md#attribute-table)', () => {
    const d = defaultAttributes();
    expect(d.transparency).toBe(0.5);
    expect(d.cubeDistance).toBe(0.75);
    expect(d.ior).toBe(1.5);
    expect(d.fresnel).toBe('exact');
    expect(d.fov).toBe(60);
    expect(d.spin).toBe(0.8);
    expect(d.time).toBeNull();
    expect(d.debugView).toBe('none');
    expect(d.controls).toBeNull();
    expect(d.cameraTarget).toBeNull();
    expect(d.projection).toBe('perspective');
    expect(d.renderer).toBe('auto');
    expect(d.cameraPosition).toHaveLength(3);
    expect(d.cameraPosition.every(Number.isFinite)).toBe(true);
    expect(d.cameraRotation).toHaveLength(2);
    expect(Math.abs(d.cameraRotation[1])).toBeLessThanOrEqual(PITCH_LIMIT);
  });

  it('declares every attribute once, with a kebab-case name matching its camelCase property', () => {
    const names = ATTRIBUTES.map((s) => s.attribute);
    expect(new Set(names).size).toBe(names.length);
    expect([...names].sort()).toEqual([
      'background', 'camera-position', 'camera-rotation', 'camera-src', 'camera-target', 'color-space', 'controls', 'cube-distance', 'debug-view',
      'environment', 'environment-intensity', 'exposure', 'fov', 'fresnel', 'glass-center', 'glass-normal', 'glass-size', 'ior', 'pixel-ratio', 'poster', 'projection', 'refine', 'reflection-format',
      'reflection-scale', 'renderer', 'roughness', 'roughness-quality', 'samples', 'shading', 'spin', 'tessellation', 'time', 'tone-mapping',
      'transparency',
    ]);
    for (const s of ATTRIBUTES) {
      expect(s.attribute.replace(/-([a-z])/g, (_, c: string) => c.toUpperCase())).toBe(s.property);
      expect(ATTR_DOCS.get(s.attribute)?.length ?? 0, `${s.attribute} documented by an @attr line`).toBeGreaterThan(10);
      expect(s.parse(null).problem).toBeUndefined();
      expect(s.parse(null).value).toEqual(s.default);
    }
  });

  it('hands out fresh arrays, so mutating one parse cannot change the default', () => {
    const a = defaultAttributes();
    a.cameraPosition[0] = 999;
    a.cameraRotation[0] = 999;
    expect(defaultAttributes().cameraPosition[0]).not.toBe(999);
    expect(defaultAttributes().cameraRotation[0]).not.toBe(999);
    expect(spec('camera-position').default).not.toContain(999);
  });

  it('formats the default back to a string that parses to the same value', () => {
    for (const s of ATTRIBUTES) {
      const raw = s.format(s.default as never);
      const r = s.parse(raw);
      expect(r.value, s.attribute).toEqual(s.default);
      expect(r.problem).toBeUndefined();
    }
  });
});

describe('numbers', () => {
  it('transparency clamps to 0..1 and falls back to 0.5 on garbage', () => {
    expectOk('transparency', '0.25', 0.25);
    expectOk('transparency', '1', 1);
    expectOk('transparency', '  3e-1  ', 0.3);
    expectFallback('transparency', '2', 1);
    expectFallback('transparency', '-1', 0);
    expectFallback('transparency', 'abc', 0.5);
    expectFallback('transparency', '', 0.5);
    expectFallback('transparency', '   ', 0.5);
    expectFallback('transparency', 'NaN', 0.5);
    expectFallback('transparency', '0.5px', 0.5);
  });

  it('ior clamps to 1..10', () => {
    expectOk('ior', '1.33', 1.33);
    expectFallback('ior', '0.5', 1);
    expectFallback('ior', '11', 10);
    expectFallback('ior', 'glass', 1.5);
  });

  it('fov clamps to 1..179', () => {
    expectOk('fov', '45', 45);
    expectFallback('fov', '0', 1);
    expectFallback('fov', '500', 179);
    expectFallback('fov', '-Infinity', 1);
  });

  it('cube-distance and spin take finite numbers, never ±Infinity; cube-distance within ±1e7', () => {
    expectOk('cube-distance', '-3', -3);
    expectOk('cube-distance', '1e7', 1e7);
    // Finite in float64 but not in float32 on the way to the GPU: clamped like camera-position.
    expectFallback('cube-distance', '1e308', 1e7);
    expectFallback('cube-distance', '-3.5e38', -1e7);
    expectOk('spin', '1e308', 1e308);
    expectFallback('cube-distance', 'Infinity', 0.75);
    expectFallback('cube-distance', '1e309', 0.75);
    expectFallback('cube-distance', 'far', 0.75);
    expectOk('spin', '0', 0);
    expectOk('spin', '-2.5', -2.5);
    expectFallback('spin', '-Infinity', 0.8);
  });

  it('time is a finite number of seconds or null', () => {
    expectOk('time', '0', 0);
    expectOk('time', '12.5', 12.5);
    expectFallback('time', 'abc', null);
    expectFallback('time', 'Infinity', null);
    expectFallback('time', '', null);
  });
});

describe('keywords', () => {
  it('fresnel is case-insensitive and falls back to exact', () => {
    expectOk('fresnel', 'SCHLICK', 'schlick');
    expectOk('fresnel', ' classic ', 'classic');
    expectOk('fresnel', 'exact', 'exact');
    expectFallback('fresnel', 'foo', 'exact');
    expectFallback('fresnel', '', 'exact');
  });

  it('debug-view accepts every listed view', () => {
    for (const v of DEBUG_VIEWS) expectOk('debug-view', v, v);
    expectFallback('debug-view', 'depth', 'none');
  });
});

describe('camera', () => {
  const defPos = spec('camera-position').default;
  const defRot = spec('camera-rotation').default;

  it('camera-position takes exactly three finite numbers', () => {
    expectOk('camera-position', '1 2 3', [1, 2, 3]);
    expectOk('camera-position', ' -1.5,0 ,  2e1 ', [-1.5, 0, 20]);
    expectFallback('camera-position', '1 2', defPos);
    expectFallback('camera-position', '1 2 3 4', defPos);
    expectFallback('camera-position', '1 NaN 3', defPos);
    expectFallback('camera-position', '1 Infinity 3', defPos);
    expectFallback('camera-position', '', defPos);
  });

  it('camera-rotation clamps pitch to ±89.9 and wraps yaw', () => {
    expectOk('camera-rotation', '-90 0', [-90, 0]);
    expectFallback('camera-rotation', '10 95', [10, 89.9]);
    expectFallback('camera-rotation', '10 -95', [10, -89.9]);
    expectOk('camera-rotation', ' 370 0', [10, 0]);
    expectOk('camera-rotation', '-370 0', [-10, 0]);
    expectOk('camera-rotation', '720 5', [0, 5]);
    expectFallback('camera-rotation', '10', defRot);
    expectFallback('camera-rotation', 'left up', defRot);
  });
});

describe('controls', () => {
  it('is a mode keyword; the bare attribute (and its boolean forms) means flyby, absence no input', () => {
    expect(parse('controls', null).value).toBeNull();
    expectOk('controls', '', 'flyby');
    expectOk('controls', 'controls', 'flyby');
    expectOk('controls', 'true', 'flyby');
    expectOk('controls', ' Orbit ', 'orbit');
    expectOk('controls', 'trackball', 'trackball');
    expectFallback('controls', 'false', 'flyby'); // present: some input, with a warning
    expectFallback('controls', 'arcball', 'flyby');
    expect(spec('controls').format('orbit' as never)).toBe('orbit');
    expect(spec('controls').format(null as never)).toBeNull();
  });
});

describe('camera-target', () => {
  it('is "x y z" or absent; a bad value means no target, with a warning', () => {
    expect(parse('camera-target', null).value).toBeNull();
    expectOk('camera-target', '0 1 -2', [0, 1, -2]);
    expectFallback('camera-target', '0 1', null);
    expectFallback('camera-target', '', null);
    expectFallback('camera-target', '1e9 0 0', [1e7, 0, 0]);
  });
});

describe('propertyToRaw', () => {
  it('turns numbers, strings, arrays, booleans, null and objects into attribute strings', () => {
    expect(propertyToRaw(spec('transparency'), 0.25)).toBe('0.25');
    expect(propertyToRaw(spec('fresnel'), 'schlick')).toBe('schlick');
    expect(propertyToRaw(spec('camera-position'), [1, 2, 3])).toBe('1 2 3');
    expect(propertyToRaw(spec('camera-rotation'), [-90, 5])).toBe('-90 5');
    expect(propertyToRaw(spec('controls'), true)).toBe('');
    expect(propertyToRaw(spec('controls'), false)).toBeNull();
    expect(propertyToRaw(spec('controls'), 'trackball')).toBe('trackball');
    expect(propertyToRaw(spec('camera-target'), [0, 1, 2])).toBe('0 1 2');
    expect(propertyToRaw(spec('time'), null)).toBeNull();
    expect(propertyToRaw(spec('time'), undefined)).toBeNull();
    expect(propertyToRaw(spec('transparency'), true)).toBe('true');
  });

  it('round-trips property values through parse', () => {
    expect(parse('camera-position', propertyToRaw(spec('camera-position'), [4, -5, 6])).value).toEqual([4, -5, 6]);
    expect(parse('fov', propertyToRaw(spec('fov'), 75)).value).toBe(75);
    expect(parse('time', propertyToRaw(spec('time'), null)).value).toBeNull();
  });

  it('makes objects, functions and symbols unusable values that parse to a fallback', () => {
    for (const v of [{}, { x: 1 }, () => 1, Symbol('s'), new Map()]) {
      const raw = propertyToRaw(spec('transparency'), v);
      expect(typeof raw).toBe('string');
      expectFallback('transparency', raw!, 0.5);
      expectFallback('camera-position', propertyToRaw(spec('camera-position'), v)!, defaultAttributes().cameraPosition);
      expectFallback('fresnel', propertyToRaw(spec('fresnel'), v)!, 'exact');
    }
  });
});

describe('fuzz: parse never throws and always yields a usable value', () => {
  const hostile = [
    '', ' ', '\t\n', '\u00a0', '\u0000', '\u0000invalid', 'é', '∞', '１', '🙂', '\u202e1', '٣',
    'x'.repeat(10_000), '1 '.repeat(5_000), '9'.repeat(400), '1e309', '-1e309', '1e-400', '-0', '0x10', '0b11', '0o7',
    '  3  ', '3,', ',3', '1,,2,,3', '1 2 3 ', 'NaN NaN NaN', 'Infinity', '-Infinity', '+5', '.5', '5.', '1e', '--1',
    'null', 'undefined', 'true', '[1,2,3]', '{"x":1}', '<script>', 'EXACT', 'Reflection', '1 2 3\n', '1\t2\t3',
    '180 0', '-180 0', '1e300 1e300', '-1e300 -1e300', '1e7 -1e7 1e8', '5e-324 0 0',
  ];

  for (const s of ATTRIBUTES) {
    it(s.attribute, () => {
      for (const raw of hostile) {
        let r: Parsed<unknown> | undefined;
        expect(() => { r = s.parse(raw); }, `${s.attribute}="${raw.slice(0, 20)}"`).not.toThrow();
        const v = r!.value;
        if (r!.problem !== undefined) expect(typeof r!.problem).toBe('string');
        switch (s.property) {
          case 'controls': expect(['flyby', 'orbit', 'trackball']).toContain(v); break;
          case 'cameraTarget':
            if (v !== null) {
              expect(v).toHaveLength(3);
              for (const x of v as number[]) expect(Math.abs(x)).toBeLessThanOrEqual(1e7);
            }
            break;
          case 'fresnel': expect(['exact', 'schlick', 'classic']).toContain(v); break;
          case 'debugView': expect(DEBUG_VIEWS).toContain(v); break;
          case 'shading': expect(['phong', 'gouraud', 'flat']).toContain(v); break;
          case 'reflectionFormat': expect(['rgba8', 'rgba16f']).toContain(v); break;
          case 'colorSpace': expect(['srgb', 'none']).toContain(v); break;
          case 'toneMapping': expect(['auto', 'neutral', 'aces', 'none']).toContain(v); break;
          case 'environment': expect(typeof v === 'string' && v !== '' && v === (v as string).trim()).toBe(true); break;
          case 'roughnessQuality': expect(['low', 'medium', 'high']).toContain(v); break;
          case 'projection': expect(['perspective', 'orthographic']).toContain(v); break;
          case 'renderer': expect(['auto', 'webgl', 'software']).toContain(v); break;
          case 'samples': expect([0, 2, 4]).toContain(v); break;
          case 'refine': expect(Number.isInteger(v) && (v as number) >= 0 && (v as number) <= 1024).toBe(true); break;
          case 'tessellation':
            if (v !== 'auto') expect(Number.isInteger(v) && (v as number) >= 4 && (v as number) <= 512).toBe(true);
            break;
          case 'pixelRatio':
            if (v !== 'auto') expect((v as number) >= 0.25 && (v as number) <= 4).toBe(true);
            break;
          case 'time': expect(v === null || Number.isFinite(v)).toBe(true); break;
          case 'cameraSrc': case 'poster': expect(v === null || (typeof v === 'string' && v.trim() === v && v !== '')).toBe(true); break;
          case 'cameraPosition':
            expect(v).toHaveLength(3);
            for (const x of v as number[]) expect(Math.abs(x)).toBeLessThanOrEqual(1e7);
            break;
          case 'glassCenter': case 'glassNormal': case 'glassSize': case 'background': {
            const xs = v as number[];
            expect(xs).toHaveLength(s.property === 'glassSize' ? 2 : 3);
            for (const x of xs) expect(Number.isFinite(x)).toBe(true);
            if (s.property === 'glassNormal') expect(Math.hypot(...xs)).toBeCloseTo(1, 12);
            if (s.property === 'glassSize') for (const x of xs) expect(x).toBeGreaterThanOrEqual(0);
            if (s.property === 'background') for (const x of xs) expect(x >= 0 && x <= 1).toBe(true);
            break;
          }
          case 'cameraRotation': {
            const [yaw, pitch] = v as number[];
            expect(Number.isFinite(yaw)).toBe(true);
            expect(yaw).toBeGreaterThanOrEqual(-180);
            expect(yaw).toBeLessThanOrEqual(180);
            expect(Math.abs(pitch)).toBeLessThanOrEqual(PITCH_LIMIT);
            break;
          }
          default: {
            expect(Number.isFinite(v), `${s.attribute}="${raw.slice(0, 20)}" → ${String(v)}`).toBe(true);
            const range = { transparency: [0, 1], ior: [1, 10], fov: [1, 179], reflectionScale: [0.125, 2], environmentIntensity: [0, 64] }[s.property as string];
            if (range) {
              expect(v as number).toBeGreaterThanOrEqual(range[0]);
              expect(v as number).toBeLessThanOrEqual(range[1]);
            }
          }
        }
      }
    });
  }

  it('treats whitespace-padded numbers, -0 and hex as numbers', () => {
    expectOk('fov', '  3  ', 3);
    expectFallback('transparency', '0x10', 1);
    expect(parse('cube-distance', '-0').value).toBe(-0);
    expect(parse('camera-rotation', '-0 -0').value).toEqual([0, -0]);
  });
});

describe('glass and background (docs/element.md#attribute-table)', () => {
  it('defaults to the glass and background of the default scene (docs/default-scene.md)', () => {
    const d = defaultAttributes();
    expect(d.glassCenter).toEqual([0, 1, 0]);
    expect(d.glassNormal).toEqual([0, 0, 1]);
    expect(d.glassSize).toEqual([8, 4]);
    // Exactly 0.1, not the 26/255 an 8-bit round trip would give.
    expect(d.background).toEqual([0.1, 0.1, 0.1]);
    expectOk('background', 'rgb(25.5 25.5 25.5)', [0.1, 0.1, 0.1]);
  });

  it('normalises glass-normal; a zero or unusable vector falls back to +Z', () => {
    expectOk('glass-normal', '0 2 0', [0, 1, 0]);
    const r = parse('glass-normal', '3 0 4').value as number[];
    expect(r[0]).toBeCloseTo(0.6, 15);
    expect(r[2]).toBeCloseTo(0.8, 15);
    expectFallback('glass-normal', '0 0 0', [0, 0, 1]);
    expectFallback('glass-normal', '1 2', [0, 0, 1]);
  });

  it('reads glass-size "0 0" as a size (no glass), clamps negative sides to 0', () => {
    expectOk('glass-size', '0 0', [0, 0]);
    expectOk('glass-size', '2.5 1', [2.5, 1]);
    expectFallback('glass-size', '-1 3', [0, 3]);
    expectFallback('glass-size', '8', [8, 4]);
  });

  it('clamps glass-center like the camera position', () => {
    expectOk('glass-center', '1, 2, 3', [1, 2, 3]);
    expectFallback('glass-center', '1e9 0 0', [1e7, 0, 0]);
    expectFallback('glass-center', 'a b c', [0, 1, 0]);
  });

  it('parses the CSS colour forms without a canvas, and "r g b" in 0..1', () => {
    expectOk('background', '#fff', [1, 1, 1]);
    expectOk('background', '#FF000080', [1, 0, 0]);
    expectOk('background', 'rgba(0, 51, 255, 0.5)', [0, 0.2, 1]);
    expectOk('background', 'rgb(50% 0% 100% / 0.3)', [0.5, 0, 1]);
    expectOk('background', '0.25 0.5 1', [0.25, 0.5, 1]);
    // In Node there is no canvas: named colours are not known here (the browser knows them).
    expectFallback('background', 'not-a-colour', [0.1, 0.1, 0.1]);
    expectFallback('background', '#12', [0.1, 0.1, 0.1]);
    expectFallback('background', 'rgb(1 2)', [0.1, 0.1, 0.1]);
  });
});
