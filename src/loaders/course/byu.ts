// A course `.byu` of either kind (docs/course-files.md#bezier-byu): the content decides mesh or Bézier surface.
import { LoadError } from '../load-error';
import { parseByuBezier, type ByuBezierResult } from './byu-bezier';
import { parseByuMesh, type ByuMeshResult } from './byu-mesh';
import { sniffCourse } from './sniff-course';
import { sniffModel, type ModelFormat } from '../sniff';

export type ByuResult = ({ kind: 'mesh' } & ByuMeshResult) | ({ kind: 'bezier' } & ByuBezierResult);

/**
 * A mesh `.byu`, or a Bézier `.byu` when its second non-blank line holds a single number;
 * `resolution` overrides a Bézier file's E. Content that is a camera or lighting file is a
 * LoadError; anything else is read as a mesh, whose parser names the faulty line. `sniffed`:
 * the text's sniffModel, if the caller has it (the content is sniffed once per load).
 */
export function parseByu(text: string, options: { url?: string; resolution?: number; sniffed?: ModelFormat } = {}): ByuResult {
  const sniffed = options.sniffed ?? sniffModel(text);
  const format = sniffCourse(options.url ?? '', text, sniffed);
  const opts = { ...options, sniffed };
  if (format === 'byu-bezier') return { kind: 'bezier', ...parseByuBezier(text, opts) };
  if (format === 'camera' || format === 'lighting') {
    throw new LoadError(options.url ?? '', `a ${format === 'camera' ? 'camera .cfg' : 'lighting'} file, not a .byu model`);
  }
  return { kind: 'mesh', ...parseByuMesh(text, opts) };
}
