// The course's camera `.cfg` (docs/course-files.md#camera-cfg): C, N, V and `d hx hy`, one per line.
import { LoadError, type LoadWarning } from '../load-error';
import { Warnings } from '../warnings';
import { courseBasis, type CourseCamera, type Vec3 } from '../../math/course-camera';
import { CourseLines, rejectNonText, type ContentLine } from './course-text';

export type { CourseCamera } from '../../math/course-camera';

export interface CameraCfgResult extends CourseCamera {
  warnings: LoadWarning[];
}

/**
 * Reads C (focus), N (view direction, any length), V (up, not necessarily orthogonal to N)
 * and `d hx hy`: N normalised, V Gram-Schmidt-orthogonalised against N and normalised,
 * U = N × V. d, hx and hy keep their signs (a negative one mirrors that axis). A missing
 * line or number, a token that is not a number, N = 0, V parallel to N or a d, hx or hy
 * of 0 is a LoadError with its line; values or lines past these are ignored with a warning.
 */
export function parseCameraCfg(text: string, options: { url?: string } = {}): CameraCfgResult {
  const url = options.url ?? '';
  rejectNonText(text, url, 'a camera .cfg file');
  const lines = new CourseLines(text, url);
  const warnings = new Warnings();
  const read = (what: string): { l: ContentLine; xyz: Vec3 } => {
    const l = lines.require(3, `no line for ${what}`);
    const [a, b, c] = lines.numbers(l, 3, what);
    if (l.tokens.length > 3) warnings.add(l.line, `values after the 3 of ${what} ignored`);
    return { l, xyz: [a, b, c] };
  };
  const c = read('C (focus)');
  const n = read('N (view direction)');
  const v = read('V (up)');
  const window = read('d hx hy');
  const [d, hx, hy] = window.xyz;
  for (const [value, name] of [[d, 'd'], [hx, 'hx'], [hy, 'hy']] as const) {
    if (value === 0) throw new LoadError(url, `${name} is 0: the screen window has no size`, window.l.line);
  }
  const rest = lines.rest();
  if (rest) warnings.add(rest.first, `${rest.count} line${rest.count === 1 ? '' : 's'} after "d hx hy"; ignored`);

  const basis = courseBasis(n.xyz, v.xyz);
  if (basis === 'zero N') throw new LoadError(url, 'N is the zero vector: no view direction', n.l.line);
  if (basis === 'V parallel to N') throw new LoadError(url, 'V is parallel to N: no up direction is left after Gram-Schmidt', v.l.line);
  return { c: c.xyz, ...basis, d, hx, hy, warnings: warnings.result() };
}
