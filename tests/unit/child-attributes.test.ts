// The children's attribute tables (<glass-object>, <glass-light>) and what they turn into:
// defaults of docs/scene-model.md#glass-object, fallbacks with a problem, never a throw; materials by precedence.
import { describe, expect, it } from 'vitest';
import { OBJECT_ATTRIBUTES, OBJECT_DEFAULTS, defaultObjectAttributes } from '../../src/element/children/object-attributes';
import { LIGHT_ATTRIBUTES, defaultLightAttributes } from '../../src/element/children/light-attributes';
import type { ChildAttributeSpec } from '../../src/element/children/child-attribute-spec';
import { resolveMaterial } from '../../src/element/children/object-material';
import { builtinShape } from '../../src/element/children/builtin-shapes';
import { gaussianMesh } from '../../src/scene/geometry/gaussian';
import { boundingSphere } from '../../src/element/children/mesh-parts';
import { DEFAULT_LIGHT } from '../../src/scene/default-scene';

const rows = [...OBJECT_ATTRIBUTES, ...LIGHT_ATTRIBUTES] as ChildAttributeSpec[];
const row = (table: readonly ChildAttributeSpec[], attribute: string) => {
  const s = table.find((r) => r.attribute === attribute);
  if (!s) throw new Error(attribute);
  return s;
};
const obj = (a: string) => row(OBJECT_ATTRIBUTES as readonly ChildAttributeSpec[], a);
const light = (a: string) => row(LIGHT_ATTRIBUTES as readonly ChildAttributeSpec[], a);

describe('<glass-object> table', () => {
  it('declares exactly the attributes of docs/scene-model.md#glass-object', () => {
    expect(OBJECT_ATTRIBUTES.map((r) => r.attribute).sort()).toEqual([
      'ambient', 'diffuse', 'mapping', 'normalize', 'opacity', 'position', 'reflect', 'resolution', 'rotation', 'scale',
      'shape', 'shininess', 'specular', 'src', 'texture',
    ]);
  });

  it('has the defaults of docs/scene-model.md#glass-object', () => {
    const d = defaultObjectAttributes();
    expect(d).toMatchObject({ src: null, shape: null, resolution: 40, position: [0, 0, 0], rotation: [0, 0, 0], scale: [1, 1, 1], normalizeModel: false, reflect: true });
    // Material rows are null: the MTL's value, else OBJECT_DEFAULTS.
    expect([d.ambient, d.diffuse, d.specular, d.shininess, d.opacity, d.texture, d.mapping]).toEqual([null, null, null, null, null, null, null]);
  });

  it('parses good values without a problem', () => {
    expect(obj('scale').parse('2')).toEqual({ value: [2, 2, 2] });
    expect(obj('scale').parse('1 2 3')).toEqual({ value: [1, 2, 3] });
    expect(obj('position').parse(' 1, -2 ,3e-1 ')).toEqual({ value: [1, -2, 0.3] });
    expect(obj('shape').parse(' Sphere ')).toEqual({ value: 'sphere' });
    expect(obj('resolution').parse('400')).toEqual({ value: 400 });
    expect(obj('diffuse').parse('0.2 0.5 0.9')).toEqual({ value: [0.2, 0.5, 0.9] });
    expect(obj('normalize').parse('')).toEqual({ value: true });
    expect(obj('src').parse(' models/a.obj ')).toEqual({ value: 'models/a.obj' });
    expect([' FALSE ', 'false', 'true', ''].map((raw) => obj('reflect').parse(raw))).toEqual([{ value: false }, { value: false }, { value: true }, { value: true }]);
  });

  it('falls back with a problem: clamps ranges, defaults the unusable', () => {
    const bad = (a: string, raw: string, value: unknown) => {
      const r = obj(a).parse(raw);
      expect(r.value, `${a}="${raw}"`).toEqual(value);
      expect(r.problem, `${a}="${raw}"`).toMatch(/./);
    };
    bad('reflect', 'no', true);
    bad('shininess', '20000', 10000);
    bad('shininess', 'shiny', null);
    bad('opacity', '-1', 0);
    bad('resolution', '1', 2);
    bad('resolution', '5000', 1024);
    bad('diffuse', '2 0.5 0.5', [1, 0.5, 0.5]);
    bad('diffuse', '0.5', null);
    bad('scale', '1 2', [1, 1, 1]);
    bad('position', '1 2 NaN', [0, 0, 0]);
    bad('rotation', '0x10 0 0', [0, 0, 0]);
    bad('shape', 'teapot', null);
    bad('mapping', 'cubic', null);
  });
});

describe('<glass-light> table', () => {
  it('defaults to the intensities of the default light (Ia 0.15, Id 0.85, Is 1)', () => {
    const d = defaultLightAttributes();
    expect(d).toEqual({ src: null, position: null, direction: null, ambient: DEFAULT_LIGHT.ambient, diffuse: DEFAULT_LIGHT.diffuse, specular: DEFAULT_LIGHT.specular });
    expect(DEFAULT_LIGHT.ambient).toEqual([0.15, 0.15, 0.15]);
  });

  it('allows intensities above 1, not below 0; a zero direction falls back', () => {
    expect(light('diffuse').parse('2 2 2')).toEqual({ value: [2, 2, 2] });
    expect(light('diffuse').parse('-1 0 0').problem).toMatch(/clamped/);
    const z = light('direction').parse('0 0 0');
    expect(z.value).toBeNull();
    expect(z.problem).toMatch(/zero/);
  });
});

describe('every child row', () => {
  const hostile = ['', ' ', 'NaN', 'Infinity', '-Infinity', '1e400', '0x1f', '١', '<b>', 'null', '1 2 3 4', '\u0000', 'x'.repeat(10000)];
  for (const s of rows) {
    it(`${s.attribute} never throws and documents itself`, () => {
      expect(s.doc.length).toBeGreaterThan(0);
      expect(s.parse(null)).toEqual({ value: s.default });
      for (const raw of hostile) {
        const r = s.parse(raw);
        if (Array.isArray(r.value)) for (const x of r.value) expect(Number.isFinite(x)).toBe(true);
        if (typeof r.value === 'number') expect(Number.isFinite(r.value)).toBe(true);
      }
    });
  }
});

describe('materials: attribute over MTL over default', () => {
  const none = { ambient: null, diffuse: null, specular: null, shininess: null, opacity: null, texture: null, mapping: null };
  it('uses the defaults with neither', () => {
    expect(resolveMaterial(none, undefined, true, null)).toEqual({
      ambient: OBJECT_DEFAULTS.ambient, diffuse: OBJECT_DEFAULTS.diffuse, specular: OBJECT_DEFAULTS.specular,
      shininess: 32, opacity: 1, texture: { kind: 'procedural' }, mapping: 'uv',
    });
    expect(resolveMaterial(none, undefined, false, null).mapping).toBe('spherical');
  });

  it('takes the MTL over the default and the attribute over the MTL', () => {
    const mtl = { diffuse: [1, 0, 0] as const, shininess: 10, opacity: 0.5, texture: 'http://x/t.png', ambient: [0, 0, 1] as const };
    const m = resolveMaterial({ ...none, diffuse: [0, 1, 0], shininess: 99 }, mtl, true, null);
    expect(m.diffuse).toEqual([0, 1, 0]);
    expect(m.shininess).toBe(99);
    expect(m.ambient).toEqual([0, 0, 1]);
    expect(m.opacity).toBe(0.5);
    expect(m.texture).toEqual({ kind: 'image', url: 'http://x/t.png' });
    expect(m.specular).toEqual(OBJECT_DEFAULTS.specular);
    expect(resolveMaterial(none, mtl, true, 'http://y/own.png').texture).toEqual({ kind: 'image', url: 'http://y/own.png' });
    expect(resolveMaterial({ ...none, mapping: 'triplanar' }, mtl, false, null).mapping).toBe('triplanar');
  });
});

describe('built-in shapes', () => {
  it('are a unit cube, a sphere of radius 0.5 and the gaussian, with containing bounds', () => {
    expect(builtinShape('cube', 40)).toEqual({ geometry: { kind: 'box', size: 1 }, bounds: { center: [0, 0, 0], radius: Math.sqrt(3) / 2 } });
    expect(builtinShape('sphere', 40)).toEqual({ geometry: { kind: 'sphere', radius: 0.5 }, bounds: { center: [0, 0, 0], radius: 0.5 } });
    const g = builtinShape('gaussian', 17);
    expect(g.geometry).toEqual({ kind: 'gaussian', resolution: 17 });
    // Every vertex of the generated surface lies inside the declared sphere.
    const p = gaussianMesh(17).positions;
    const c = g.bounds.center;
    let far = 0;
    for (let i = 0; i < p.length; i += 3) far = Math.max(far, Math.hypot(p[i] - c[0], p[i + 1] - c[1], p[i + 2] - c[2]));
    expect(far).toBeLessThanOrEqual(g.bounds.radius + 1e-6);
    // …and it is not a loose one: the tightest sphere is hardly smaller.
    expect(boundingSphere(p).radius).toBeGreaterThan(g.bounds.radius * 0.99);
  });
});

describe('the course lighting file in the scene terms (docs/course-files.md#lighting-file)', () => {
  it('maps ka, kd·Od, ks, n onto Ka, Kd, Ks and a Blinn exponent 4n; Ia/255 and Il/255 onto the point light', async () => {
    const { courseMaterialValues, courseLight } = await import('../../src/element/children/course-lighting');
    const m = courseMaterialValues({ ka: 0.2, kd: 0.5, ks: 0.3, od: [0.7, 0.5, 0.8], n: 2 });
    expect(m.ambient).toEqual([0.2, 0.2, 0.2]);
    expect(m.diffuse).toEqual([0.35, 0.25, 0.4]);
    expect(m.specular).toEqual([0.3, 0.3, 0.3]);
    expect(m.shininess).toBe(8);
    expect(courseMaterialValues({ ka: 0, kd: 0, ks: 0, od: [0, 0, 0], n: 1e9 }).shininess).toBe(10000);
    expect(courseLight({ position: [1, 2, 3], ambient: [255, 0, 51], intensity: [255, 255, 0] })).toEqual({
      kind: 'point', vector: [1, 2, 3], ambient: [1, 0, 0.2], diffuse: [1, 1, 0], specular: [1, 1, 0],
    });
  });

  it('puts the file below the attribute and the MTL, above the default; .byu objects are plain', async () => {
    const { resolveMaterial } = await import('../../src/element/children/object-material');
    const none = { ambient: null, diffuse: null, specular: null, shininess: null, opacity: null, texture: null, mapping: null };
    const file = { ambient: [0.2, 0.2, 0.2] as const, diffuse: [0.35, 0.25, 0.4] as const, shininess: 8 };
    const m = resolveMaterial({ ...none, diffuse: [0.1, 0.9, 0.1] }, { shininess: 50 }, false, null, { file, plain: true });
    expect(m.diffuse).toEqual([0.1, 0.9, 0.1]); // attribute
    expect(m.shininess).toBe(50); // MTL
    expect(m.ambient).toEqual([0.2, 0.2, 0.2]); // file
    expect(m.specular).toEqual([0.5, 0.5, 0.5]); // default
    expect(m.texture).toEqual({ kind: 'none' });
    expect(resolveMaterial(none, undefined, false, 'http://x/t.png', { plain: true }).texture).toEqual({ kind: 'image', url: 'http://x/t.png', fallback: 'none' });
    expect(resolveMaterial(none, undefined, true, null).texture).toEqual({ kind: 'procedural' });
  });
});
