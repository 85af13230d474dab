import 'glass-plane-scene';                         // defines the three elements
import type { GlassPlaneScene } from 'glass-plane-scene';

const scene = document.querySelector('glass-plane-scene')!; // typed: GlassPlaneScene
scene.transparency = 0.8;                                   // reflects to the attribute
scene.addEventListener('frame', (e) => console.log(e.detail.passes));
