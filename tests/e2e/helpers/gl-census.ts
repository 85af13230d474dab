// Counts the GL objects that are really alive, from the context's own create*/delete* calls,
// independent of the element's bookkeeping (its `stats.resources` are zeroed on disposal, so
// they cannot show a leak). The init script wraps WebGL2RenderingContext.prototype, which
// covers every context on the page, the shared OffscreenCanvas one included.
import type { Page } from '@playwright/test';

/** Object kind → live count (created and not yet deleted). */
export type Census = Record<string, number>;

/** Passed to page.addInitScript: self-contained. */
export function countGlObjects(): void {
  const P = globalThis.WebGL2RenderingContext?.prototype as unknown as Record<string, (...a: unknown[]) => unknown>;
  if (!P) return;
  const live = new Map<string, Set<unknown>>();
  const created: Record<string, number> = {};
  const pairs: [string, string, string][] = [
    ['buffers', 'createBuffer', 'deleteBuffer'],
    ['textures', 'createTexture', 'deleteTexture'],
    ['framebuffers', 'createFramebuffer', 'deleteFramebuffer'],
    ['renderbuffers', 'createRenderbuffer', 'deleteRenderbuffer'],
    ['vertexArrays', 'createVertexArray', 'deleteVertexArray'],
    ['programs', 'createProgram', 'deleteProgram'],
    ['shaders', 'createShader', 'deleteShader'],
    ['queries', 'createQuery', 'deleteQuery'],
    ['samplers', 'createSampler', 'deleteSampler'],
    ['transformFeedbacks', 'createTransformFeedback', 'deleteTransformFeedback'],
    ['syncs', 'fenceSync', 'deleteSync'],
  ];
  for (const [kind, create, del] of pairs) {
    const set = new Set<unknown>();
    live.set(kind, set);
    created[kind] = 0;
    const c = P[create];
    const d = P[del];
    P[create] = function (this: unknown, ...a: unknown[]) {
      const o = c.apply(this, a);
      if (o) {
        set.add(o);
        created[kind]++;
      }
      return o;
    };
    // Deleting null, or an object twice, is legal GL and changes nothing: only the first
    // delete of a live object counts.
    P[del] = function (this: unknown, ...a: unknown[]) {
      set.delete(a[0]);
      return d.apply(this, a);
    };
  }
  (globalThis as { __glCensus__?: () => { live: Record<string, number>; created: Record<string, number> } }).__glCensus__ = () => ({
    live: Object.fromEntries([...live].map(([k, s]) => [k, s.size])),
    created: { ...created },
  });
}

/** Live objects per kind, and how many of each were ever created, as the wrapped context saw them. */
export async function glCensus(page: Page): Promise<{ live: Census; created: Census }> {
  return page.evaluate(() => {
    const f = (globalThis as { __glCensus__?: () => { live: Census; created: Census } }).__glCensus__;
    if (!f) throw new Error('the GL census init script is not installed');
    return f();
  });
}

export const liveTotal = (c: Census): number => Object.values(c).reduce((a, b) => a + b, 0);
