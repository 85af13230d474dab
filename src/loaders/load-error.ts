// The one error a loader throws, and the warning record every loader returns.

/** A recoverable fault: the statement on `line` (1-based) was skipped, the rest of the file used. */
export interface LoadWarning {
  line: number;
  message: string;
}

/** What the element puts in its `error` event's detail (docs/scene-model.md#loading). */
export interface LoadErrorDetail {
  type: 'load';
  url: string;
  line?: number;
  message: string;
}

/**
 * Nothing usable could be read: not the format at all (an HTML page, binary bytes) or no
 * drawable content. `message` is console-ready text (prefixed, with URL and line); `detail`
 * holds the bare parts for the `error` event.
 */
export class LoadError extends Error {
  readonly url: string;
  readonly line: number | undefined;
  readonly detail: LoadErrorDetail;

  constructor(url: string, message: string, line?: number) {
    super(`glass-plane-scene: ${where(url, line)}: ${message}`);
    this.name = 'LoadError';
    this.url = url;
    this.line = line;
    this.detail = line === undefined ? { type: 'load', url, message } : { type: 'load', url, line, message };
  }
}

/** Console text for a warning, in the same shape as a LoadError's message. */
export function warningText(url: string, warning: LoadWarning): string {
  return `glass-plane-scene: ${where(url, warning.line)}: ${warning.message}`;
}

function where(url: string, line: number | undefined): string {
  const name = url === '' ? '(inline)' : url;
  return line === undefined ? name : `${name} line ${line}`;
}
