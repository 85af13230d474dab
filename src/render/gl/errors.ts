// RendererOptions.checks: what gl.getError() holds after a frame, on the console (at most 8).
export function reportGlErrors(gl: WebGL2RenderingContext, frame: number): void {
  for (let e = gl.getError(), i = 0; e !== gl.NO_ERROR && i < 8; e = gl.getError(), i++) {
    console.error(`glass-plane-scene: WebGL error 0x${e.toString(16)} after frame ${frame}`);
  }
}
