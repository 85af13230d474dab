// The course page: a scene read from the course's files (docs/course-files.md), drawn by either renderer, and the
// difference image between them (|WebGL − software| × 8, from capture() of each).
import '../src/index';
import type { GlassPlaneScene } from '../src/index';

const scene = document.getElementById('scene') as GlassPlaneScene;
const status = document.getElementById('status')!;
const caption = document.getElementById('difference-caption')!;
const difference = document.getElementById('difference') as HTMLCanvasElement;

for (const input of document.querySelectorAll<HTMLSelectElement>('[data-attr]')) {
  const attr = input.dataset.attr!;
  input.value = scene.getAttribute(attr) ?? input.value;
  input.addEventListener('input', () => scene.setAttribute(attr, input.value));
  // Both ways: a change made elsewhere shows in the menu.
  new MutationObserver(() => { input.value = scene.getAttribute(attr) ?? input.value; }).observe(scene, { attributes: true, attributeFilter: [attr] });
}

const glass = document.getElementById('glass') as HTMLSelectElement;
glass.addEventListener('input', () => {
  scene.setAttribute('glass-size', glass.value);
  if (glass.value !== '0 0') {
    scene.setAttribute('glass-center', '0 -1.001 0');
    scene.setAttribute('glass-normal', '0 1 0');
  }
});

/** The next frame drawn after `change`, captured. */
function frameAfter(change: () => void): Promise<ImageData> {
  return new Promise((resolve) => {
    scene.addEventListener('frame', () => resolve(scene.capture()!), { once: true });
    change();
  });
}

document.getElementById('compare')!.addEventListener('click', async () => {
  const was = scene.getAttribute('renderer') ?? 'webgl';
  status.textContent = 'drawing with both renderers…';
  const gl = await frameAfter(() => scene.setAttribute('renderer', 'webgl'));
  const cpu = await frameAfter(() => scene.setAttribute('renderer', 'software'));
  scene.setAttribute('renderer', was);
  if (gl.width !== cpu.width || gl.height !== cpu.height) {
    status.textContent = 'the element was resized while comparing; try again';
    return;
  }
  const out = new ImageData(gl.width, gl.height);
  let sq = 0;
  for (let i = 0; i < gl.data.length; i += 4) {
    for (let c = 0; c < 3; c++) {
      const d = gl.data[i + c] - cpu.data[i + c];
      sq += d * d;
      out.data[i + c] = Math.min(255, Math.abs(d) * 8);
    }
    out.data[i + 3] = 255;
  }
  const mse = sq / ((gl.data.length / 4) * 3);
  const psnr = mse === 0 ? Infinity : 10 * Math.log10((255 * 255) / mse);
  difference.width = out.width;
  difference.height = out.height;
  difference.getContext('2d')!.putImageData(out, 0, 0);
  caption.textContent = `|WebGL − software| × 8: ${psnr.toFixed(1)} dB between the two renderers.`;
  status.textContent = '';
});

scene.addEventListener('error', (e) => { status.textContent = `error: ${e.detail.type}: ${e.detail.message}`; });
scene.addEventListener('frame', () => {
  const { renderer, thread } = scene.stats;
  status.textContent = renderer === 'software' ? `software renderer (${thread})` : 'WebGL2';
});
