// THE attribute table of <glass-object> (docs/scene-model.md#glass-object): every row's name, default, range and
// fallback. Material rows default to null, meaning "the MTL's value, else the default", so
// that an attribute wins over the MTL and the MTL over the default (nothing is written back).
import { MAPPINGS, type Mapping, type Vec3 } from '../../scene/scene';
import { MAX_RESOLUTION, MIN_RESOLUTION } from '../../scene/geometry/gaussian';
import { clampedNumber, flag, keyword, truth, url, vec3, type ChildAttributeSpec } from './child-attribute-spec';

export const SHAPES = ['cube', 'sphere', 'gaussian'] as const;
export type Shape = (typeof SHAPES)[number];

export interface ObjectAttributes {
  src: string | null;
  shape: Shape | null;
  resolution: number;
  position: Vec3;
  rotation: Vec3;
  scale: Vec3;
  /** Property `normalizeModel`: `normalize()` is a DOM method every element already has. */
  normalizeModel: boolean;
  ambient: Vec3 | null;
  diffuse: Vec3 | null;
  specular: Vec3 | null;
  shininess: number | null;
  opacity: number | null;
  texture: string | null;
  mapping: Mapping | null;
  /** False keeps the object out of the glass's reflection. */
  reflect: boolean;
}

/** Material values of an object with neither attribute nor MTL value (docs/scene-model.md#glass-object). */
export const OBJECT_DEFAULTS = {
  ambient: [0.2, 0.2, 0.2] as Vec3,
  diffuse: [0.8, 0.8, 0.8] as Vec3,
  specular: [0.5, 0.5, 0.5] as Vec3,
  shininess: 32,
  opacity: 1,
} as const;

const colour = (property: 'ambient' | 'diffuse' | 'specular', attribute: string, what: string, def: Vec3) =>
  vec3(property, attribute, null, `"r g b" 0..1, ${what}; the MTL's value, else "${def.join(' ')}"`, { min: 0, max: 1 });

type Row = { [K in keyof ObjectAttributes]: ChildAttributeSpec<ObjectAttributes[K], K> }[keyof ObjectAttributes];

export const OBJECT_ATTRIBUTES: readonly Row[] = [
  url('src', 'src', 'URL of an .obj model (its mtllib resolved against it) or a course .byu (mesh or Bézier surface); the format is sniffed from the content'),
  keyword('shape', 'shape', SHAPES, null, 'cube (edge 1), sphere (radius 0.5) or gaussian; cube when there is no src, ignored when there is'),
  clampedNumber('resolution', 'resolution', 40, MIN_RESOLUTION, MAX_RESOLUTION, 'N×N vertices of the gaussian grid; when set, E of a Bézier .byu (the file\'s E otherwise)', true) as ChildAttributeSpec<number, 'resolution'>,
  vec3('position', 'position', [0, 0, 0], '"x y z" of the object\'s origin') as ChildAttributeSpec<Vec3, 'position'>,
  vec3('rotation', 'rotation', [0, 0, 0], '"x y z" in degrees, applied X then Y then Z') as ChildAttributeSpec<Vec3, 'rotation'>,
  vec3('scale', 'scale', [1, 1, 1], 'one number or "x y z"', { single: true }) as ChildAttributeSpec<Vec3, 'scale'>,
  flag('normalizeModel', 'normalize', 'centre the model on the origin and scale its longest side to 2, before the transform'),
  colour('ambient', 'ambient', 'Ka', OBJECT_DEFAULTS.ambient),
  colour('diffuse', 'diffuse', 'Kd', OBJECT_DEFAULTS.diffuse),
  colour('specular', 'specular', 'Ks', OBJECT_DEFAULTS.specular),
  clampedNumber('shininess', 'shininess', null, 0, 10000, 'Blinn-Phong exponent 0..10000; the MTL\'s Ns, else 32'),
  clampedNumber('opacity', 'opacity', null, 0, 1, '1 − kt, 0..1; the MTL\'s d, else 1'),
  url('texture', 'texture', 'URL of an image multiplying Ka and Kd; the MTL\'s map_Kd, else the procedural texture'),
  keyword('mapping', 'mapping', MAPPINGS, null, 'uv, triplanar, cylindrical or spherical; uv where the model has UVs, else spherical'),
  truth('reflect', 'reflect', true, '"false" keeps the object out of the glass\'s reflection (it is drawn everywhere else)'),
];

export function defaultObjectAttributes(): ObjectAttributes {
  const out: Record<string, unknown> = {};
  for (const s of OBJECT_ATTRIBUTES) out[s.property] = s.parse(null).value;
  return out as unknown as ObjectAttributes;
}
