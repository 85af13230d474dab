// Consumer test (scripts/check-package.mjs): the svelteHTML entries svelte-check reads.
import 'glass-plane-scene/svelte';

export const scene: svelteHTML.IntrinsicElements['glass-plane-scene'] = {
  fresnel: 'exact', 'debug-view': 'fresnel', onready: (e) => console.log(e.detail.width), 'on:camera-change': (e) => console.log(e.detail.target),
};
export const light: svelteHTML.IntrinsicElements['glass-light'] = { direction: '0 1 0' };
// @ts-expect-error shading is phong, gouraud or flat
export const wrong: svelteHTML.IntrinsicElements['glass-plane-scene'] = { shading: 'smooth' };
