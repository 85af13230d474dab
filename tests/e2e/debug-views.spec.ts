// Debug views as a whole: the 'passes' tiles cover the canvas, whatever its size.
import { test, expect, mount, openPage, capture } from './fixtures';

test.describe('debug-view passes', () => {
  for (const samples of [0, 4]) {
    test(`odd-sized canvas, samples ${samples}: every pixel is written by one of the four tiles`, async ({ page }) => {
      await openPage(page);
      // 161×91: the halves are 80 and 81 wide, 45 and 46 high; a tile of floor(size / 2) each
      // side leaves the middle column and row unwritten (transparent black).
      const { selector } = await mount(page, { time: 1.25, 'debug-view': 'passes', 'pixel-ratio': 1, samples }, { width: 161, height: 91 });
      const image = await capture(page, undefined, selector);
      expect([image.width, image.height]).toEqual([161, 91]);
      const unwritten: string[] = [];
      for (let y = 0; y < image.height; y++) {
        for (let x = 0; x < image.width; x++) {
          if (image.data[(y * image.width + x) * 4 + 3] !== 255) unwritten.push(`(${x}, ${y})`);
        }
      }
      expect(unwritten.length, `pixels no tile wrote (alpha ≠ 255), e.g. ${unwritten.slice(0, 5).join(' ')}`).toBe(0);
    });
  }
});
