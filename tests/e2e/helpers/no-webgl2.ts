// An init script for pages that must run without WebGL2: getContext('webgl2') returns null on
// every kind of canvas the element might create (its shared context is an OffscreenCanvas where
// the browser has one). Passed to page.addInitScript, so it may use nothing outside itself.
export function withoutWebGL2(): void {
  for (const C of [globalThis.HTMLCanvasElement, globalThis.OffscreenCanvas]) {
    if (!C) continue;
    const original = C.prototype.getContext as (...a: unknown[]) => unknown;
    C.prototype.getContext = function (this: unknown, type: string, ...rest: unknown[]) {
      if (type === 'webgl2') return null;
      return original.call(this, type, ...rest);
    } as typeof C.prototype.getContext;
  }
}
