// Demo page: each control writes its attribute on the element; the element does the rest.
import '../src/index';

const scene = document.querySelector('glass-plane-scene')!;
const status = document.getElementById('status')!;

for (const input of document.querySelectorAll<HTMLInputElement | HTMLSelectElement>('[data-attr]')) {
  const attr = input.dataset.attr!;
  const output = input.closest('label')?.querySelector('output');
  const show = () => { if (output) output.textContent = input.value; };
  input.addEventListener('input', () => {
    scene.setAttribute(attr, input.value);
    show();
  });
  // Both ways: an attribute changed elsewhere (a script, the F key, devtools) moves the control.
  const follow = () => {
    const value = scene.getAttribute(attr);
    if (value !== null && value !== input.value) {
      input.value = value;
      show();
    }
  };
  new MutationObserver(follow).observe(scene, { attributes: true, attributeFilter: [attr] });
  follow();
  show();
}

// What the chosen controls mode does, under the scene.
const HELP: Record<string, string> = {
  orbit: 'Drag to turn around the scene, right-drag or two fingers to pan, wheel or pinch to zoom; arrow keys and +/− while focused.',
  trackball: 'Drag to turn the objects (they keep spinning when flicked), right- or Shift-drag to move the light, wheel or pinch to zoom.',
  flyby: 'Click the scene, then fly: W A S D move, Space/Shift up/down, mouse or arrow keys look, F cycles the debug view, Esc releases the mouse.',
};
const help = document.getElementById('help')!;
const showHelp = () => { help.textContent = HELP[scene.getAttribute('controls') || 'flyby'] ?? ''; };
new MutationObserver(showHelp).observe(scene, { attributes: true, attributeFilter: ['controls'] });
showHelp();

// Keep the debug-view menu in step when the F key changes it inside the element.
const debugSelect = document.querySelector<HTMLSelectElement>('[data-attr="debug-view"]')!;
let frames = 0;
let last = performance.now();
scene.addEventListener('frame', () => {
  debugSelect.value = scene.debugView;
  frames++;
  const now = performance.now();
  if (now - last > 1000) {
    const { drawCalls } = scene.stats;
    status.textContent = `${Math.round((frames * 1000) / (now - last))} frames/s · ${drawCalls} draw calls · ${scene.clientWidth}×${scene.clientHeight} CSS px`;
    frames = 0;
    last = now;
  }
});
// At rest the element stops drawing once the still view is refined: say so (no frame comes to overwrite it).
scene.addEventListener('refined', (e) => { status.textContent = `at rest: ${e.detail.refinement} frames averaged, the picture is final`; });
scene.addEventListener('error', (e) => { status.textContent = `error: ${e.detail.type}`; });
