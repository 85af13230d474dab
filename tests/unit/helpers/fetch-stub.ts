// A stand-in for `fetch` in the loading tests: a body (or an HTTP status) per absolute URL, each
// answer taken in turn, and every request counted. Restored by vi.unstubAllGlobals().
import { vi } from 'vitest';

/** A body, or an HTTP status to fail with; a list is answered one entry per request, the last repeated. */
export type Served = string | number | (string | number)[];

export function stubFetch(files: Record<string, Served>): { requests: string[] } {
  const requests: string[] = [];
  const asked = new Map<string, number>();
  vi.stubGlobal('fetch', async (input: string | URL) => {
    const url = String(input);
    requests.push(url);
    const served = files[url] ?? 404;
    const list = Array.isArray(served) ? served : [served];
    const k = asked.get(url) ?? 0;
    asked.set(url, k + 1);
    const answer = list[Math.min(k, list.length - 1)];
    return typeof answer === 'number' ? new Response('', { status: answer }) : new Response(answer);
  });
  return { requests };
}
