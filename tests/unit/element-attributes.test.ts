// The attribute table's parsers called directly (docs/element.md#attribute-table): every default, every range's
// boundaries (just inside, at, just outside), the fallbacks and the exact warning of each, and the formatters.
import { describe, expect, it } from 'vitest';
import { TONE_MAPPINGS } from '../../src/math/tone-map';
import {
  ATTRIBUTE_BY_NAME, ATTRIBUTES, DEFAULT_BACKGROUND, DEFAULT_CAMERA_POSITION, DEFAULT_CAMERA_ROTATION, DEFAULT_CUBE_DISTANCE,
  defaultAttributes, propertyToRaw, type AttributeSpec, type Parsed,
} from '../../src/element/attributes';

function spec(attribute: string): AttributeSpec {
  const s = ATTRIBUTE_BY_NAME.get(attribute);
  if (!s) throw new Error(`no attribute ${attribute}`);
  return s;
}

/** The whole outcome: the value, and the warning's exact text (undefined: no warning). */
function expectParse(attribute: string, raw: string | null, value: unknown, problem?: string): void {
  const r: Parsed<unknown> = spec(attribute).parse(raw);
  expect(r.value, `${attribute}=${JSON.stringify(raw)}`).toEqual(value);
  expect(r.problem, `${attribute}=${JSON.stringify(raw)} problem`).toBe(problem);
}

const format = (attribute: string, value: unknown) => spec(attribute).format(value as never);

describe('defaults (docs/element.md#attribute-table)', () => {
  it('has the exact documented value of every attribute', () => {
    expect(defaultAttributes()).toEqual({
      transparency: 0.5, cubeDistance: 0.75, ior: 1.5, fresnel: 'exact', cameraPosition: [3.6, 2.4, 0.2],
      cameraRotation: [-169, -23.6], fov: 60, projection: 'perspective', controls: null, renderer: 'auto', cameraTarget: null,
      cameraSrc: null, poster: null, spin: 0.8, time: null, debugView: 'none', reflectionScale: 1, samples: 4, refine: 10, shading: 'phong',
      tessellation: 'auto', pixelRatio: 'auto', reflectionFormat: 'rgba8', colorSpace: 'srgb', toneMapping: 'auto', exposure: 1, environment: 'neutral', environmentIntensity: 1, roughness: 0,
      roughnessQuality: 'medium', glassCenter: [0, 1, 0], glassNormal: [0, 0, 1], glassSize: [8, 4], background: [0.1, 0.1, 0.1],
    });
    expect(DEFAULT_CAMERA_POSITION).toEqual([3.6, 2.4, 0.2]);
    expect(DEFAULT_CAMERA_ROTATION).toEqual([-169, -23.6]);
    expect(DEFAULT_CUBE_DISTANCE).toBe(0.75);
    expect(DEFAULT_BACKGROUND).toBe('rgb(25.5 25.5 25.5)');
  });

  it('parses an absent attribute to its default, with no warning', () => {
    for (const s of ATTRIBUTES) {
      const r = s.parse(null);
      expect(r.value, s.attribute).toEqual(s.default);
      expect(r.problem, s.attribute).toBeUndefined();
    }
  });

  it('hands out a fresh copy of a tuple default on each fallback', () => {
    for (const name of ['camera-position', 'camera-rotation', 'glass-center', 'glass-normal', 'glass-size']) {
      const a = spec(name).parse('bad').value as number[];
      const b = spec(name).parse(null).value as number[];
      expect(a, name).not.toBe(spec(name).default);
      expect(b, name).not.toBe(spec(name).default);
      expect(a, name).not.toBe(b);
    }
  });
});

describe('numbers in a range', () => {
  it('transparency: 0..1, default 0.5', () => {
    expectParse('transparency', '0', 0);
    expectParse('transparency', '0.001', 0.001);
    expectParse('transparency', '-0.001', 0, 'below 0, clamped');
    expectParse('transparency', '0.999', 0.999);
    expectParse('transparency', '1', 1);
    expectParse('transparency', '1.001', 1, 'above 1, clamped');
    expectParse('transparency', '0.5px', 0.5, 'not a number, using 0.5');
    expectParse('transparency', 'NaN', 0.5, 'not a number, using 0.5');
    expectParse('transparency', '', 0.5, 'not a number, using 0.5');
    expectParse('transparency', ' ', 0.5, 'not a number, using 0.5');
    expectParse('transparency', ' \t\n ', 0.5, 'not a number, using 0.5');
    expectParse('transparency', '0 ', 0);
    expectParse('transparency', ' 1', 1);
  });

  it('ior: 1..10, default 1.5', () => {
    expectParse('ior', '0.999', 1, 'below 1, clamped');
    expectParse('ior', '1', 1);
    expectParse('ior', '10', 10);
    expectParse('ior', '10.001', 10, 'above 10, clamped');
    expectParse('ior', 'glass', 1.5, 'not a number, using 1.5');
  });

  it('fov: 1..179 degrees, default 60', () => {
    expectParse('fov', '0.999', 1, 'below 1, clamped');
    expectParse('fov', '1', 1);
    expectParse('fov', '179', 179);
    expectParse('fov', '179.001', 179, 'above 179, clamped');
    expectParse('fov', 'wide', 60, 'not a number, using 60');
  });

  it('environment: neutral, none or a URL as written, default neutral; environment-intensity: 0..64, default 1', () => {
    expectParse('environment', 'none', 'none');
    expectParse('environment', ' NEUTRAL ', 'neutral');
    expectParse('environment', ' None', 'none');
    expectParse('environment', null, 'neutral');
    expectParse('environment', '  ', 'neutral');
    // Anything else is a URL (relative to the page), trimmed, its case kept: a word that is no file fails as a load does.
    expectParse('environment', ' skies/Venice Sunset.HDR ', 'skies/Venice Sunset.HDR');
    expectParse('environment', 'studio', 'studio');
    expectParse('environment-intensity', '0', 0);
    expectParse('environment-intensity', '2.5', 2.5);
    expectParse('environment-intensity', '-1', 0, 'below 0, clamped');
    expectParse('environment-intensity', '65', 64, 'above 64, clamped');
    expectParse('environment-intensity', 'bright', 1, 'not a number, using 1');
  });

  it('exposure: 0..64, default 1', () => {
    expectParse('exposure', '-0.001', 0, 'below 0, clamped');
    expectParse('exposure', '0', 0);
    expectParse('exposure', '2.5', 2.5);
    expectParse('exposure', '64', 64);
    expectParse('exposure', '64.001', 64, 'above 64, clamped');
    expectParse('exposure', 'Infinity', 64, 'above 64, clamped');
    expectParse('exposure', 'bright', 1, 'not a number, using 1');
  });

  it('reflection-scale: 0.125..2, default 1', () => {
    expectParse('reflection-scale', '0.124', 0.125, 'below 0.125, clamped');
    expectParse('reflection-scale', '0.125', 0.125);
    expectParse('reflection-scale', '2', 2);
    expectParse('reflection-scale', '2.001', 2, 'above 2, clamped');
    expectParse('reflection-scale', 'x', 1, 'not a number, using 1');
  });

  it('roughness: 0..1, default 0', () => {
    expectParse('roughness', '-0.001', 0, 'below 0, clamped');
    expectParse('roughness', '0.3', 0.3);
    expectParse('roughness', '1.001', 1, 'above 1, clamped');
    expectParse('roughness', '', 0, 'not a number, using 0');
  });
});

describe('finite numbers', () => {
  it('cube-distance: any finite number within ±1e7, default 0.75', () => {
    expectParse('cube-distance', '1e7', 1e7);
    expectParse('cube-distance', '-1e7', -1e7);
    expectParse('cube-distance', '10000001', 1e7, 'beyond ±10000000, clamped');
    expectParse('cube-distance', '-10000001', -1e7, 'beyond ±10000000, clamped');
    expectParse('cube-distance', 'Infinity', 0.75, 'not a finite number, using 0.75');
    expectParse('cube-distance', '-Infinity', 0.75, 'not a finite number, using 0.75');
    expectParse('cube-distance', '', 0.75, 'not a finite number, using 0.75');
    expectParse('cube-distance', '1m', 0.75, 'not a finite number, using 0.75');
  });

  it('spin: any finite number of rad/s, default 0.8', () => {
    expectParse('spin', '0', 0);
    expectParse('spin', '-1.7976931348623157e308', -Number.MAX_VALUE);
    expectParse('spin', '1.7976931348623157e308', Number.MAX_VALUE);
    expectParse('spin', '1e309', 0.8, 'not a finite number, using 0.8');
    expectParse('spin', 'fast', 0.8, 'not a finite number, using 0.8');
  });

  it('time: finite seconds, else the live clock', () => {
    expectParse('time', '0', 0);
    expectParse('time', '-3.25', -3.25);
    expectParse('time', 'Infinity', null, 'not a finite number, using the live clock');
    expectParse('time', '  ', null, 'not a finite number, using the live clock');
    expect(format('time', 0)).toBe('0');
    expect(format('time', 12.5)).toBe('12.5');
    expect(format('time', null)).toBeNull();
  });
});

describe('samples: 0, 2 or 4, the nearest at or below', () => {
  it('keeps the allowed counts and rounds others down with a warning', () => {
    expectParse('samples', '0', 0);
    expectParse('samples', '2', 2);
    expectParse('samples', '4', 4);
    expectParse('samples', '5', 4, 'expected 0, 2 or 4; using 4');
    expectParse('samples', '3.999', 2, 'expected 0, 2 or 4; using 2');
    expectParse('samples', '1.999', 0, 'expected 0, 2 or 4; using 0');
    expectParse('samples', '-1', 0, 'expected 0, 2 or 4; using 0');
    expectParse('samples', 'many', 4, 'expected 0, 2 or 4; using 4');
    expectParse('samples', '', 4, 'expected 0, 2 or 4; using 4');
    expect(format('samples', 2)).toBe('2');
  });
});

describe('refine: a whole number of frames, 0..1024', () => {
  it('keeps whole numbers in range, rounds and clamps others with a warning, and falls back to the default on words', () => {
    expectParse('refine', '0', 0);
    expectParse('refine', '10', 10);
    expectParse('refine', '1024', 1024);
    expectParse('refine', '2.5', 3, 'expected a whole number of frames 0..1024; using 3');
    expectParse('refine', '9.4', 9, 'expected a whole number of frames 0..1024; using 9');
    expectParse('refine', '1025', 1024, 'expected a whole number of frames 0..1024; using 1024');
    expectParse('refine', '-1', 0, 'expected a whole number of frames 0..1024; using 0');
    expectParse('refine', 'Infinity', 1024, 'expected a whole number of frames 0..1024; using 1024');
    expectParse('refine', 'lots', 10, 'not a number, using 10');
    expectParse('refine', '', 10, 'not a number, using 10');
    expectParse('refine', null, 10);
    expect(format('refine', 82)).toBe('82');
  });
});

describe('auto or a number', () => {
  it('tessellation: auto or an integer 4..512, rounded', () => {
    expectParse('tessellation', 'auto', 'auto');
    expectParse('tessellation', ' AuTo ', 'auto');
    expectParse('tessellation', '3.4', 4, 'below 4, clamped');
    expectParse('tessellation', '3.5', 4);
    expectParse('tessellation', '4', 4);
    expectParse('tessellation', '33.6', 34);
    expectParse('tessellation', '512', 512);
    expectParse('tessellation', '512.4', 512);
    expectParse('tessellation', '512.5', 512, 'above 512, clamped');
    expectParse('tessellation', 'many', 'auto', 'expected a number or auto, using auto');
    expectParse('tessellation', '', 'auto', 'expected a number or auto, using auto');
    expect(format('tessellation', 'auto')).toBe('auto');
    expect(format('tessellation', 64)).toBe('64');
  });

  it('pixel-ratio: auto or a number 0.25..4, not rounded', () => {
    expectParse('pixel-ratio', 'AUTO', 'auto');
    expectParse('pixel-ratio', '0.249', 0.25, 'below 0.25, clamped');
    expectParse('pixel-ratio', '0.25', 0.25);
    expectParse('pixel-ratio', '1.5', 1.5);
    expectParse('pixel-ratio', '4', 4);
    expectParse('pixel-ratio', '4.001', 4, 'above 4, clamped');
    expectParse('pixel-ratio', '2x', 'auto', 'expected a number or auto, using auto');
  });
});

describe('keywords: trimmed, any case, else the first with a warning', () => {
  const cases: [string, string[]][] = [
    ['fresnel', ['exact', 'schlick', 'classic']],
    ['projection', ['perspective', 'orthographic']],
    ['renderer', ['auto', 'webgl', 'software']],
    ['debug-view', ['none', 'reflection', 'scene', 'fresnel', 'passes']],
    ['shading', ['phong', 'gouraud', 'flat']],
    ['reflection-format', ['rgba8', 'rgba16f']],
    ['color-space', ['srgb', 'none']],
    ['tone-mapping', ['auto', ...TONE_MAPPINGS]],
    ['roughness-quality', ['medium', 'low', 'high']],
  ];
  for (const [name, words] of cases) {
    it(name, () => {
      for (const w of words) {
        expectParse(name, w, w);
        expectParse(name, ` ${w.toUpperCase()} `, w);
        expect(format(name, w)).toBe(w);
      }
      const problem = `expected one of ${words.join(', ')}; using ${words[0]}`;
      expectParse(name, 'other', words[0], problem);
      expectParse(name, '', words[0], problem);
      expectParse(name, `${words[1]}x`, words[0], problem);
    });
  }
});

describe('controls', () => {
  it('is flyby when bare (or a boolean form), a mode, or flyby with a warning', () => {
    expectParse('controls', null, null);
    for (const raw of ['', '  ', 'true', 'TRUE', ' Controls ']) expectParse('controls', raw, 'flyby');
    expectParse('controls', 'ORBIT', 'orbit');
    expectParse('controls', 'flyby', 'flyby');
    expectParse('controls', 'trackball', 'trackball');
    expectParse('controls', 'false', 'flyby', 'expected one of flyby, orbit, trackball; using flyby');
    expect(format('controls', 'trackball')).toBe('trackball');
    expect(format('controls', null)).toBeNull();
  });
});

describe('tuples', () => {
  it('camera-position: "x y z" within ±1e7', () => {
    expectParse('camera-position', '1 2 3', [1, 2, 3]);
    expectParse('camera-position', '1,2,3', [1, 2, 3]);
    expectParse('camera-position', '\t1  ,  2\n3 ', [1, 2, 3]);
    expectParse('camera-position', '1e7 -1e7 0', [1e7, -1e7, 0]);
    expectParse('camera-position', '10000001 -10000001 5', [1e7, -1e7, 5], 'coordinates clamped to ±10000000');
    const problem = 'expected "x y z", using "3.6 2.4 0.2"';
    expectParse('camera-position', '1 2', [3.6, 2.4, 0.2], problem);
    expectParse('camera-position', '1 2 3 4', [3.6, 2.4, 0.2], problem);
    expectParse('camera-position', '1 2 x', [3.6, 2.4, 0.2], problem);
    expectParse('camera-position', 'x 2 3', [3.6, 2.4, 0.2], problem);
    expectParse('camera-position', '1  3', [3.6, 2.4, 0.2], problem);
    expectParse('camera-position', '', [3.6, 2.4, 0.2], problem);
    expect(format('camera-position', [1, -2, 0.5])).toBe('1 -2 0.5');
  });

  it('camera-rotation: "yaw pitch", yaw wrapped, pitch clamped to ±89.9', () => {
    expectParse('camera-rotation', '190 89.9', [-170, 89.9]);
    expectParse('camera-rotation', '0 -89.9', [0, -89.9]);
    expectParse('camera-rotation', '0 89.91', [0, 89.9], 'pitch clamped to ±89.9');
    expectParse('camera-rotation', '0 -89.91', [0, -89.9], 'pitch clamped to ±89.9');
    const problem = 'expected "yaw pitch", using the default view';
    expectParse('camera-rotation', '1 2 3', [-169, -23.6], problem);
    expectParse('camera-rotation', '1', [-169, -23.6], problem);
    expectParse('camera-rotation', '1 Infinity', [-169, -23.6], problem);
    expect(format('camera-rotation', [10, -5])).toBe('10 -5');
  });

  it('camera-target: "x y z" within ±1e7, else no target', () => {
    expectParse('camera-target', '0 1 -2', [0, 1, -2]);
    expectParse('camera-target', '0 -1e8 2', [0, -1e7, 2], 'coordinates clamped to ±10000000');
    expectParse('camera-target', '0 1 2 3', null, 'expected "x y z", using no target');
    expectParse('camera-target', 'here', null, 'expected "x y z", using no target');
    expect(format('camera-target', [0, 1, -2])).toBe('0 1 -2');
    expect(format('camera-target', null)).toBeNull();
  });

  it('glass-center: "x y z" within ±1e7, default "0 1 0"', () => {
    expectParse('glass-center', '-2 0 3', [-2, 0, 3]);
    expectParse('glass-center', '0 0 1e9', [0, 0, 1e7], 'coordinates clamped to ±10000000');
    expectParse('glass-center', '0 0', [0, 1, 0], 'expected "x y z", using "0 1 0"');
    expect(format('glass-center', [0, 1, 0])).toBe('0 1 0');
  });

  it('glass-normal: normalised; zero or overflowing falls back to "0 0 1"', () => {
    expectParse('glass-normal', '0 -3 0', [0, -1, 0]);
    expectParse('glass-normal', '0 0 0.5', [0, 0, 1]);
    const unusable = 'not a usable direction, using "0 0 1"';
    expectParse('glass-normal', '0 0 0', [0, 0, 1], unusable);
    expectParse('glass-normal', '1.5e308 1.5e308 0', [0, 0, 1], unusable);
    expectParse('glass-normal', '0 0', [0, 0, 1], 'expected "x y z", using "0 0 1"');
  });

  it('glass-size: "w h", negative sides clamped to 0, sides above 1e7 clamped', () => {
    expectParse('glass-size', '0 0', [0, 0]);
    expectParse('glass-size', '1e7 3', [1e7, 3]);
    expectParse('glass-size', '3 -0.5', [3, 0], 'negative size clamped to 0');
    expectParse('glass-size', '-1 2', [0, 2], 'negative size clamped to 0');
    expectParse('glass-size', '10000001 3', [1e7, 3], 'size clamped to 10000000');
    // A negative side does not spare the other its cap.
    expectParse('glass-size', '1e300 -1', [1e7, 0], 'negative size clamped to 0, size clamped to 10000000');
    expectParse('glass-size', '1 2 3', [8, 4], 'expected "w h", using "8 4"');
    expect(format('glass-size', [8, 4])).toBe('8 4');
  });
});

describe('urls and colours', () => {
  it('camera-src and poster: the trimmed URL, or none when blank', () => {
    for (const name of ['camera-src', 'poster']) {
      expectParse(name, ' a/b.cfg ', 'a/b.cfg');
      expectParse(name, '', null);
      expectParse(name, ' \t', null);
      expect(format(name, 'x.png')).toBe('x.png');
      expect(format(name, null)).toBeNull();
    }
  });

  it('background: a CSS colour, else the 0.1 grey with a warning', () => {
    expectParse('background', '#000', [0, 0, 0]);
    expectParse('background', 'no', [0.1, 0.1, 0.1], 'not a CSS colour, using rgb(25.5 25.5 25.5)');
    expect(format('background', [0, 0.5, 1])).toBe('0 0.5 1');
  });

  it('formats numbers with String', () => {
    for (const name of ['transparency', 'ior', 'fov', 'cube-distance', 'spin', 'reflection-scale', 'roughness', 'pixel-ratio']) {
      expect(format(name, 0.75), name).toBe('0.75');
    }
  });
});

describe('propertyToRaw', () => {
  it('turns each kind of property value into its attribute string', () => {
    expect(propertyToRaw(spec('transparency'), null)).toBeNull();
    expect(propertyToRaw(spec('transparency'), undefined)).toBeNull();
    expect(propertyToRaw(spec('controls'), true)).toBe('');
    expect(propertyToRaw(spec('controls'), false)).toBeNull();
    expect(propertyToRaw(spec('controls'), 'orbit')).toBe('orbit');
    expect(propertyToRaw(spec('shading'), false)).toBe('false');
    expect(propertyToRaw(spec('shading'), true)).toBe('true');
    expect(propertyToRaw(spec('glass-size'), [1, 2.5])).toBe('1 2.5');
    expect(propertyToRaw(spec('camera-src'), ['a', null])).toBe('a null');
    expect(propertyToRaw(spec('fov'), 45)).toBe('45');
    expect(propertyToRaw(spec('fov'), 'wide')).toBe('wide');
    expect(propertyToRaw(spec('fov'), 10n)).toBe('\u0000invalid');
    expect(propertyToRaw(spec('fov'), {})).toBe('\u0000invalid');
  });
});
