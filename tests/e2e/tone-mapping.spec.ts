// Tone mapping in WebGL (docs/pbr.md#tone-mapping): the box face of light (3, 1.5, 0.75) that tone-mapped-frames.test.ts works out
// by hand for the CPU renderers, drawn by the Renderer within one 8-bit level; a frame with `none` and exposure 1 is
// today's byte for byte; a glass reflecting light above 1 against the reference; and the element's attributes.
import { test, expect, openPage, capture } from './fixtures';
import { drawScene, openRendererPage } from './helpers/scene-json';
import { expectPsnr, note } from './helpers/bounds';
import { mountHtml } from './helpers/scene-children';
import { samePixels as same, wait } from './helpers/chunks';
import { renderScene, compareImages } from '../../src/reference';
import { linearToSrgb } from '../../src/math/srgb';
import { toneMap } from '../../src/math/tone-map';
import type { FrameState } from '../../src/frame/types';
import { BOX, BOX_STATE, CENTRE, FLOOR, FLOOR_STATE, NEUTRAL } from '../unit/helpers/tone-scenes';

test('WebGL: the box face of light above 1, tone mapped, as worked by hand', async ({ page }) => {
  await openRendererPage(page);
  const cases: [Partial<FrameState>, number[]][] = [
    [{ toneMapping: 'neutral' }, NEUTRAL],
    [{ toneMapping: 'aces' }, [...toneMap('aces', [0, 0, 0], 3, 1.5, 0.75)]],
    [{ toneMapping: 'none', exposure: 0.5 }, [1, 0.75, 0.375]],
    [{ toneMapping: 'neutral', exposure: 0.25 }, [...toneMap('neutral', [0, 0, 0], 0.75, 0.375, 0.1875)]],
  ];
  for (const [over, linear] of cases) {
    const image = await drawScene(page, { ...BOX_STATE, ...over }, BOX);
    const got = [...image.data.subarray(4 * CENTRE, 4 * CENTRE + 3)];
    const want = linear.map((l) => linearToSrgb(l) * 255);
    got.forEach((g, k) => expect(Math.abs(g - want[k]), `${JSON.stringify(over)} channel ${k}: ${got} against ${want}`).toBeLessThanOrEqual(1));
  }
  // Without tone mapping the light clips at 1; `none` with exposure 1 is that frame, byte for byte.
  const plain = await drawScene(page, BOX_STATE, BOX);
  expect([...plain.data.subarray(4 * CENTRE, 4 * CENTRE + 2)]).toEqual([255, 255]);
  expect(Buffer.from((await drawScene(page, { ...BOX_STATE, toneMapping: 'none', exposure: 1 }, BOX)).data).equals(Buffer.from(plain.data))).toBe(true);
});

test('WebGL: a glass reflecting light above 1, tone mapped, against the reference', async ({ page }) => {
  await openRendererPage(page);
  const state = { ...FLOOR_STATE, toneMapping: 'neutral' as const, exposure: 0.5, samples: 4 };
  const image = await drawScene(page, state, FLOOR);
  const cmp = compareImages(renderScene(FLOOR, state, null, { samplesPerAxis: 4 }), image.data);
  const p = cmp.psnr;
  note(`tone-mapped glass floor, WebGL against the reference: all ${p.all.toFixed(1)}, objects ${p.objects.toFixed(1)}, glass ${p.glass.toFixed(1)} dB`);
  expectPsnr(cmp, { all: 43.1, objects: 63.1, glass: 54.6 }, 'tone-mapped glass floor');
});

test('the element: tone-mapping and exposure change the picture; `none` is the default scene\'s frame exactly', async ({ page }) => {
  await openPage(page);
  const SCENE = (attrs: string) => `<glass-plane-scene refine="0" time="0" spin="0" ${attrs}></glass-plane-scene>`;
  const shot = async (attrs: string) => {
    await openPage(page);
    await mountHtml(page, SCENE(attrs));
    await wait(page, 200);
    return capture(page);
  };
  const plain = await shot('');
  expect(same(await shot('tone-mapping="none"'), plain)).toBe(true);
  expect(same(await shot('tone-mapping="auto"'), plain)).toBe(true);
  expect(same(await shot('tone-mapping="neutral"'), plain)).toBe(false);
  expect(same(await shot('tone-mapping="none" exposure="2"'), plain)).toBe(false);
});
