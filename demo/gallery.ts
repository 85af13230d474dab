// Model gallery, a model viewer over a glass floor: switch models, and change Ka, Kd, Ks, shininess, Ia, Id, Is
// and the mapping mode. Each control writes one attribute of the element's children; the
// controls follow the attributes back when something else changes them.
import '../src/index';
import type { LoadErrorDetail, ModelProgress } from '../src/index';

const model = document.getElementById('model')!;
const status = document.getElementById('status')!;
const targets: Record<string, Element> = { model, light: document.getElementById('light')! };

const MODELS: Record<string, Record<string, string>> = {
  bunny: { src: 'models/bunny.obj', texture: 'models/marble.png', mapping: 'spherical' },
  dragon: { src: 'models/dragon.obj', texture: 'models/bricks.png', mapping: 'triplanar' },
  // No texture attribute: the MTL's map_Kd gives it.
  torus: { src: 'models/torus.obj', texture: '', mapping: 'uv' },
};

const controls = [...document.querySelectorAll<HTMLInputElement | HTMLSelectElement>('[data-attr]')];

/** A grey control writes "x x x"; the others their value. */
function write(input: HTMLInputElement | HTMLSelectElement): void {
  const value = 'grey' in input.dataset ? `${input.value} ${input.value} ${input.value}` : input.value;
  targets[input.dataset.target!].setAttribute(input.dataset.attr!, value);
}

function show(input: HTMLInputElement | HTMLSelectElement): void {
  const output = input.closest('label')?.querySelector('output');
  if (output) output.textContent = input.value;
}

/** Controls follow their attribute (set by this page, the console or another script). */
function follow(): void {
  for (const input of controls) {
    const raw = targets[input.dataset.target!].getAttribute(input.dataset.attr!);
    if (raw !== null && raw !== '') input.value = raw.trim().split(/\s+/)[0];
    show(input);
  }
}

for (const input of controls) input.addEventListener('input', () => { write(input); show(input); });
for (const target of Object.values(targets)) new MutationObserver(follow).observe(target, { attributes: true });
follow();

document.getElementById('model-select')!.addEventListener('change', (e) => {
  const chosen = MODELS[(e.target as HTMLSelectElement).value];
  for (const [name, value] of Object.entries(chosen)) {
    if (value === '') model.removeAttribute(name);
    else model.setAttribute(name, value);
  }
});

const detail = <T>(e: Event) => (e as CustomEvent<T>).detail;
model.addEventListener('progress', (e) => { status.textContent = `loading… ${Math.round(detail<ModelProgress>(e).loaded / 1024)} kB`; });
model.addEventListener('load', (e) => { status.textContent = `loaded ${detail<{ url: string }>(e).url.split('/').pop()}`; });
model.addEventListener('error', (e) => { status.textContent = `error: ${detail<LoadErrorDetail>(e).message}`; });
