// <glass-light>: one light of the scene (SPEC §9). `position` makes a point light, `direction` a
// directional one; with neither it is the default light of SPEC §3 (with its own intensities).
import { DEFAULT_LIGHT } from '../../scene/default-scene';
import type { Light, Vec3 } from '../../scene/scene';
import { AttributeWarnings } from '../warnings';
import { ChildElement, defineChildProperties } from './child-element';
import { defaultLightAttributes, LIGHT_ATTRIBUTES, type LightAttributes } from './light-attributes';

export const LIGHT_TAG = 'glass-light';
const conflicts = new AttributeWarnings();

export interface GlassLight extends LightAttributes {}

/**
 * One light of the scene (SPEC §9), a child of `<glass-plane-scene>`: `position` makes a point
 * light, `direction` a directional one; with neither it is the default light of SPEC §3.
 * Every attribute is also a property.
 *
 * @tagname glass-light
 * @attr {string} [position=null] - "x y z": a point light there (wins over direction)
 * @attr {string} [direction=null] - "x y z" towards a directional light; neither: the default light's direction
 * @attr {string} [ambient="0.15 0.15 0.15"] - "r g b" ≥ 0, Ia (above 1 allowed)
 * @attr {string} [diffuse="0.85 0.85 0.85"] - "r g b" ≥ 0, Id (above 1 allowed)
 * @attr {string} [specular="1 1 1"] - "r g b" ≥ 0, Is (above 1 allowed)
 */
export class GlassLight extends ChildElement<LightAttributes> {
  static get observedAttributes(): string[] {
    return LIGHT_ATTRIBUTES.map((a) => a.attribute);
  }

  constructor() {
    super(LIGHT_TAG, LIGHT_ATTRIBUTES, defaultLightAttributes());
  }

  protected override attributeParsed(property: string): void {
    if ((property === 'position' || property === 'direction') && this.values.position && this.values.direction) {
      conflicts.report({ attribute: 'direction' }, this.getAttribute('direction') ?? '', 'position is set too: a point light, direction ignored', LIGHT_TAG);
    }
    super.attributeParsed(property);
  }

  /** This light as a scene value. */
  toLight(): Light {
    const { position, direction, ambient, diffuse, specular } = this.values;
    if (position) return { kind: 'point', vector: position, ambient, diffuse, specular };
    const vector: Vec3 = direction ? unit(direction) : DEFAULT_LIGHT.vector;
    return { kind: 'directional', vector, ambient, diffuse, specular };
  }
}

function unit(v: Vec3): Vec3 {
  const l = Math.hypot(v[0], v[1], v[2]);
  return [v[0] / l, v[1] / l, v[2] / l];
}

defineChildProperties(GlassLight.prototype, LIGHT_ATTRIBUTES);
