// Fetches a file's bytes with an AbortSignal, reading the body as a stream so that progress
// (bytes so far, and the total when the server states one) can be reported as it arrives.
import { LoadError } from '../../loaders/load-error';

export interface Progress {
  loaded: number;
  total?: number;
}

export async function fetchBytes(url: string, signal: AbortSignal, onProgress?: (p: Progress) => void): Promise<Uint8Array> {
  // A first report before the request: the loading bar (loading-view.ts) shows from here, not the first byte.
  onProgress?.({ loaded: 0 });
  let response: Response;
  try {
    response = await fetch(url, { signal });
  } catch (e) {
    if (signal.aborted) throw e;
    throw new LoadError(url, `could not be fetched (${e instanceof Error ? e.message : String(e)})`);
  }
  if (!response.ok) throw new LoadError(url, `HTTP ${response.status}${response.statusText ? ` ${response.statusText}` : ''}`);
  // Content-Length counts encoded bytes: only a total for an unencoded body.
  const length = Number(response.headers.get('content-length'));
  const encoded = (response.headers.get('content-encoding') ?? 'identity') !== 'identity';
  const total = Number.isFinite(length) && length > 0 && !encoded ? length : undefined;
  const report = (loaded: number) => onProgress?.(total === undefined ? { loaded } : { loaded, total });
  if (!response.body) {
    const bytes = new Uint8Array(await response.arrayBuffer());
    report(bytes.length);
    return bytes;
  }
  const reader = response.body.getReader();
  const chunks: Uint8Array[] = [];
  let loaded = 0;
  for (;;) {
    const { done, value } = await reader.read();
    if (done) break;
    chunks.push(value);
    loaded += value.length;
    report(loaded);
  }
  if (chunks.length === 1) return chunks[0];
  const bytes = new Uint8Array(loaded);
  let at = 0;
  for (const c of chunks) {
    bytes.set(c, at);
    at += c.length;
  }
  return bytes;
}
