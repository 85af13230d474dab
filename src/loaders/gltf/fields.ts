// Reading a glTF file's JSON with every value checked where it is read: a wrong type, an index
// out of range or a number out of its range is a LoadError naming the JSON path
// (`accessors[3].bufferView`, docs/gltf.md#errors), never a TypeError from deep inside.
import { LoadError } from '../load-error';

export type Obj = Readonly<Record<string, unknown>>;

/** Warnings with the JSON path they are about, once per message (docs/gltf.md#warnings). */
export interface GltfWarning {
  path: string;
  message: string;
}

const MAX_WARNINGS = 100;

/** The file being read: its URL (for errors), its top-level arrays, its warnings. */
export class GltfFile {
  readonly warnings: GltfWarning[] = [];
  /** Buffer views decoded from a compressed form (EXT_meshopt_compression), by index: read instead of their range. */
  decodedViews: ReadonlyMap<number, Uint8Array> = new Map();
  /** Accessors decoded from a Draco primitive (KHR_draco_mesh_compression), by index: their elements, tightly packed. */
  decodedAccessors: ReadonlyMap<number, Uint8Array> = new Map();
  private readonly said = new Set<string>();

  constructor(readonly url: string, readonly json: Obj) {}

  fail(path: string, message: string): never {
    throw new LoadError(this.url, message, path);
  }

  /** One warning per distinct message (a thousand primitives of points say it once). */
  warn(path: string, message: string): void {
    if (this.said.has(message) || this.warnings.length >= MAX_WARNINGS) return;
    this.said.add(message);
    this.warnings.push({ path, message });
  }

  /** A top-level array (`accessors`, `nodes`, …): empty when absent. */
  list(name: string): readonly unknown[] {
    const v = this.json[name];
    if (v === undefined) return [];
    if (!Array.isArray(v)) this.fail(name, `${name} is not an array`);
    return v;
  }

  /** Element `index` of a top-level array, which must be an object; `from` is where the index was read. */
  item(name: string, index: number, from: string): Obj {
    const list = this.list(name);
    if (index >= list.length) this.fail(from, `${name}[${index}] does not exist (${name} has ${list.length})`);
    return object(this, list[index], `${name}[${index}]`);
  }
}

export function object(file: GltfFile, v: unknown, path: string): Obj {
  if (v === null || typeof v !== 'object' || Array.isArray(v)) file.fail(path, `${path} is not an object`);
  return v as Obj;
}

/** An optional object field: undefined when absent. */
/** The JSON path of `key` in the object at `path`: `scene` at the top level, `nodes[2].mesh` below it. */
export function fieldPath(path: string, key: string): string {
  return path === '' ? key : `${path}.${key}`;
}

export function optionalObject(file: GltfFile, o: Obj, key: string, path: string): Obj | undefined {
  return o[key] === undefined ? undefined : object(file, o[key], fieldPath(path, key));
}

export function num(file: GltfFile, o: Obj, key: string, path: string, fallback?: number, min = -Infinity, max = Infinity): number {
  const v = o[key];
  if (v === undefined && fallback !== undefined) return fallback;
  // Stryker disable next-line ConditionalExpression: without the typeof test, Number.isFinite is false for every non-number too
  if (typeof v !== 'number' || !Number.isFinite(v)) file.fail(fieldPath(path, key), `${fieldPath(path, key)} is ${shownValue(v)}, not a number`);
  if (v < min || v > max) file.fail(fieldPath(path, key), `${fieldPath(path, key)} is ${v}, outside [${min}, ${max}]`);
  return v;
}

/** A non-negative integer (an index, a count, an offset), below `max`. */
export function int(file: GltfFile, o: Obj, key: string, path: string, fallback?: number, max = Number.MAX_SAFE_INTEGER): number {
  const v = num(file, o, key, path, fallback);
  if (!Number.isInteger(v) || v < 0) file.fail(fieldPath(path, key), `${fieldPath(path, key)} is ${v}, not an index or count`);
  if (v > max) file.fail(fieldPath(path, key), `${fieldPath(path, key)} is ${v}, above ${max}`);
  return v;
}

export function optionalInt(file: GltfFile, o: Obj, key: string, path: string): number | undefined {
  return o[key] === undefined ? undefined : int(file, o, key, path);
}

/** A fixed-length array of finite numbers, or `fallback` when absent. */
export function numbers(file: GltfFile, o: Obj, key: string, path: string, length: number, fallback: readonly number[]): number[] {
  const v = o[key];
  // Stryker disable next-line MethodExpression: every caller passes a fresh literal or copies the result, and none writes to it
  if (v === undefined) return fallback.slice();
  // Stryker disable next-line ConditionalExpression: without the typeof test, Number.isFinite is false for every non-number too
  if (!Array.isArray(v) || v.length !== length || !v.every((x) => typeof x === 'number' && Number.isFinite(x))) {
    file.fail(fieldPath(path, key), `${fieldPath(path, key)} is not an array of ${length} numbers`);
  }
  return v as number[];
}

export function str(file: GltfFile, o: Obj, key: string, path: string, fallback?: string): string {
  const v = o[key];
  if (v === undefined && fallback !== undefined) return fallback;
  if (typeof v !== 'string') file.fail(fieldPath(path, key), `${fieldPath(path, key)} is ${shownValue(v)}, not a string`);
  return v;
}

/** A value for a message: short, whatever it is. */
export function shownValue(v: unknown): string {
  if (v === undefined) return 'missing';
  const s = JSON.stringify(v) ?? String(v);
  return s.length > 40 ? `${s.slice(0, 40)}…` : s;
}
