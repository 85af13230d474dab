// <glass-object> and <glass-light> for a page that wants them defined before any scene finds one
// (a scene defines them itself, through its lazy part CHILD_ELEMENTS, element/parts.ts).

/** Resolves once both child elements are defined. */
export function defineChildren(): Promise<void> {
  return import('./children/child-elements').then((chunk) => chunk.defineChildren());
}
