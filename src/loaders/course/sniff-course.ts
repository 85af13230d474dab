// Tells the course's files apart (docs/course-files.md), in the manner of ../sniff.ts: by content first,
// the URL's name only when the content is too broken to say.
import { sniffModel, type ModelFormat } from '../sniff';
import { CourseLines, isNumber } from './course-text';

export type CourseFormat = 'byu-mesh' | 'byu-bezier' | 'camera' | 'lighting' | 'html' | 'binary' | 'unknown';

/** Numbers per line of a well-formed camera `.cfg` and of `iluminacao.txt`. */
const CAMERA = [3, 3, 3, 3];
const LIGHTING = [3, 1, 3, 1, 3, 1, 3, 1];
const COUNT = /^\d+$/;

/**
 * A `.byu` whose first non-blank line is two whole numbers is a mesh, or a Bézier surface
 * when its second non-blank line holds a single number; four lines of three numbers are a
 * camera; lines of 3, 1, 3, 1, 3, 1, 3, 1 numbers are a lighting file (those first lines:
 * lines after them are for the parsers to warn about). Content that fits none of these is
 * named by the URL (`*.cfg` a camera, `iluminacao*.txt` lighting, `*.byu` a mesh) so that
 * its parser reports the faulty line; otherwise 'unknown'. Reads only the first nine
 * non-blank lines, and a few tokens of each. `model`: the text's sniffModel, if already known.
 */
export function sniffCourse(url: string, text: string, model: ModelFormat = sniffModel(text)): CourseFormat {
  if (model === 'html' || model === 'binary') return model;
  const lines = new CourseLines(text, url);
  const shape: number[] = []; // numbers per line, −1 for a line with anything else
  const first: string[][] = [];
  for (let k = 0; k < 9; k++) {
    const l = lines.next(3);
    if (l === null) break;
    first.push(l.tokens);
    shape.push(l.tokens.length <= 3 && l.tokens.every(isNumber) ? l.tokens.length : -1);
  }
  if (first.length >= 1 && first[0].length === 2 && first[0].every((t) => COUNT.test(t))) {
    return shape[1] === 1 ? 'byu-bezier' : 'byu-mesh';
  }
  if (matches(shape, LIGHTING)) return 'lighting';
  if (matches(shape, CAMERA)) return 'camera';
  const name = (url.split(/[?#]/, 1)[0].split('/').pop() ?? '').toLowerCase();
  if (name.endsWith('.cfg')) return 'camera';
  if (/^ilumina[cç][aã]o.*\.txt$/.test(name)) return 'lighting';
  if (name.endsWith('.byu')) return 'byu-mesh';
  return 'unknown';
}

function matches(shape: number[], want: number[]): boolean {
  return want.every((n, k) => shape[k] === n);
}
