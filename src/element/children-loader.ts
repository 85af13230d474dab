// Loads and defines <glass-object> and <glass-light> (children/child-elements.ts) once per page: the first
// scene that finds such a child asks for it, or a page that wants the classes calls defineChildren().
let loading: Promise<void> | null = null;

/** Resolves once both child elements are defined; a failed load may be asked again. */
export function defineChildren(): Promise<void> {
  return (loading ??= import('./children/child-elements').then((chunk) => chunk.defineChildren(), (e: unknown) => {
    loading = null;
    throw e;
  }));
}
