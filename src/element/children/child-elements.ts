// The child elements in a chunk of their own (children-loader.ts loads it): a scene with no
// <glass-object> or <glass-light> never downloads them. Defines both tags unless already defined
// (by another copy of the package, or an earlier load).
import { GlassLight } from './glass-light';
import { GlassObject } from './glass-object';
import { LIGHT_TAG, OBJECT_TAG } from './tags';

export function defineChildren(): void {
  if (!customElements.get(OBJECT_TAG)) customElements.define(OBJECT_TAG, GlassObject);
  if (!customElements.get(LIGHT_TAG)) customElements.define(LIGHT_TAG, GlassLight);
}

export { GlassLight, GlassObject };
