// Helpers for the children tests: a page-side summary of el.scene (no typed arrays cross the
// boundary), scenes written as HTML, and waits for child events.
import type { Page } from '@playwright/test';

export interface ObjectSummary {
  kind: string;
  key?: string;
  size?: number;
  radius?: number;
  resolution?: number;
  vertices?: number;
  triangles?: number;
  position: number[];
  scale: number[];
  material: { ambient: number[]; diffuse: number[]; specular: number[]; shininess: number; opacity: number; texture: string; mapping: string };
  bounds: { center: number[]; radius: number };
}

export interface SceneSummary {
  glass: { center: number[]; normal: number[]; size: number[] } | null;
  objects: ObjectSummary[];
  lights: { kind: string; vector: number[]; ambient: number[]; diffuse: number[]; specular: number[] }[];
  background: number[];
}

/** Installs window.__summary(el) before any page script. */
export async function installSummary(page: Page): Promise<void> {
  await page.addInitScript(() => {
    (window as unknown as { __summary: (el: Element) => unknown }).__summary = (el: Element) => {
      const s = (el as unknown as { scene: any }).scene;
      return {
        glass: s.glass && { center: [...s.glass.center], normal: [...s.glass.normal], size: [...s.glass.size] },
        background: [...s.background],
        lights: s.lights.map((l: any) => ({ kind: l.kind, vector: [...l.vector], ambient: [...l.ambient], diffuse: [...l.diffuse], specular: [...l.specular] })),
        objects: s.objects.map((o: any) => {
          const g = o.geometry;
          const m = o.material;
          return {
            kind: g.kind, key: g.key, size: g.size, radius: g.radius, resolution: g.resolution,
            vertices: g.data ? g.data.positions.length / 3 : undefined,
            triangles: g.data ? g.data.indices.length / 3 : undefined,
            position: [...o.transform.position], scale: [...o.transform.scale],
            material: {
              ambient: [...m.ambient], diffuse: [...m.diffuse], specular: [...m.specular], shininess: m.shininess,
              opacity: m.opacity, texture: m.texture.kind === 'image' ? m.texture.url : m.texture.kind, mapping: m.mapping,
            },
            bounds: { center: [...o.bounds.center], radius: o.bounds.radius },
          };
        }),
      };
    };
  });
}

export async function summary(page: Page, selector = 'glass-plane-scene'): Promise<SceneSummary> {
  return page.evaluate((selector) => (window as unknown as { __summary: (el: Element) => SceneSummary }).__summary(document.querySelector(selector)!), selector);
}

/**
 * Puts `html` (a <glass-plane-scene> with children) into the body and resolves with the
 * event types seen on the scene element up to its `ready` (children's events bubble to it).
 */
export async function mountHtml(page: Page, html: string, timeoutMs = 30_000): Promise<{ type: string; target: string; detail: any }[]> {
  return page.evaluate(({ html, timeoutMs }) => new Promise<{ type: string; target: string; detail: any }[]>((resolve, reject) => {
    const host = document.createElement('div');
    host.innerHTML = html;
    const el = host.querySelector('glass-plane-scene')!;
    // The unrefined picture, unless the test asks for refinement (tests/e2e/fixtures.ts mount).
    if (!el.hasAttribute('refine')) el.setAttribute('refine', '0');
    (el as HTMLElement).style.width = '160px';
    (el as HTMLElement).style.height = '90px';
    const seen: { type: string; target: string; detail: any }[] = [];
    (window as unknown as { __seen: unknown }).__seen = seen;
    for (const type of ['progress', 'load', 'error']) {
      el.addEventListener(type, (e) => seen.push({ type, target: (e.target as Element).localName, detail: JSON.parse(JSON.stringify((e as CustomEvent).detail ?? null)) }));
    }
    const timer = setTimeout(() => reject(new Error('no ready event')), timeoutMs);
    el.addEventListener('ready', () => {
      clearTimeout(timer);
      seen.push({ type: 'ready', target: 'glass-plane-scene', detail: null });
      resolve(seen);
    }, { once: true });
    document.body.append(...host.childNodes);
  }), { html, timeoutMs });
}

/**
 * Mounts `html` (one scene element and its children) and returns that element's first frame,
 * read back inside its first `frame` event: what a chunk the frame waited for changed, or not.
 */
export async function mountFirstFrame(page: Page, html: string): Promise<{ width: number; height: number; data: Uint8Array }> {
  const { width, height, b64 } = await page.evaluate((html) => new Promise<{ width: number; height: number; b64: string }>((resolve) => {
    const host = document.createElement('div');
    host.innerHTML = html;
    const el = host.querySelector('glass-plane-scene') as HTMLElement & { capture(): ImageData };
    if (!el.hasAttribute('refine')) el.setAttribute('refine', '0');
    el.addEventListener('frame', () => {
      const img = el.capture();
      const bytes = new Uint8Array(img.data.buffer);
      let s = '';
      for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
      resolve({ width: img.width, height: img.height, b64: btoa(s) });
    }, { once: true });
    document.body.append(...host.childNodes);
  }), html);
  return { width, height, data: new Uint8Array(Buffer.from(b64, 'base64')) };
}

/** Resolves with the detail of the next `type` event bubbling to the scene element. */
export async function nextEvent(page: Page, type: string, change: string, selector = 'glass-plane-scene'): Promise<any> {
  return page.evaluate(({ type, change, selector }) => new Promise((resolve, reject) => {
    const el = document.querySelector(selector)!;
    const timer = setTimeout(() => reject(new Error(`no ${type} event`)), 20_000);
    el.addEventListener(type, (e) => {
      clearTimeout(timer);
      resolve(JSON.parse(JSON.stringify((e as CustomEvent).detail ?? null)));
    }, { once: true });
    new Function('el', change)(el);
  }), { type, change, selector });
}

/** Asks the page's first scene element for a frame and waits for its `frame` event (a frame started after this call). */
export const requestedFrame = (page: Page): Promise<unknown> => page.evaluate(() => new Promise((r) => {
  const el = document.querySelector('glass-plane-scene') as unknown as HTMLElement & { requestRender(): void };
  el.addEventListener('frame', r, { once: true });
  el.requestRender();
}));
