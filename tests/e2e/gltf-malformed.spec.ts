// Broken glTF files through the element (docs/gltf.md#errors): each ends in one `error` naming the
// file and the place in it (or `load` with a warning where the rest can be drawn), the page
// answering scripts within 1 s throughout, and the cube beside it drawn. The unit tests
// (gltf-errors.test.ts) hold the reader's messages; here the element's behaviour with them.
import { test, expect, openPage, capture } from './fixtures';
import { productGlb } from './helpers/gltf-models';
import { glbBin, glbJson, makeGlb } from '../unit/helpers/gltf';

type Json = Record<string, any>; // eslint-disable-line @typescript-eslint/no-explicit-any
type Case = { name: string; url: string; body: () => Promise<Buffer | string>; end: 'load' | 'error'; where: RegExp; routes?: Record<string, () => Promise<Buffer | string | null>> };

/** The product GLB with its JSON changed by `f` (the BIN chunk as it was, or `bin` changed by `g`). */
async function broken(f: (json: Json) => void, g?: (bin: Uint8Array, json: Json) => Uint8Array): Promise<Buffer> {
  const glb = await productGlb();
  const json = glbJson(glb);
  let bin: Uint8Array = glbBin(glb).slice();
  f(json);
  if (g) bin = g(bin, json);
  return Buffer.from(makeGlb(json, bin));
}

const CASES: Case[] = [
  { name: 'a truncated GLB', url: '/bad/cut.glb', end: 'error', where: /^GLB header$/, body: async () => Buffer.from((await productGlb()).subarray(0, 600)) },
  {
    name: 'a chunk length past the file', url: '/bad/chunk.glb', end: 'error', where: /^GLB chunk 1 /,
    body: async () => {
      const glb = Buffer.from(await productGlb());
      const jsonLength = glb.readUInt32LE(12);
      glb.writeUInt32LE(glb.length, 20 + jsonLength);
      return glb;
    },
  },
  { name: 'an accessor past its buffer view', url: '/bad/accessor.glb', end: 'error', where: /^accessors\[0\]$/, body: () => broken((j) => { j.accessors[0].count *= 50; }) },
  {
    name: 'an index past the vertex count', url: '/bad/index.glb', end: 'error', where: /^accessors\[\d+\]$/,
    body: () => broken(() => {}, (bin, j) => {
      const indices = j.accessors[j.meshes[0].primitives[0].indices];
      new DataView(bin.buffer).setUint16((j.bufferViews[indices.bufferView].byteOffset ?? 0) + (indices.byteOffset ?? 0), 60000, true);
      return bin;
    }),
  },
  {
    name: 'NaN and 1e30 positions (drawn without their triangles)', url: '/bad/nan.glb', end: 'load', where: /attributes\.POSITION/,
    body: () => broken(() => {}, (bin, j) => {
      const p = j.accessors[j.meshes[0].primitives[0].attributes.POSITION];
      const at = (j.bufferViews[p.bufferView].byteOffset ?? 0) + (p.byteOffset ?? 0);
      const stride = j.bufferViews[p.bufferView].byteStride ?? 12;
      new DataView(bin.buffer).setFloat32(at, NaN, true);
      new DataView(bin.buffer).setFloat32(at + stride, 1e30, true);
      return bin;
    }),
  },
  { name: 'a node graph with a cycle', url: '/bad/cycle.glb', end: 'error', where: /^nodes\[\d+\]\.children\[\d+\]$/, body: () => broken((j) => { j.nodes[1].children = [0]; }) },
  {
    name: '100,000 nodes in a chain', url: '/bad/deep.glb', end: 'load', where: /^$/,
    body: () => broken((j) => {
      const n = 100_000, mesh = j.nodes.find((x: Json) => x.mesh !== undefined).mesh;
      j.nodes = Array.from({ length: n }, (_, i) => (i + 1 < n ? { children: [i + 1] } : { mesh }));
      j.scenes[0].nodes = [0];
    }),
  },
  { name: 'a declared byteLength of 2 GB', url: '/bad/huge.glb', end: 'error', where: /^buffers\[0\]\.byteLength$/, body: () => broken((j) => { j.buffers[0].byteLength = 2 ** 31; }) },
  {
    name: 'a .gltf whose .bin is missing', url: '/bad/lonely.gltf', end: 'error', where: /^buffers\[0\]\.uri$/,
    body: async () => {
      const json = glbJson(await productGlb());
      json.buffers[0].uri = 'lonely.bin';
      json.images = json.images.map(() => ({ uri: 'data:image/png;base64,iVBORw0KGgo=' }));
      return JSON.stringify(json);
    },
    routes: { '**/bad/lonely.bin': async () => null },
  },
  { name: 'an HTML page saved as .glb', url: '/bad/page.glb', end: 'error', where: /^$/, body: async () => '<!doctype html><html><body>Not found</body></html>' },
  { name: 'JSON that is not glTF', url: '/bad/data.gltf', end: 'error', where: /^asset$/, body: async () => '{"vertices": [1, 2, 3]}' },
];

for (const c of CASES) {
  test(`${c.name}: ${c.end}, the page answering, the cube drawn`, async ({ page, consoleLog }) => {
    const body = await c.body();
    await page.route(`**${c.url}`, (route) => route.fulfill({ status: 200, contentType: 'text/plain', body }));
    for (const [pattern, make] of Object.entries(c.routes ?? {})) {
      await page.route(pattern, async (route) => { const b = await make(); await (b === null ? route.fulfill({ status: 404, body: 'no' }) : route.fulfill({ body: b })); });
    }
    await openPage(page);
    await page.evaluate((url) => {
      const host = document.createElement('div');
      host.innerHTML = `<glass-plane-scene refine="0" time="0" spin="0" style="width:160px;height:90px">
        <glass-object shape="cube" position="-1 1 1"></glass-object><glass-object src="${url}" position="1 1 1"></glass-object></glass-plane-scene>`;
      const el = host.firstElementChild!;
      const w = window as unknown as { __ends: unknown[]; __ready: boolean };
      w.__ends = [];
      w.__ready = false;
      for (const type of ['load', 'error']) {
        el.addEventListener(type, (e) => { if ((e.target as Element).getAttribute('src')) w.__ends.push({ type, detail: JSON.parse(JSON.stringify((e as CustomEvent).detail)) }); });
      }
      el.addEventListener('ready', () => { w.__ready = true; });
      document.body.append(host);
    }, c.url);
    // A hang check, not a speed test: every round trip to the page within 1 s until `ready`.
    type End = { type: string; detail: { url: string; path?: string; message?: string; warnings?: string[] } };
    let state: { ends: End[]; ready: boolean } = { ends: [], ready: false };
    const started = Date.now();
    while (!state.ready && Date.now() - started < 30_000) {
      const t0 = Date.now();
      state = await page.evaluate(() => {
        const w = window as unknown as { __ends: End[]; __ready: boolean };
        return { ends: w.__ends, ready: w.__ready };
      });
      expect(Date.now() - t0, 'a round trip to the page (ms)').toBeLessThan(1_000);
      await new Promise((r) => setTimeout(r, 50));
    }
    expect(state.ends.map((e) => e.type), 'exactly one load or error').toEqual([c.end]);
    const d = state.ends[0].detail;
    expect(d.url).toMatch(new RegExp(`${c.url.replace(/[./]/g, '\\$&')}$`));
    if (c.end === 'error') expect(d.path ?? '').toMatch(c.where);
    else if (c.where.source !== '^$') expect(d.warnings!.join('\n')).toMatch(c.where);
    const img = await capture(page);
    let lit = 0;
    for (let y = 0; y < img.height; y++) for (let x = 0; x < img.width / 2; x++) {
      const i = 4 * (y * img.width + x);
      if (Math.abs(img.data[i] - 26) + Math.abs(img.data[i + 1] - 26) > 30) lit++;
    }
    expect(lit, 'cube pixels other than the background').toBeGreaterThan(100);
    expect(consoleLog.take('pageerror')).toEqual([]);
    consoleLog.take('error');
    consoleLog.take('warning');
  });
}
