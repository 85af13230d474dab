// The base of the scene element: HTMLElement where it exists (a plain class where it does not:
// server-side rendering, Node tests), with addEventListener and removeEventListener typed by the
// element's own events, so `el.addEventListener('camera-change', (e) => e.detail.position)` checks.

const Html = (typeof HTMLElement === 'undefined' ? class {} : HTMLElement) as typeof HTMLElement;

export class ElementBase<EventMap> extends Html {
  override addEventListener<K extends keyof EventMap & string>(
    type: K, listener: (this: this, ev: EventMap[K]) => unknown, options?: boolean | AddEventListenerOptions): void;
  override addEventListener(type: string, listener: EventListenerOrEventListenerObject, options?: boolean | AddEventListenerOptions): void;
  override addEventListener(type: string, listener: unknown, options?: boolean | AddEventListenerOptions): void {
    super.addEventListener(type, listener as EventListenerOrEventListenerObject, options);
  }

  override removeEventListener<K extends keyof EventMap & string>(
    type: K, listener: (this: this, ev: EventMap[K]) => unknown, options?: boolean | EventListenerOptions): void;
  override removeEventListener(type: string, listener: EventListenerOrEventListenerObject, options?: boolean | EventListenerOptions): void;
  override removeEventListener(type: string, listener: unknown, options?: boolean | EventListenerOptions): void {
    super.removeEventListener(type, listener as EventListenerOrEventListenerObject, options);
  }
}
