// The course's `iluminacao.txt` (docs/course-files.md#lighting-file): Pl / ka / Ia / kd / Od / ks / Il / n, one per line.
import type { LoadWarning } from '../load-error';
import { Warnings } from '../warnings';
import type { CourseLight, CourseMaterial } from '../../math/course-phong';
import type { Vec3 } from '../../math/course-camera';
import { CourseLines, rejectNonText } from './course-text';

export type { CourseLight, CourseMaterial } from '../../math/course-phong';

export interface LightingTxtResult {
  /** A point light at Pl with Ia and Il (0..255). */
  light: CourseLight;
  /** The material of the element's objects: ka, kd, ks, Od, n. */
  material: CourseMaterial;
  warnings: LoadWarning[];
}

/** Each line: its name, how many numbers, and the range a value is clamped to (with a warning). */
const LINES: readonly [string, 1 | 3, number, number][] = [
  ['Pl', 3, -Infinity, Infinity], ['ka', 1, 0, 1], ['Ia', 3, 0, 255], ['kd', 1, 0, 1],
  ['Od', 3, 0, 1], ['ks', 1, 0, 1], ['Il', 3, 0, 255], ['n', 1, 0, Infinity],
];

/**
 * Reads the 8 lines. A missing line or number, or a token that is not a number, is a
 * LoadError with its line; a value outside its range (ka, kd, ks, Od in 0..1; Ia, Il in
 * 0..255; n ≥ 0) is clamped with a warning; values or lines past these are ignored with
 * a warning.
 */
export function parseLightingTxt(text: string, options: { url?: string } = {}): LightingTxtResult {
  const url = options.url ?? '';
  rejectNonText(text, url, 'a lighting file (iluminacao.txt)');
  const lines = new CourseLines(text, url);
  const warnings = new Warnings();
  const values: number[][] = [];
  for (const [name, count, lo, hi] of LINES) {
    const l = lines.require(count, `no line for ${name}`);
    const read = lines.numbers(l, count, name);
    if (l.tokens.length > count) warnings.add(l.line, `values after the ${count === 1 ? 'one' : count} of ${name} ignored`);
    values.push(read.map((x) => {
      if (x >= lo && x <= hi) return x;
      const clamped = Math.min(hi, Math.max(lo, x));
      warnings.add(l.line, `${name} ${x} is outside ${lo}..${hi === Infinity ? '' : hi}; using ${clamped}`);
      return clamped;
    }));
  }
  const rest = lines.rest();
  if (rest) warnings.add(rest.first, `${rest.count} line${rest.count === 1 ? '' : 's'} after n; ignored`);
  const [pl, [ka], ia, [kd], od, [ks], il, [n]] = values;
  return {
    light: { position: pl as Vec3, ambient: ia as Vec3, intensity: il as Vec3 },
    material: { ka, kd, ks, od: od as Vec3, n },
    warnings: warnings.result(),
  };
}
