// The shadow root's styles: a constructable sheet (allowed under a strict CSP), <style> as fallback.
// The page scrolls through the element unless a controls mode takes the fingers (docs/interaction.md#touch-and-keys):
// touch-action none with [controls]. Written compact: this text ships as it is.
const CSS = `:host{display:inline-block;position:relative;width:300px;height:150px;contain:content}
:host([hidden]){display:none}
:host(:focus-visible){outline:2px solid Highlight;outline-offset:2px}
canvas{display:block;width:100%;height:100%}
:host([controls]),:host([controls]) canvas{touch-action:none}
[part=message]{position:absolute;inset:0;display:flex;align-items:center;justify-content:center;
box-sizing:border-box;padding:1em;font:14px/1.4 system-ui,sans-serif;color:#ddd;
background:#1a1a1a;text-align:center;overflow:hidden}
[part=poster]{position:absolute;inset:0;width:100%;height:100%;object-fit:cover}
[part=progress]{position:absolute;inset:auto 0 0;height:3px;background:#fff3}
[part=progress-bar]{height:100%;width:30%;background:#4a9eff}
[hidden]{display:none!important}`;

let sheet: CSSStyleSheet | null | undefined;

export function applyStyle(root: ShadowRoot): void {
  if (sheet === undefined) {
    try {
      sheet = new CSSStyleSheet();
      sheet.replaceSync(CSS);
    } catch {
      sheet = null;
    }
  }
  if (sheet && 'adoptedStyleSheets' in root) {
    root.adoptedStyleSheets = [sheet];
  } else {
    const style = document.createElement('style');
    style.textContent = CSS;
    root.append(style);
  }
}
