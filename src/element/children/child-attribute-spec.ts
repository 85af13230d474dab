// Row builders for the children's attribute tables (<glass-object>, <glass-light>): the same
// shape as the scene element's table (name, default, range, fallback, doc), and parse never
// throws: an unusable value comes back as the fallback with a `problem` to warn about.
import type { Parsed } from '../attributes';
import type { Vec3 } from '../../scene/scene';

export type { Parsed };

export interface ChildAttributeSpec<V = unknown, P extends string = string> {
  property: P;
  attribute: string;
  /** The value an absent attribute stands for (null: "from the MTL, else the default"). */
  default: V;
  /** One line for the README and warnings. */
  doc: string;
  /** Presence is the value (`normalize`). */
  boolean?: true;
  parse(raw: string | null): Parsed<V>;
}

const NUMBER = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;
/** Coordinates beyond this are clamped (float32 on the GPU; nothing useful is that far). */
export const MAX_COORD = 1e7;

export const num = (s: string): number => (NUMBER.test(s.trim()) ? Number(s.trim()) : NaN);

/** `n` numbers separated by spaces or commas, all finite; undefined otherwise. */
export function numbers(raw: string, counts: readonly number[]): number[] | undefined {
  const parts = raw.trim().split(/[\s,]+/);
  if (!counts.includes(parts.length)) return undefined;
  const xs = parts.map(num);
  return xs.every(Number.isFinite) ? xs : undefined;
}

const clamp = (x: number, lo: number, hi: number): number => Math.min(hi, Math.max(lo, x));

export function clampedNumber<P extends string>(
  property: P, attribute: string, def: number | null, min: number, max: number, doc: string, integer = false,
): ChildAttributeSpec<number | null, P> {
  return {
    property, attribute, default: def, doc,
    parse(raw) {
      if (raw === null) return { value: def };
      let x = num(raw);
      if (Number.isNaN(x)) return { value: def, problem: `not a number, using ${def ?? 'the default'}` };
      if (integer) x = Math.round(x);
      const c = clamp(x, min, max);
      return c === x ? { value: x } : { value: c, problem: `outside ${min}..${max}, clamped` };
    },
  };
}

/** "x y z" of finite numbers (`single`: one number stands for all three, as for scale). */
export function vec3<P extends string>(
  property: P, attribute: string, def: Vec3 | null, doc: string,
  options: { single?: boolean; min?: number; max?: number; nonZero?: boolean } = {},
): ChildAttributeSpec<Vec3 | null, P> {
  const { single = false, min = -MAX_COORD, max = MAX_COORD, nonZero = false } = options;
  const form = single ? 'one number or "x y z"' : '"x y z"';
  const shownDef = def === null ? 'the default' : `"${def.join(' ')}"`;
  return {
    property, attribute, default: def, doc,
    parse(raw) {
      if (raw === null) return { value: def };
      const xs = numbers(raw, single ? [1, 3] : [3]);
      if (!xs) return { value: def, problem: `expected ${form}, using ${shownDef}` };
      const v = (xs.length === 1 ? [xs[0], xs[0], xs[0]] : xs) as [number, number, number];
      if (nonZero && v.every((x) => x === 0)) return { value: def, problem: `a zero vector has no direction, using ${shownDef}` };
      const c = v.map((x) => clamp(x, min, max)) as [number, number, number];
      return c.some((x, i) => x !== v[i]) ? { value: c, problem: `outside ${min}..${max}, clamped` } : { value: c };
    },
  };
}

export function keyword<W extends string, P extends string>(
  property: P, attribute: string, words: readonly W[], def: W | null, doc: string,
): ChildAttributeSpec<W | null, P> {
  return {
    property, attribute, default: def, doc,
    parse(raw) {
      if (raw === null) return { value: def };
      const w = raw.trim().toLowerCase() as W;
      if (words.includes(w)) return { value: w };
      return { value: def, problem: `expected one of ${words.join(', ')}; using ${def ?? 'the default'}` };
    },
  };
}

export function flag<P extends string>(property: P, attribute: string, doc: string): ChildAttributeSpec<boolean, P> {
  return { property, attribute, default: false, doc, boolean: true, parse: (raw) => ({ value: raw !== null }) };
}

/** "true" or "false" (any case, blank meaning true): a yes/no whose absence is `def`, unlike a flag's. */
export function truth<P extends string>(property: P, attribute: string, def: boolean, doc: string): ChildAttributeSpec<boolean, P> {
  return {
    property, attribute, default: def, doc,
    parse(raw) {
      if (raw === null) return { value: def };
      const w = raw.trim().toLowerCase();
      if (w === 'false') return { value: false };
      if (w === 'true' || w === '') return { value: true };
      return { value: def, problem: `expected true or false, using ${def}` };
    },
  };
}

/** A URL as written (resolved against the document by whoever fetches it); blank = absent. */
export function url<P extends string>(property: P, attribute: string, doc: string): ChildAttributeSpec<string | null, P> {
  return {
    property, attribute, default: null, doc,
    parse: (raw) => ({ value: raw === null || raw.trim() === '' ? null : raw.trim() }),
  };
}

/**
 * What a script assigned to a property, as the attribute string it stands for: null/undefined
 * remove it, booleans toggle presence (for a boolean row), arrays join with spaces.
 */
export function propertyToRaw(spec: ChildAttributeSpec, value: unknown): string | null {
  if (value === null || value === undefined) return null;
  if (spec.boolean) return value ? '' : null;
  if (Array.isArray(value)) return value.map((x) => String(x)).join(' ');
  if (typeof value === 'number' || typeof value === 'string' || typeof value === 'boolean') return String(value);
  return '\u0000invalid';
}
