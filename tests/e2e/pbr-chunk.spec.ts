// glTF materials' shader part is a chunk of its own (render/pbr-gl.ts, the lazy part PBR_MATERIALS, docs/pbr.md#the-scenes-lights):
// a scene without a glTF material never fetches it; a frame with one waits for it (the first frame is
// already lit by the glTF BRDF, however slow the chunk); if it cannot load, one warning, no error,
// and the model drawn with its Blinn-Phong stand-in.
import type { Page } from '@playwright/test';
import { test, expect, openPage, capture } from './fixtures';
import { mountHtml } from './helpers/scene-children';
import { blockChunk, expectOneWarning, fetchedChunks, holdBack, samePixels as same, wait } from './helpers/chunks';
import { Document, NodeIO } from '@gltf-transform/core';
import { boxArrays } from './helpers/gltf-models';

const PBR = 'pbr-gl';
const SCENE = (children = '') => `<glass-plane-scene refine="0" time="0" spin="0" samples="0" camera-position="1.8 1.6 4.5" camera-rotation="-100 -12">${children}</glass-plane-scene>`;
const MODEL = '<glass-object src="/wild/product.glb" position="0 0.3 1.2"></glass-object>';
const OBJ = '<glass-object shape="sphere" position="0 0.5 1"></glass-object>';

/** A box of a gold metal, roughness 0.4: no texture (whose decoding would be a frame of its own). */
async function boxGlb(): Promise<Uint8Array> {
  const doc = new Document();
  const buffer = doc.createBuffer();
  const b = boxArrays(0.5);
  const acc = (type: 'VEC3' | 'SCALAR', a: Float32Array<ArrayBuffer> | Uint16Array<ArrayBuffer>) => doc.createAccessor().setType(type).setArray(a).setBuffer(buffer);
  const gold = doc.createMaterial('gold').setBaseColorFactor([1, 0.77, 0.34, 1]).setMetallicFactor(1).setRoughnessFactor(0.4);
  const mesh = doc.createMesh().addPrimitive(doc.createPrimitive().setAttribute('POSITION', acc('VEC3', b.positions))
    .setAttribute('NORMAL', acc('VEC3', b.normals)).setIndices(acc('SCALAR', b.indices)).setMaterial(gold));
  doc.createScene('scene').addChild(doc.createNode('box').setMesh(mesh).setRotation([0, Math.sin(Math.PI / 8), 0, Math.cos(Math.PI / 8)]));
  return new NodeIO().writeBinary(doc);
}

async function serveModel(page: Page): Promise<void> {
  const glb = await boxGlb();
  await page.route('**/wild/product.glb', (route) => route.fulfill({ status: 200, contentType: 'model/gltf-binary', body: Buffer.from(glb) }));
}

const settled = async (page: Page) => {
  await wait(page, 300);
  return capture(page);
};

test('only a scene with a glTF material fetches it', async ({ page }) => {
  await serveModel(page);
  await openPage(page);
  await mountHtml(page, SCENE());
  await mountHtml(page, SCENE(OBJ));
  await wait(page, 200);
  expect(await fetchedChunks(page, [PBR])).toEqual([]);
  await mountHtml(page, SCENE(MODEL));
  expect(await fetchedChunks(page, [PBR])).toEqual([PBR]);
});

test('held back 600 ms: the first frame with the model is already lit by the glTF BRDF', async ({ page }) => {
  await serveModel(page);
  await openPage(page);
  await mountHtml(page, SCENE(MODEL));
  const lit = await settled(page);
  await holdBack(page, PBR, 600);
  await openPage(page);
  // The first frame after the model's `load`, read back in its `frame` event: the model arrives long
  // before the chunk, and a frame drawn meanwhile would show its stand-in.
  const first = await page.evaluate((html) => new Promise<number[]>((resolve) => {
    const host = document.createElement('div');
    host.innerHTML = html;
    const el = host.querySelector('glass-plane-scene') as HTMLElement & { capture(): ImageData };
    el.style.width = '160px';
    el.style.height = '90px';
    el.addEventListener('load', () => {
      el.addEventListener('frame', () => resolve([...el.capture().data]), { once: true });
    }, { once: true });
    document.body.append(...host.childNodes);
  }), SCENE(MODEL));
  expect(same({ width: lit.width, height: lit.height, data: Uint8Array.from(first) }, lit)).toBe(true);
});

test('if it cannot load: one warning, no error, the model drawn with its Blinn-Phong stand-in', async ({ page, consoleLog }) => {
  await serveModel(page);
  await openPage(page);
  await mountHtml(page, SCENE(MODEL));
  const lit = await settled(page);
  await blockChunk(page, PBR);
  await openPage(page);
  const seen = await mountHtml(page, SCENE(MODEL));
  expect(seen.filter((e) => e.type === 'error')).toEqual([]);
  expect(seen.filter((e) => e.type === 'load').length).toBe(1);
  const standIn = await settled(page);
  expect(same(standIn, lit)).toBe(false);
  expectOneWarning(consoleLog, 'glTF materials and tone mapping could not load');
  // The stand-in draws the model: not the empty floor.
  await openPage(page);
  await mountHtml(page, SCENE());
  expect(same(standIn, await settled(page))).toBe(false);
});
