// What a person sees while models load (docs/element.md#loading-a-person-can-see): a progress bar
// (`::part(progress)`, its fill `::part(progress-bar)`) while any child's model is on its way,
// from the children's own `progress` events, and the `poster` image until the first frame with
// the content is drawn (`ready`), then removed. The page styles or hides either by its part.

export interface LoadingViewHost {
  element: HTMLElement;
  root: ShadowRoot;
  poster(): string | null;
}

interface Loading {
  loaded: number;
  total: number | undefined;
}

export class LoadingView {
  readonly bar = document.createElement('div');
  readonly poster = document.createElement('img');
  private readonly fill = document.createElement('div');
  /** The children whose model is on its way, with their bytes so far. */
  private readonly loading = new Map<EventTarget, Loading>();
  private ready = false;

  constructor(private readonly host: LoadingViewHost) {
    this.bar.setAttribute('part', 'progress');
    this.bar.setAttribute('role', 'progressbar');
    this.bar.setAttribute('aria-label', 'Loading models');
    this.bar.hidden = true;
    this.fill.setAttribute('part', 'progress-bar');
    this.bar.append(this.fill);
    this.poster.setAttribute('part', 'poster');
    this.poster.alt = '';
    this.poster.hidden = true;
    host.root.append(this.poster, this.bar);
    const el = host.element;
    el.addEventListener('progress', (e) => this.progress(e));
    el.addEventListener('load', (e) => this.settled(e));
    el.addEventListener('error', (e) => this.settled(e));
    el.addEventListener('ready', () => {
      this.ready = true;
      this.posterChanged();
    });
  }

  /** The `poster` attribute changed (or `ready` came): shown until ready, then gone. */
  posterChanged(): void {
    const src = this.ready ? null : this.host.poster();
    if (src) this.poster.src = src;
    else this.poster.removeAttribute('src');
    this.poster.hidden = !src;
  }

  private progress(e: Event): void {
    if (e.target === this.host.element) return;
    const d = (e as CustomEvent<{ loaded?: unknown; total?: unknown }>).detail;
    if (typeof d?.loaded !== 'number') return;
    this.loading.set(e.target!, { loaded: d.loaded, total: typeof d.total === 'number' ? d.total : undefined });
    this.show();
  }

  private settled(e: Event): void {
    if (e.target === this.host.element || !this.loading.delete(e.target!)) return;
    this.show();
  }

  /** The bar: the share of bytes received where every total is known, else indeterminate. */
  private show(): void {
    let loaded = 0, total = 0, known = true;
    for (const l of this.loading.values()) {
      loaded += l.loaded;
      if (l.total === undefined) known = false;
      else total += l.total;
    }
    this.bar.hidden = this.loading.size === 0;
    const share = known && total > 0 ? Math.min(1, loaded / total) : null;
    // Indeterminate (no share): the stylesheet's 30 %, no aria-valuenow.
    this.fill.style.width = share === null ? '' : `${(100 * share).toFixed(1)}%`;
    if (share === null) this.bar.removeAttribute('aria-valuenow');
    else this.bar.setAttribute('aria-valuenow', String(Math.round(100 * share)));
  }
}
