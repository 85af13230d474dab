// THE attribute table of <glass-light> (docs/scene-model.md#glass-light). The defaults make one child light the default
// light of docs/default-scene.md#the-light exactly: directional towards normalize(0.4, 1, 0.6), Ia 0.15, Id 0.85, Is 1.
import { DEFAULT_LIGHT } from '../../scene/default-scene';
import type { Vec3 } from '../../scene/scene';
import { url, vec3, type ChildAttributeSpec } from './child-attribute-spec';

export interface LightAttributes {
  /** The course's iluminacao.txt (docs/course-files.md#lighting-file): its point light and the element's material. */
  src: string | null;
  /** A point light here, or null. */
  position: Vec3 | null;
  /** Towards a directional light (normalised when read), or null. */
  direction: Vec3 | null;
  ambient: Vec3;
  diffuse: Vec3;
  specular: Vec3;
}

/** Intensities above 1 are allowed (docs/scene-model.md#lights); this only keeps them finite in float32. */
const MAX_INTENSITY = 1e6;

const intensity = (property: 'ambient' | 'diffuse' | 'specular', what: string, def: Vec3) =>
  vec3(property, property, def, `"r g b" ≥ 0, ${what} (above 1 allowed)`, { min: 0, max: MAX_INTENSITY }) as ChildAttributeSpec<Vec3, typeof property>;

type Row = { [K in keyof LightAttributes]: ChildAttributeSpec<LightAttributes[K], K> }[keyof LightAttributes];

export const LIGHT_ATTRIBUTES: readonly Row[] = [
  url('src', 'src', "URL of the course's iluminacao.txt: a point light at Pl, and the material of the element's objects; attributes win over the file"),
  vec3('position', 'position', null, '"x y z": a point light there (wins over direction)'),
  vec3('direction', 'direction', null, '"x y z" towards a directional light; neither: the default light\'s direction', { nonZero: true }),
  intensity('ambient', 'Ia', DEFAULT_LIGHT.ambient),
  intensity('diffuse', 'Id', DEFAULT_LIGHT.diffuse),
  intensity('specular', 'Is', DEFAULT_LIGHT.specular),
];

export function defaultLightAttributes(): LightAttributes {
  const out: Record<string, unknown> = {};
  for (const s of LIGHT_ATTRIBUTES) out[s.property] = s.parse(null).value;
  return out as unknown as LightAttributes;
}
