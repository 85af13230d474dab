// CSS colours → linear 0..1 RGB for the `background` attribute. The forms written by hand
// (#hex, rgb()/rgba(), and our own "r g b" in 0..1) are parsed here exactly, with no 8-bit
// rounding (the default "rgb(25.5 25.5 25.5)" must be exactly 0.1); anything else (named
// colours, hsl(), color()) goes through a 2D canvas `fillStyle` round trip where there is one.
export type Rgb = [number, number, number];

const clamp01 = (x: number): number => Math.min(1, Math.max(0, x));
const NUMBER = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;

/** A channel of rgb(): a number 0..255 or a percentage; null when malformed. */
function channel(token: string): number | null {
  const percent = token.endsWith('%');
  const body = percent ? token.slice(0, -1) : token;
  if (!NUMBER.test(body)) return null;
  return clamp01(Number(body) / (percent ? 100 : 255));
}

function alphaOk(token: string | undefined): boolean {
  if (token === undefined) return true;
  const body = token.endsWith('%') ? token.slice(0, -1) : token;
  return NUMBER.test(body);
}

function hex(body: string): Rgb | null {
  if (!/^[0-9a-f]+$/i.test(body)) return null;
  if (body.length === 3 || body.length === 4) return [0, 1, 2].map((i) => parseInt(body[i] + body[i], 16) / 255) as Rgb;
  if (body.length === 6 || body.length === 8) return [0, 2, 4].map((i) => parseInt(body.slice(i, i + 2), 16) / 255) as Rgb;
  return null;
}

function rgbFunction(args: string): Rgb | null {
  // Legacy "r, g, b[, a]" or modern "r g b [/ a]".
  let parts: string[];
  let alpha: string | undefined;
  if (args.includes(',')) {
    parts = args.split(',').map((s) => s.trim());
    if (parts.length === 4) alpha = parts.pop();
  } else {
    const [colour, a, extra] = args.split('/').map((s) => s.trim());
    if (extra !== undefined) return null;
    parts = colour.split(/\s+/); // trimmed above: no empty part at either end
    alpha = a;
  }
  if (parts.length !== 3 || !alphaOk(alpha)) return null;
  const rgb = parts.map(channel);
  return rgb.every((c) => c !== null) ? (rgb as Rgb) : null;
}

/**
 * The colour `text` names, alpha ignored (the clear colour is opaque), or null when it is none
 * of the forms parsed here. Pure: the same answer in Node and in a browser.
 */
export function parseCssColor(text: string): Rgb | null {
  const s = text.trim().toLowerCase();
  if (s.startsWith('#')) return hex(s.slice(1));
  const fn = /^rgba?\((.*)\)$/s.exec(s);
  if (fn) return rgbFunction(fn[1]);
  const triple = s.split(/\s+/);
  if (triple.length === 3 && triple.every((t) => NUMBER.test(t))) return triple.map((t) => clamp01(Number(t))) as Rgb;
  return null;
}

let context: CanvasRenderingContext2D | null | undefined;

/** Any colour the browser knows (named, hsl(), …), via a 2D canvas; null without one or when invalid. */
export function browserCssColor(text: string): Rgb | null {
  if (context === undefined) {
    context = typeof document === 'undefined' ? null : document.createElement('canvas').getContext('2d');
  }
  if (!context || text.length > 200) return null;
  // Two different sentinels: a value the canvas rejects leaves either one in place.
  const read = (sentinel: string): string => {
    context!.fillStyle = sentinel;
    context!.fillStyle = text;
    return String(context!.fillStyle);
  };
  const a = read('#000001');
  const b = read('#000002');
  if (a !== b) return null;
  return parseCssColor(a);
}
