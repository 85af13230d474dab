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
  show();
}

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
scene.addEventListener('error', (e) => { status.textContent = `error: ${e.detail.type}`; });
