// The model worker's work as a plain function (testable without a worker): bytes in, result
// out, with the list of buffers to transfer instead of copy. OBJ, or a course `.byu`.
import { LoadError, type LoadErrorDetail } from './load-error';
import { parseObjBytes, type ObjResult } from './obj';
import { parseByuModel, type ByuBezierInfo } from './course/byu-model';
import type { ModelFormat } from './sniff';

export interface ObjJobRequest {
  id: number;
  url: string;
  bytes: ArrayBuffer;
  /** Absent: OBJ. */
  format?: 'obj' | 'byu';
  /** The content's sniffModel, as the page sniffed it (not sniffed again here). */
  sniffed?: ModelFormat;
}

export type ObjJobResponse =
  | { id: number; ok: true; result: ObjResult; bezier?: ByuBezierInfo | null }
  | { id: number; ok: false; error: LoadErrorDetail };

export function runObjJob(request: ObjJobRequest): { response: ObjJobResponse; transfer: ArrayBuffer[] } {
  try {
    const { url, sniffed } = request;
    const byu = request.format === 'byu' ? parseByuModel(request.bytes, url, sniffed) : null;
    const result = byu ? byu.obj : parseObjBytes(request.bytes, { url, sniffed });
    const arrays = [result.positions, result.normals, result.uvs, result.colors, result.indices];
    const transfer = arrays.flatMap((a) => (a ? [a.buffer as ArrayBuffer] : []));
    return { response: { id: request.id, ok: true, result, bezier: byu?.bezier ?? null }, transfer };
  } catch (e) {
    const error: LoadErrorDetail = e instanceof LoadError ? e.detail
      : { type: 'load', url: request.url, message: e instanceof Error ? e.message : String(e) };
    return { response: { id: request.id, ok: false, error }, transfer: [] };
  }
}
