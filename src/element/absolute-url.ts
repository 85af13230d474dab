// A URL attribute as the key the page's caches share (models, course files, texture images):
// resolved to its absolute form, so "a.obj" and "./a.obj" on one page are one load.

/** `url` resolved against `base` (the document's by default); null for a URL that cannot be one. */
export function absoluteUrl(url: string | null, base: string = document.baseURI): string | null {
  if (url === null) return null;
  try {
    return new URL(url, base).href;
  } catch {
    return null;
  }
}
