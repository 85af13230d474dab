// What colour held in linear light costs this GPU, by render-target format (RGBA8, SRGB8_ALPHA8,
// RGBA16F) and samples (0, 4) at 640×360: clear, a full-screen opaque draw, a full-screen
// premultiplied blend over it, and the multisample resolve (blitFramebuffer into a single-sample
// texture of the same format), each closed by a 1-pixel readback. `node bench/formats-probe.mjs`.
// Measured on SwiftShader (2 shared cores, ms/frame, three runs), cumulative: RGBA8 MSAA 4 opaque
// 3.0–4.2, + blend 5.1–6.0, opaque + resolve 2.8–3.1; SRGB8_ALPHA8 MSAA 4 opaque 9.5–10.7, + blend
// 22.2–23.2, opaque + resolve 40.9–45.0; RGBA16F MSAA 4 opaque 16.0–24.2, + blend 28.2–42.5, opaque
// + resolve 28.1–31.8. The resolve of an SRGB8_ALPHA8 target alone costs 30–35 ms here (RGBA8's ~0):
// with color-space srgb every multisampled pass pays it, on this software rasterizer only.
const W = 640, H = 360;
const canvas = document.getElementById('c') as HTMLCanvasElement;
const gl = canvas.getContext('webgl2', { alpha: true, antialias: false, depth: true, stencil: false, premultipliedAlpha: true, preserveDrawingBuffer: false })!;
gl.getExtension('EXT_color_buffer_float');
function sh(type: number, src: string) { const s = gl.createShader(type)!; gl.shaderSource(s, src); gl.compileShader(s); if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(s)!); return s; }
function prog(fs: string) {
  const p = gl.createProgram()!;
  gl.attachShader(p, sh(gl.VERTEX_SHADER, `#version 300 es
  void main(){ vec2 v = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0); gl_Position = vec4(v, 0.5, 1.0); }`));
  gl.attachShader(p, sh(gl.FRAGMENT_SHADER, fs)); gl.linkProgram(p); return p;
}
const solid = prog(`#version 300 es
precision highp float; out vec4 o; void main(){ o = vec4(fract(gl_FragCoord.xy / 97.0), 0.3, 1.0); }`);
const glass = prog(`#version 300 es
precision highp float; out vec4 o; void main(){ o = vec4(0.1, 0.2, 0.3, 0.5); }`);
const px = new Uint8Array(4);
const FORMATS: Record<string, number> = { RGBA8: gl.RGBA8, SRGB8_ALPHA8: gl.SRGB8_ALPHA8, RGBA16F: gl.RGBA16F };
function target(format: number, samples: number) {
  const fb = gl.createFramebuffer()!; gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
  const depth = gl.createRenderbuffer()!; gl.bindRenderbuffer(gl.RENDERBUFFER, depth);
  if (samples) gl.renderbufferStorageMultisample(gl.RENDERBUFFER, samples, gl.DEPTH_COMPONENT24, W, H); else gl.renderbufferStorage(gl.RENDERBUFFER, gl.DEPTH_COMPONENT24, W, H);
  gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, depth);
  if (samples) {
    const rb = gl.createRenderbuffer()!; gl.bindRenderbuffer(gl.RENDERBUFFER, rb);
    gl.renderbufferStorageMultisample(gl.RENDERBUFFER, samples, format, W, H);
    gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.RENDERBUFFER, rb);
  } else {
    const t = gl.createTexture()!; gl.bindTexture(gl.TEXTURE_2D, t); gl.texStorage2D(gl.TEXTURE_2D, 1, format, W, H);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, t, 0);
  }
  if (gl.checkFramebufferStatus(gl.FRAMEBUFFER) !== gl.FRAMEBUFFER_COMPLETE) throw new Error('incomplete');
  return fb;
}
function time(name: string, draw: () => void, frames = 20) {
  for (let i = 0; i < 3; i++) draw();
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
  const t0 = performance.now();
  for (let i = 0; i < frames; i++) { draw(); gl.bindFramebuffer(gl.FRAMEBUFFER, null); gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px); }
  return [name, +((performance.now() - t0) / frames).toFixed(2)] as const;
}
const out: (readonly [string, number])[] = [];
for (const [fname, format] of Object.entries(FORMATS)) {
  for (const samples of [0, 4]) {
    const fb = target(format, samples);
    const resolve = samples ? target(format, 0) : null;
    const clear = () => { gl.bindFramebuffer(gl.FRAMEBUFFER, fb); gl.viewport(0, 0, W, H); gl.clearColor(0.1, 0.1, 0.1, 1); gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT); };
    const opaque = () => { gl.disable(gl.BLEND); gl.enable(gl.DEPTH_TEST); gl.useProgram(solid); gl.drawArrays(gl.TRIANGLES, 0, 3); };
    const blend = () => { gl.enable(gl.BLEND); gl.blendFunc(gl.ONE, gl.ONE_MINUS_SRC_ALPHA); gl.disable(gl.DEPTH_TEST); gl.useProgram(glass); gl.drawArrays(gl.TRIANGLES, 0, 3); gl.disable(gl.BLEND); };
    const res = () => { if (!resolve) return; gl.bindFramebuffer(gl.READ_FRAMEBUFFER, fb); gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, resolve); gl.blitFramebuffer(0, 0, W, H, 0, 0, W, H, gl.COLOR_BUFFER_BIT, gl.NEAREST); };
    out.push(time(`${fname} samples ${samples}: clear`, clear));
    out.push(time(`${fname} samples ${samples}: clear + opaque full screen`, () => { clear(); opaque(); }));
    out.push(time(`${fname} samples ${samples}: clear + opaque + blended full screen`, () => { clear(); opaque(); blend(); }));
    if (resolve) out.push(time(`${fname} samples ${samples}: clear + opaque + resolve blit`, () => { clear(); opaque(); res(); }));
  }
}
(window as unknown as { __probe: unknown }).__probe = out;
document.body.dataset.done = '1';
