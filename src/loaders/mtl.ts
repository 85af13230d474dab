// The MTL loader (docs/scene-model.md#obj-and-mtl): material values and texture paths by material name. Pure, like
// the OBJ loader; a value the file does not give is left out, so attributes and defaults
// can take precedence over what is missing.
import { isNumberToken } from './number-token';
import { decodeText, type Bytes } from './decode-text';
import { LoadError, type LoadWarning } from './load-error';
import { sniffModel, type ModelFormat } from './sniff';
import { logicalLines, stripComment } from './text-lines';
import { readMapStatement, type MtlTexture } from './mtl-map';
import { shown, Warnings } from './warnings';

export type { MtlTexture } from './mtl-map';
export type Rgb = [number, number, number];

export interface MtlMaterial {
  name: string;
  /** Ka, Kd, Ks. */
  ambient?: Rgb;
  diffuse?: Rgb;
  specular?: Rgb;
  /** Ns, the Blinn-Phong exponent. */
  shininess?: number;
  /** d, or 1 − Tr; clamped to 0..1. */
  opacity?: number;
  /** Ni, at least 1. */
  ior?: number;
  illum?: number;
  /** map_Kd and map_Ka. */
  diffuseMap?: MtlTexture;
  ambientMap?: MtlTexture;
}

export interface MtlResult {
  materials: Map<string, MtlMaterial>;
  warnings: LoadWarning[];
}

/** Statements we know and do not use: skipped without a warning. */
const KNOWN_UNUSED = new Set(['ke', 'tf', 'pr', 'pm', 'ps', 'pc', 'pcr', 'aniso', 'anisor', 'sharpness', 'map_ks',
  'map_ns', 'map_d', 'map_bump', 'bump', 'disp', 'decal', 'refl', 'norm', 'map_pr', 'map_pm', 'map_ps', 'map_ke',
  'map_tr', 'map_refl', 'map_aat']);

export function parseMtl(text: string, options: { url?: string; sniffed?: ModelFormat } = {}): MtlResult {
  const url = options.url ?? '';
  const format = options.sniffed ?? sniffModel(text);
  if (format === 'html') throw new LoadError(url, 'an HTML page (or other markup), not an MTL file');
  if (format === 'binary') throw new LoadError(url, 'binary content, not an MTL file');

  const base = absoluteBase(url);
  const materials = new Map<string, MtlMaterial>();
  const warnings = new Warnings();
  const fromD = new Set<MtlMaterial>(); // materials whose opacity came from d, which beats Tr
  let current: MtlMaterial | null = null;

  for (const { line, text: raw } of logicalLines(text)) {
    const body = stripComment(raw).trim();
    if (body === '') continue;
    const keyword = body.split(/\s/, 1)[0];
    const rest = body.slice(keyword.length).trim();
    const key = keyword.toLowerCase();
    if (key === 'newmtl') {
      if (materials.has(rest)) warnings.add(line, `material ${shown(rest)} defined again; the later one is used`);
      current = { name: rest };
      materials.set(rest, current);
      continue;
    }
    if (current === null) {
      warnings.add(line, `${shown(keyword)} before any newmtl; ignored`);
      continue;
    }
    const args = rest === '' ? [] : rest.split(/\s+/);
    readStatement({ m: current, keyword, key, rest, args, line, warnings, fromD, base });
  }
  return { materials, warnings: warnings.result() };
}

/** One statement inside a material: where it is, what it says, and where its findings go. */
interface Statement {
  m: MtlMaterial;
  keyword: string;
  /** The keyword in lower case. */
  key: string;
  rest: string;
  args: string[];
  line: number;
  warnings: Warnings;
  /** Materials whose opacity came from d, which beats Tr. */
  fromD: Set<MtlMaterial>;
  /** The file's own URL, which texture paths are relative to; null when it has none. */
  base: URL | null;
}

/** Sets what statement `s` gives its material; a malformed or unknown one is a warning. */
function readStatement(s: Statement): void {
  const { m, key, keyword, line, warnings } = s;
  switch (key) {
    case 'ka': case 'kd': case 'ks': {
      const v = numbers(s, 1, 3);
      if (v === null) break;
      const rgb: Rgb = v.length === 3 ? [v[0], v[1], v[2]] : [v[0], v[0], v[0]];
      if (v.length === 2) warnings.add(line, `${shown(keyword)} with 2 values; read as grey ${v[0]}`);
      if (key === 'ka') m.ambient = rgb;
      else if (key === 'kd') m.diffuse = rgb;
      else m.specular = rgb;
      break;
    }
    case 'ns': {
      const v = numbers(s, 1, 1);
      if (v) m.shininess = clamped(s, v[0], 0, Infinity, 'Ns');
      break;
    }
    case 'd': {
      const v = numbers(s, 1, 1);
      if (v) {
        m.opacity = clamped(s, v[0], 0, 1, 'd');
        s.fromD.add(m);
      }
      break;
    }
    case 'tr': {
      // Some exporters write Tr meaning what d means; d is the standard, so it wins.
      const v = numbers(s, 1, 1);
      if (v && !s.fromD.has(m)) m.opacity = 1 - clamped(s, v[0], 0, 1, 'Tr');
      break;
    }
    case 'ni': {
      const v = numbers(s, 1, 1);
      if (v) m.ior = clamped(s, v[0], 1, Infinity, 'Ni (ior)');
      break;
    }
    case 'illum': {
      const v = numbers(s, 1, 1);
      if (v) m.illum = v[0];
      break;
    }
    case 'map_kd': case 'map_ka': {
      const map = textureOf(s);
      if (map && key === 'map_kd') m.diffuseMap = map;
      else if (map) m.ambientMap = map;
      break;
    }
    default:
      if (!KNOWN_UNUSED.has(key)) warnings.addOncePerKeyword(keyword.slice(0, 64), line, `unknown statement ${shown(keyword)}; ignored`);
  }
}

/**
 * A map_Kd or map_Ka statement's texture, its path resolved against the MTL's URL; null (with a
 * warning) when it has no path or one that makes no URL: that costs the texture, never the file.
 */
function textureOf(s: Statement): MtlTexture | null {
  const map = readMapStatement(s.rest, (message) => s.warnings.add(s.line, `${s.keyword}: ${message}`));
  if (map === null || s.base === null) return map;
  try {
    map.url = new URL(map.path, s.base).href;
  } catch {
    s.warnings.add(s.line, `${s.keyword} ${shown(map.path)} is not a usable URL; texture ignored`);
    return null;
  }
  return map;
}

/** `url` as a base for texture paths, or null when it is not an absolute URL (a file read inline, a test). */
function absoluteBase(url: string): URL | null {
  try {
    return new URL(url);
  } catch {
    return null;
  }
}

/** The statement's min..max numbers, or null (with a warning) when it has not that many. */
function numbers(s: Statement, min: number, max: number): number[] | null {
  const { args } = s;
  if (args.length < min || args.length > max || !args.every((a) => isNumberToken(a))) {
    s.warnings.add(s.line, `${shown(s.keyword)} needs ${min === max ? min : `${min} to ${max}`} numbers, got ${shown(s.rest)}; ignored`);
    return null;
  }
  return args.map(Number);
}

/** `value` within lo..hi, with a warning naming `what` when it had to be moved there. */
function clamped(s: Statement, value: number, lo: number, hi: number, what: string): number {
  if (value >= lo && value <= hi) return value;
  const c = Math.min(hi, Math.max(lo, value));
  s.warnings.add(s.line, `${what} ${value} is outside ${lo}..${hi === Infinity ? '' : hi}; using ${c}`);
  return c;
}

/** Parses MTL bytes (UTF-8 or UTF-16 with a BOM), their content sniffed once. */
export function parseMtlBytes(bytes: Bytes, options: { url?: string } = {}): MtlResult {
  const sniffed = sniffModel(bytes);
  if (sniffed === 'binary') throw new LoadError(options.url ?? '', 'binary content, not an MTL file');
  return parseMtl(decodeText(bytes), { ...options, sniffed });
}
