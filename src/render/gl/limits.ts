// The largest side any render target may have: texture, renderbuffer and viewport limits.
export function maxTargetSize(gl: WebGL2RenderingContext): number {
  const dims = gl.getParameter(gl.MAX_VIEWPORT_DIMS) as Int32Array | null;
  if (!dims) return 4096; // lost context: any sane bound until it is restored
  return Math.min(dims[0], dims[1], gl.getParameter(gl.MAX_TEXTURE_SIZE) as number, gl.getParameter(gl.MAX_RENDERBUFFER_SIZE) as number);
}
