// Manual check of the three.js peer: renders the default FrameState with our renderer and with
// ThreePeer side by side, shows |difference| × 8, prints per-region differences and timings.
// Serve with `npx vite --port 5191 --strictPort` and open /bench/three-peer.html; query
// `?samples=4&scale=0.5&segments=32&type=byte&cs=none&x=..&y=..&z=..&yaw=..&pitch=..&time=..&timing=0`
// changes the frame (cs: color-space, srgb by default as on the element). bench/check-peer.mjs loads it headless and reads `window.__peerCheck`.
import { Renderer } from '../src/render/renderer';
import { DEFAULT_CAMERA_POSITION, DEFAULT_CAMERA_ROTATION, DEFAULT_CUBE_DISTANCE } from '../src/element/attributes';
import type { FrameState } from '../src/frame/types';
import { defaultFrameState } from '../tests/unit/helpers/frame-state';
import { ThreePeer, type PeerOptions } from './three-peer';

const q = new URLSearchParams(location.search);
const num = (k: string, d: number) => (q.has(k) ? Number(q.get(k)) : d);

const W = num('w', 640);
const H = num('h', 360);
const samples = num('samples', 0) as 0 | 2 | 4;
const state: FrameState = defaultFrameState({
  width: W, height: H, time: num('time', 1.25), cubeDistance: num('cube', DEFAULT_CUBE_DISTANCE), transparency: num('t', 0.5),
  ior: num('ior', 1.5), fresnel: (q.get('fresnel') ?? 'exact') as FrameState['fresnel'],
  cameraPosition: [num('x', DEFAULT_CAMERA_POSITION[0]), num('y', DEFAULT_CAMERA_POSITION[1]), num('z', DEFAULT_CAMERA_POSITION[2])],
  yaw: num('yaw', DEFAULT_CAMERA_ROTATION[0]), pitch: num('pitch', DEFAULT_CAMERA_ROTATION[1]),
  colorSpace: (q.get('cs') ?? 'srgb') as FrameState['colorSpace'], reflectionScale: num('scale', 1), samples, shading: (q.get('shading') ?? 'phong') as FrameState['shading'], tessellation: num('segments', 64),
});
const peerOptions: PeerOptions = {
  samples, reflectionScale: state.reflectionScale, sphereSegments: state.tessellation as number,
  reflectionType: (q.get('type') ?? 'half') as 'half' | 'byte',
};

function setup(id: string): HTMLCanvasElement {
  const c = document.getElementById(id) as HTMLCanvasElement;
  c.width = W;
  c.height = H;
  return c;
}

const oursCanvas = setup('ours');
const peerCanvas = setup('peer');
const diffCanvas = setup('diff');
// The element's own context attributes (alpha: true so a multisample resolve into it works).
const gl = oursCanvas.getContext('webgl2', {
  alpha: true, antialias: false, depth: true, stencil: false, premultipliedAlpha: true, preserveDrawingBuffer: false,
})!;
const ours = new Renderer(gl, {});
const peer = new ThreePeer(peerCanvas);
const peerGl = peer.renderer.getContext() as WebGL2RenderingContext;

// ---- pixels ----------------------------------------------------------------------------------

ours.render(null, state);
const a = ours.read(null, state, null, 'final').data;
const glassMask = ours.read(null, { ...state, view: 'fresnel' }, null, 'screen').data; // F as grey on visible glass, black elsewhere
peer.render(state, peerOptions);
const b = peer.readPixels();
// Re-draw so the visible canvases show the frame (the read above redrew off screen).
ours.render(null, state);

const n = W * H;
const isGlass = new Uint8Array(n);
for (let i = 0; i < n; i++) isGlass[i] = glassMask[i * 4] > 0 ? 1 : 0;
// Edges: pixels next to a change of region (glass / not) or of coverage (background / not) in either image.
const bg = (d: Uint8ClampedArray, i: number) => Math.abs(d[i * 4] - 26) <= 1 && Math.abs(d[i * 4 + 1] - 26) <= 1 && Math.abs(d[i * 4 + 2] - 26) <= 1;
const cls = (d: Uint8ClampedArray, i: number) => isGlass[i] * 2 + (bg(d, i) ? 1 : 0);
const edge = new Uint8Array(n);
for (let y = 0; y < H; y++) {
  for (let x = 0; x < W; x++) {
    const i = y * W + x;
    const ca = cls(a, i);
    const cb = cls(b, i);
    for (let dy = -1; dy <= 1 && !edge[i]; dy++) {
      for (let dx = -1; dx <= 1; dx++) {
        const xx = x + dx;
        const yy = y + dy;
        if (xx < 0 || yy < 0 || xx >= W || yy >= H) continue;
        const j = yy * W + xx;
        if (cls(a, j) !== ca || cls(b, j) !== cb) { edge[i] = 1; break; }
      }
    }
  }
}

interface Stats { pixels: number; meanAbs: [number, number, number]; max: number; over1: number; over8: number }
function stats(select: (i: number) => boolean): Stats {
  const sum = [0, 0, 0];
  let max = 0, count = 0, over1 = 0, over8 = 0;
  for (let i = 0; i < n; i++) {
    if (!select(i)) continue;
    count++;
    let m = 0;
    for (let c = 0; c < 3; c++) {
      const d = Math.abs(a[i * 4 + c] - b[i * 4 + c]);
      sum[c] += d;
      if (d > m) m = d;
    }
    if (m > max) max = m;
    if (m > 1) over1++;
    if (m > 8) over8++;
  }
  const r = (v: number) => Math.round((v / Math.max(1, count)) * 1000) / 1000;
  return { pixels: count, meanAbs: [r(sum[0]), r(sum[1]), r(sum[2])], max, over1, over8 };
}
const regions = {
  all: stats(() => true),
  notGlass: stats((i) => !isGlass[i]),
  notGlassNoEdges: stats((i) => !isGlass[i] && !edge[i]),
  glass: stats((i) => isGlass[i] === 1),
  glassNoEdges: stats((i) => isGlass[i] === 1 && !edge[i]),
};

const dctx = diffCanvas.getContext('2d')!;
const img = dctx.createImageData(W, H);
for (let i = 0; i < n; i++) {
  let m = 0;
  for (let c = 0; c < 3; c++) m = Math.max(m, Math.abs(a[i * 4 + c] - b[i * 4 + c]));
  const v = Math.min(255, m * 8);
  img.data[i * 4] = v;
  img.data[i * 4 + 1] = isGlass[i] ? 0 : v;
  img.data[i * 4 + 2] = isGlass[i] ? 0 : v;
  img.data[i * 4 + 3] = 255;
}
dctx.putImageData(img, 0, 0);

// ---- timing ----------------------------------------------------------------------------------

const px = new Uint8Array(4);
function close(g: WebGL2RenderingContext): void {
  g.bindFramebuffer(g.FRAMEBUFFER, null);
  g.readPixels(0, 0, 1, 1, g.RGBA, g.UNSIGNED_BYTE, px);
}
function median(v: number[]): number {
  const s = [...v].sort((x, y) => x - y);
  return Math.round(s[s.length >> 1] * 100) / 100;
}
type Timing = { median: number; min: number; max: number };
function summary(ms: number[]): Timing {
  const r = (v: number) => Math.round(v * 100) / 100;
  return { median: median(ms), min: r(Math.min(...ms)), max: r(Math.max(...ms)) };
}
/** Frames of ours and the peer alternate, so drift in the machine's speed hits both alike. */
function timePair(sm: 0 | 2 | 4, frames = num('frames', 30)): { ours: Timing; peer: Timing } {
  const msOurs: number[] = [];
  const msPeer: number[] = [];
  for (let k = -3; k < frames; k++) {
    const s = { ...state, samples: sm, time: state.time + k / 60 };
    let t0 = performance.now();
    ours.render(null, s);
    close(gl);
    if (k >= 0) msOurs.push(performance.now() - t0);
    t0 = performance.now();
    peer.render(s, { ...peerOptions, samples: sm });
    close(peerGl);
    if (k >= 0) msPeer.push(performance.now() - t0);
  }
  return { ours: summary(msOurs), peer: summary(msPeer) };
}
const timing: Record<string, Timing> = {};
if (q.get('timing') !== '0') {
  for (const sm of [0, 4] as const) {
    const t = timePair(sm);
    timing[`ours samples ${sm}`] = t.ours;
    timing[`peer samples ${sm}`] = t.peer;
  }
  // Leave the visible canvases showing the checked frame.
  ours.render(null, state);
  peer.render(state, peerOptions);
}

/** FNV-1a of the peer's pixels: tells a changed peer frame from an unchanged one. */
function fnv1a(d: Uint8ClampedArray): string {
  let h = 0x811c9dc5;
  for (let i = 0; i < d.length; i++) h = Math.imul(h ^ d[i], 0x01000193);
  return (h >>> 0).toString(16).padStart(8, '0');
}

// The bench draws both colour spaces with one peer: a frame after a switch away and back must
// be the frame drawn fresh (the same hash).
peer.render({ ...state, colorSpace: state.colorSpace === 'srgb' ? 'none' : 'srgb' }, peerOptions);
peer.render(state, peerOptions);
const peerHashAfterSwitch = fnv1a(peer.readPixels());
peer.render(state, peerOptions);

const result = { state, peerOptions, regions, peerHash: fnv1a(b), peerHashAfterSwitch, timing, renderer: peerGl.getParameter(peerGl.RENDERER) as string };
(window as unknown as { __peerCheck: unknown }).__peerCheck = result;
document.getElementById('out')!.textContent = JSON.stringify(result, null, 1);
document.body.dataset.done = '1';
