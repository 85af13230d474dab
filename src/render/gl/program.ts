// A linked GLSL program built from shader files plus #define lines; owns both shaders.
import type { ResourceCounter } from './resource-counter';

export class ShaderError extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'ShaderError';
  }
}

/** Prepends `header` lines right after `#version`, where #define and #extension must go. */
export function withHeader(source: string, header: readonly string[]): string {
  const nl = source.indexOf('\n');
  return source.slice(0, nl + 1) + header.map((l) => l + '\n').join('') + source.slice(nl + 1);
}

/** The log plus the numbered source lines it points at (ogl's addLineNumbers idea). */
function annotate(log: string, source: string): string {
  const lines = source.split('\n');
  const wanted = new Set<number>();
  for (const m of log.matchAll(/ERROR:\s*\d+:(\d+)/g)) wanted.add(Number(m[1]));
  const excerpt = lines
    .map((l, i) => [i + 1, l] as const)
    .filter(([n]) => [...wanted].some((w) => Math.abs(w - n) <= 2))
    .map(([n, l]) => `${String(n).padStart(4)}${wanted.has(n) ? '>' : ' '} ${l}`)
    .join('\n');
  return excerpt ? `${log.trim()}\n${excerpt}` : log.trim();
}

export class Program {
  readonly handle: WebGLProgram;
  private readonly shaders: WebGLShader[];
  private readonly locations = new Map<string, WebGLUniformLocation | null>();
  private disposed = false;

  constructor(
    private readonly gl: WebGL2RenderingContext,
    private readonly counter: ResourceCounter,
    readonly name: string,
    vertexSource: string,
    fragmentSource: string,
    header: readonly string[] = [],
  ) {
    const vs = this.compile(gl.VERTEX_SHADER, withHeader(vertexSource, header));
    // FRAGMENT_STAGE: what both stages share (footprint.glsl) may read textures by screen derivatives, which only a fragment shader has.
    const fs = this.compile(gl.FRAGMENT_SHADER, withHeader(fragmentSource, ['#define FRAGMENT_STAGE', ...header]), vs);
    const program = gl.createProgram()!;
    counter.add('programs');
    gl.attachShader(program, vs);
    gl.attachShader(program, fs);
    gl.linkProgram(program);
    this.handle = program;
    this.shaders = [vs, fs];
    if (!gl.getProgramParameter(program, gl.LINK_STATUS) && !gl.isContextLost()) {
      const log = gl.getProgramInfoLog(program) ?? '';
      this.dispose();
      throw new ShaderError(`glass-plane-scene: program "${name}" failed to link: ${log.trim()}`);
    }
  }

  private compile(type: number, source: string, other?: WebGLShader): WebGLShader {
    const gl = this.gl;
    const shader = gl.createShader(type)!;
    this.counter.add('shaders');
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS) && !gl.isContextLost()) {
      const log = gl.getShaderInfoLog(shader) ?? '';
      gl.deleteShader(shader);
      this.counter.add('shaders', -1);
      if (other) { gl.deleteShader(other); this.counter.add('shaders', -1); }
      const kind = type === gl.VERTEX_SHADER ? 'vertex' : 'fragment';
      throw new ShaderError(`glass-plane-scene: ${kind} shader of "${this.name}" failed to compile:\n${annotate(log, source)}`);
    }
    return shader;
  }

  use(): void {
    this.gl.useProgram(this.handle);
  }

  location(name: string): WebGLUniformLocation | null {
    let loc = this.locations.get(name);
    if (loc === undefined) {
      loc = this.gl.getUniformLocation(this.handle, name);
      this.locations.set(name, loc);
    }
    return loc;
  }

  dispose(): void {
    if (this.disposed) return;
    this.disposed = true;
    const gl = this.gl;
    for (const s of this.shaders ?? []) {
      gl.detachShader(this.handle, s);
      gl.deleteShader(s);
      this.counter.add('shaders', -1);
    }
    gl.deleteProgram(this.handle);
    this.counter.add('programs', -1);
  }
}
