// The one error a loader throws, and the warning record every loader returns.

/** A recoverable fault: the statement on `line` (1-based) was skipped, the rest of the file used. */
export interface LoadWarning {
  line: number;
  message: string;
  /** A glTF warning's JSON path (its `line` is 0): named instead of a line. */
  path?: string;
}

/** What the element puts in its `error` event's detail (docs/scene-model.md#loading). */
export interface LoadErrorDetail {
  type: 'load';
  url: string;
  /** The line of a text format (OBJ, MTL, the course's files), 1-based. */
  line?: number;
  /** The place in a glTF file's JSON, e.g. `accessors[3].bufferView` (docs/gltf.md#errors). */
  path?: string;
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
  readonly path: string | undefined;
  readonly detail: LoadErrorDetail;

  /** `at`: the line (a number) of a text format, or the JSON path (a string) of a glTF file. */
  constructor(url: string, message: string, at?: number | string) {
    super(`glass-plane-scene: ${where(url, at)}: ${message}`);
    this.name = 'LoadError';
    this.url = url;
    this.line = typeof at === 'number' ? at : undefined;
    this.path = typeof at === 'string' ? at : undefined;
    this.detail = at === undefined ? { type: 'load', url, message }
      : typeof at === 'number' ? { type: 'load', url, line: at, message } : { type: 'load', url, path: at, message };
  }
}

/** Console text for a warning, in the same shape as a LoadError's message. */
export function warningText(url: string, warning: LoadWarning): string {
  return `glass-plane-scene: ${where(url, warning.path ?? warning.line)}: ${warning.message}`;
}

function where(url: string, at: number | string | undefined): string {
  const name = url === '' ? '(inline)' : url;
  return at === undefined ? name : typeof at === 'number' ? `${name} line ${at}` : `${name} at ${at}`;
}
