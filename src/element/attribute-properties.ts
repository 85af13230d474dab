// One camelCase accessor per row of the attribute table: the getter returns the parsed value,
// the setter writes the attribute (which parses, warns if needed and re-renders).
import { ATTRIBUTES, ATTRIBUTE_BY_NAME, propertyToRaw, type SceneAttributes } from './attributes';
import type { AttributeWarnings } from './warnings';

/** Where an element keeps its parsed values; `live` may override one (the flown camera). */
export interface AttributeHost extends HTMLElement {
  readAttributeValue(property: keyof SceneAttributes): unknown;
}

export function defineAttributeProperties(proto: AttributeHost): void {
  for (const spec of ATTRIBUTES) {
    Object.defineProperty(proto, spec.property, {
      configurable: true,
      enumerable: true,
      get(this: AttributeHost) {
        const v = this.readAttributeValue(spec.property);
        return Array.isArray(v) ? [...v] : v;
      },
      set(this: AttributeHost, value: unknown) {
        const raw = propertyToRaw(spec, value);
        if (raw === null) this.removeAttribute(spec.attribute);
        else this.setAttribute(spec.attribute, raw);
      },
    });
  }
}

/**
 * Properties set on the element before it was defined shadow its accessors: each (of the
 * attribute table and `extra`, whose attributes are their names) is deleted and set again
 * through its accessor. Returns the attributes of those set again.
 */
export function upgradeProperties(el: HTMLElement, extra: readonly string[]): string[] {
  const own = el as unknown as Record<string, unknown>;
  const set: string[] = [];
  for (const { property, attribute } of [...ATTRIBUTES, ...extra.map((p) => ({ property: p, attribute: p }))]) {
    if (Object.prototype.hasOwnProperty.call(el, property)) {
      const value = own[property];
      delete own[property];
      own[property] = value;
      set.push(attribute);
    }
  }
  return set;
}

/**
 * Attribute `name` parsed into `values` (a bad value warned about once, its fallback kept): its
 * property, or null for an attribute that is not one of the table's.
 */
export function parseAttribute(values: SceneAttributes, name: string, raw: string | null, warnings: AttributeWarnings): keyof SceneAttributes | null {
  const spec = ATTRIBUTE_BY_NAME.get(name);
  if (!spec) return null;
  const parsed = spec.parse(raw);
  if (parsed.problem) warnings.report(spec, raw ?? '', parsed.problem);
  (values as unknown as Record<string, unknown>)[spec.property] = parsed.value;
  return spec.property;
}
