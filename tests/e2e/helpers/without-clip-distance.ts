// An init script that hides WEBGL_clip_cull_distance, so the renderer takes its `discard`
// fallback for the reflection pass's clip plane (the test browser has the extension, so the
// fallback is never compiled otherwise). Records each time the extension was asked for, so a
// test can tell the fallback really was exercised. Passed to page.addInitScript: self-contained.
export function withoutClipDistance(): void {
  const NAME = 'WEBGL_clip_cull_distance';
  const g = globalThis as { __clipDistanceRefused__?: number };
  g.__clipDistanceRefused__ = 0;
  for (const C of [globalThis.WebGL2RenderingContext, globalThis.WebGLRenderingContext]) {
    if (!C) continue;
    const getExtension = C.prototype.getExtension as (this: unknown, name: string) => unknown;
    const getSupported = C.prototype.getSupportedExtensions;
    C.prototype.getExtension = function (this: unknown, name: string) {
      if (name.toLowerCase() === NAME.toLowerCase()) {
        g.__clipDistanceRefused__!++;
        return null;
      }
      return getExtension.call(this, name);
    } as typeof C.prototype.getExtension;
    C.prototype.getSupportedExtensions = function (this: WebGLRenderingContext) {
      return getSupported.call(this)?.filter((n) => n !== NAME) ?? null;
    };
  }
}
