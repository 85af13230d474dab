// The one shape of the element's parts (in the spirit of Lit's ReactiveController): the element
// keeps a list of controllers and tells each when it is connected to a document and when it
// leaves. A controller takes what it needs of the element through a small host interface of its
// own, declared in its file, and never imports the element.

export interface Controller {
  /** The element was connected: listen, observe, load, start. */
  hostConnected?(): void;
  /** The element left the document: stop everything started in hostConnected. */
  hostDisconnected?(): void;
}
