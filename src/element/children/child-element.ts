// What <glass-object> and <glass-light> share: an attribute table turned into parsed values and
// camelCase properties, warnings once per (attribute, value) on the page, and a change
// notice that bubbles to the scene element (which cannot observe its children's attributes).
import { AttributeWarnings } from '../warnings';
import { propertyToRaw, type ChildAttributeSpec } from './child-attribute-spec';

/** Fired (bubbling, not composed) by a child whenever its part of the scene may have changed. */
export { CHILD_CHANGE } from './tags';
import { CHILD_CHANGE } from './tags';

// Lets the module load where HTMLElement does not exist (server-side rendering, Node tests).
const Base = (typeof HTMLElement === 'undefined' ? class {} : HTMLElement) as typeof HTMLElement;

/** One set per tag: the same bad value on many children of a page warns once. */
const warningsByTag = new Map<string, AttributeWarnings>();

export abstract class ChildElement<V extends object> extends Base {
  protected readonly values: V;
  private readonly specs: ReadonlyMap<string, ChildAttributeSpec>;

  protected constructor(private readonly tag: string, specs: readonly ChildAttributeSpec[], defaults: V) {
    super();
    this.values = defaults;
    this.specs = new Map(specs.map((s) => [s.attribute, s]));
  }

  connectedCallback(): void {
    upgradeProperties(this, [...this.specs.values()]);
    this.changed();
  }

  disconnectedCallback(): void {}

  attributeChangedCallback(name: string, _old: string | null, raw: string | null): void {
    const spec = this.specs.get(name);
    if (!spec) return;
    const parsed = spec.parse(raw);
    if (parsed.problem) {
      let w = warningsByTag.get(this.tag);
      if (!w) warningsByTag.set(this.tag, (w = new AttributeWarnings()));
      w.report(spec, raw ?? '', parsed.problem, this.tag);
    }
    (this.values as Record<string, unknown>)[spec.property] = parsed.value;
    this.attributeParsed(spec.property);
  }

  /** A row's value changed; the default tells the scene. */
  protected attributeParsed(_property: string): void {
    this.changed();
  }

  /** Tells the scene element (if this child is in one) to rebuild its scene. */
  /** A child's own event (load, progress, error): bubbles and crosses shadow roots. */
  protected fire(type: string, detail: unknown): void {
    this.dispatchEvent(new CustomEvent(type, { detail, bubbles: true, composed: true }));
  }

  protected changed(): void {
    if (this.isConnected) this.dispatchEvent(new Event(CHILD_CHANGE, { bubbles: true }));
  }
}

/** One camelCase accessor per row: the getter returns the parsed value, the setter writes the attribute. */
export function defineChildProperties(proto: object, specs: readonly ChildAttributeSpec[]): void {
  for (const spec of specs) {
    Object.defineProperty(proto, spec.property, {
      configurable: true,
      enumerable: true,
      get(this: { values: Record<string, unknown> }) {
        const v = this.values[spec.property];
        return Array.isArray(v) ? [...v] : v;
      },
      set(this: HTMLElement, value: unknown) {
        const raw = propertyToRaw(spec, value);
        if (raw === null) this.removeAttribute(spec.attribute);
        else this.setAttribute(spec.attribute, raw);
      },
    });
  }
}

/** A property set before the element was defined shadows the accessor: replay it through it. */
function upgradeProperties(el: HTMLElement, specs: readonly ChildAttributeSpec[]): void {
  const own = el as unknown as Record<string, unknown>;
  for (const { property } of specs) {
    if (Object.prototype.hasOwnProperty.call(el, property)) {
      const value = own[property];
      delete own[property];
      own[property] = value;
    }
  }
}
