// The background's CSS colours (src/element/css-color.ts): the forms parsed by hand, exactly (no 8-bit rounding), every
// malformed variant refused; and the canvas round trip for the rest, against a fake 2D context that keeps a value it
// accepts and ignores one it does not, as a browser's does.
import { afterEach, describe, expect, it, vi } from 'vitest';

const load = async () => import('../../src/element/css-color');

afterEach(() => {
  vi.unstubAllGlobals();
  vi.resetModules();
});

describe('parseCssColor', () => {
  it('#rgb, #rgba, #rrggbb and #rrggbbaa, any case; alpha dropped', async () => {
    const { parseCssColor } = await load();
    expect(parseCssColor('#f80')).toEqual([1, 0x88 / 255, 0]);
    expect(parseCssColor('#F80C')).toEqual([1, 0x88 / 255, 0]);
    expect(parseCssColor('#1a2B3c')).toEqual([0x1a / 255, 0x2b / 255, 0x3c / 255]);
    expect(parseCssColor('  #1a2b3c80 ')).toEqual([0x1a / 255, 0x2b / 255, 0x3c / 255]);
    for (const bad of ['#', '#12', '#12345', '#1234567', '#123456789', '#12g', '#ggg', 'x#123', '#12 3', '#-12']) expect(parseCssColor(bad), bad).toBeNull();
  });

  it('rgb() and rgba(), legacy commas or modern spaces and slash, numbers or percentages, clamped', async () => {
    const { parseCssColor } = await load();
    expect(parseCssColor('rgb(25.5 25.5 25.5)')).toEqual([0.1, 0.1, 0.1]);
    expect(parseCssColor('rgb(255, 0, 51)')).toEqual([1, 0, 0.2]);
    expect(parseCssColor('RGBA(255, 0, 51, 0.5)')).toEqual([1, 0, 0.2]);
    expect(parseCssColor('rgba(255,0,51,50%)')).toEqual([1, 0, 0.2]);
    expect(parseCssColor('rgb(100% 50% 0% / 0.25)')).toEqual([1, 0.5, 0]);
    expect(parseCssColor('rgb(  10%   20%\t30%  )')).toEqual([0.1, 0.2, 0.3]);
    expect(parseCssColor('rgb(300 -5 1e2)')).toEqual([1, 0, 100 / 255]);
    expect(parseCssColor('rgb(.5 +1 2.)')).toEqual([0.5 / 255, 1 / 255, 2 / 255]);
    expect(parseCssColor('rgb(.55 1e+2 25E-1)')).toEqual([0.55 / 255, 100 / 255, 2.5 / 255]);
    expect(parseCssColor('rgb(1e10 0 0)')).toEqual([1, 0, 0]);
    expect(parseCssColor('rgba(255, 0, 51, 5)')).toEqual([1, 0, 0.2]);
    for (const bad of [
      'rgb()', 'rgb(1 2)', 'rgb(1 2 3 4)', 'rgb(1, 2)', 'rgb(1, 2, 3, 4, 5)', 'rgb(1 2 3 / 4 / 5)', 'rgb(1 2 x)', 'rgb(1, 2, 3, x)',
      'rgb(1 2 3 / x%)', 'rgb(1 2 3 / 5x%)', 'rgb(1% 2 %3)', 'rgb(1x 2 3)', 'rgb(1e 2 3)', 'rgb(1e+ 2 3)', 'rgb(1 2 3', 'rgb 1 2 3)', 'xrgb(1 2 3)', 'rgb(1 2 3) x', 'rgb(1, 2 3)', 'rgb(e 2 3)',
    ]) expect(parseCssColor(bad), bad).toBeNull();
  });

  it('our own "r g b" in 0..1, clamped; anything else is not parsed here', async () => {
    const { parseCssColor } = await load();
    expect(parseCssColor('0.1 0.2 0.3')).toEqual([0.1, 0.2, 0.3]);
    expect(parseCssColor(' 1   -1  2 ')).toEqual([1, 0, 1]);
    for (const bad of ['0.1 0.2', '0.1 0.2 0.3 0.4', '0.1 0.2 x', 'red', 'hsl(0 100% 50%)', '', '1,2,3']) expect(parseCssColor(bad), bad).toBeNull();
  });
});

/** A 2D context as a browser's: fillStyle keeps a colour it knows (normalised to #rrggbb), ignores anything else. */
function fakeDocument(known: Record<string, string>) {
  let style = '#000000';
  const context = {
    get fillStyle() { return style; },
    set fillStyle(v: string) {
      const k = known[v.trim().toLowerCase()] ?? (/^#[0-9a-f]{6}$/i.test(v) ? v.toLowerCase() : undefined);
      if (k !== undefined) style = k;
    },
  };
  const createElement = vi.fn(() => ({ getContext: (kind: string) => (kind === '2d' ? context : null) }));
  return { document: { createElement }, createElement };
}

describe('browserCssColor', () => {
  it('a colour the canvas knows, by its #rrggbb; one it refuses (it keeps either sentinel): null', async () => {
    const fake = fakeDocument({ rebeccapurple: '#663399', 'hsl(120 100% 50%)': '#00ff00' });
    vi.stubGlobal('document', fake.document);
    const { browserCssColor } = await load();
    expect(browserCssColor('RebeccaPurple')).toEqual([0x66 / 255, 0x33 / 255, 0x99 / 255]);
    expect(browserCssColor('hsl(120 100% 50%)')).toEqual([0, 1, 0]);
    expect(browserCssColor('not a colour')).toBeNull();
    // Again, right after one the canvas refused (the second sentinel still in place): still null.
    expect(browserCssColor('nor this')).toBeNull();
    // The canvas is made once and asked for a 2d context.
    expect(fake.createElement).toHaveBeenCalledTimes(1);
    expect(fake.createElement).toHaveBeenCalledWith('canvas');
  });

  it('more than 200 characters: null without asking the canvas; 200 are asked', async () => {
    const long = 'x'.repeat(190) + 'rebeccapur';
    const fake = fakeDocument({ [long]: '#010203' });
    vi.stubGlobal('document', fake.document);
    const { browserCssColor } = await load();
    expect(long.length).toBe(200);
    expect(browserCssColor(long)).toEqual([1 / 255, 2 / 255, 3 / 255]);
    expect(browserCssColor(`${long} `)).toBeNull();
  });

  it('without a document (a worker, Node): null, every time', async () => {
    const { browserCssColor } = await load();
    expect(browserCssColor('red')).toBeNull();
    expect(browserCssColor('#ff0000')).toBeNull();
  });
});
