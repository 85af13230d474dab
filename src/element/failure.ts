// Why the element cannot draw (docs/element.md#failure-behaviour): shown in its `message` part, fired as `error`. A missing
// WebGL2 hides the canvas; a lost context waits for the context to come back; a shader that
// failed waits for a change that may select a variant that compiles. The message part's texts are
// a lazy part (FAILURE_MESSAGES, element/parts.ts): a page that never fails never loads them.
import type { ErrorType } from './types';
import { PREFIX } from './warnings';

export class Failure {
  /** What keeps the element from drawing now; null: nothing does. */
  type: ErrorType | null = null;
  /** The message part, shown while a failure is in force (until a frame is drawn again). */
  readonly message: HTMLElement;
  /** The shader error last reported: the same one again (the same broken variant) is not news. */
  private reported: unknown = null;

  /** `messages`: fetches the message part's texts (null if they cannot load). */
  constructor(
    private readonly element: HTMLElement, private readonly canvas: HTMLCanvasElement,
    private readonly messages: () => Promise<typeof import('./failure-messages') | null>,
  ) {
    this.message = document.createElement('div');
    this.message.setAttribute('part', 'message');
    this.message.setAttribute('role', 'alert');
    this.message.hidden = true;
  }

  fail(type: ErrorType, error: unknown): void {
    const message = error instanceof Error ? error.message : String(error);
    this.type = type;
    this.message.textContent = '';
    // The texts come with their chunk; without it, the error's own message.
    void this.messages().then((m) => {
      if (this.type === type) this.message.textContent = m?.FAILURE_MESSAGES[type] ?? message;
    });
    this.message.hidden = false;
    this.canvas.hidden = type === 'webgl2-unavailable';
    if (type === 'shader') {
      if (error === this.reported) return;
      this.reported = error;
    }
    // A broken shader is a bug worth a console line (with the annotated source); a missing
    // WebGL2 or a lost context is a state of the machine, reported through the event only.
    if (type === 'shader') console.error(message.startsWith(PREFIX) ? message : `${PREFIX} ${message}`);
    queueMicrotask(() => this.element.dispatchEvent(new CustomEvent('error', { detail: { type, message } })));
  }

  /** Drawing starts again (a restored context, another renderer): the message goes. */
  clear(): void {
    this.type = null;
    this.message.hidden = true;
    this.canvas.hidden = false;
  }

  /** A change may select a shader variant that compiles: try again (the message stays until a frame is drawn). */
  retry(): void {
    if (this.type === 'shader') this.type = null;
  }

  /** A frame was drawn: the message of an earlier shader failure goes. */
  drawn(): void {
    if (!this.message.hidden) this.message.hidden = true;
    this.reported = null;
  }
}
