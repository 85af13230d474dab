// A stand-in WebGL2 context for unit tests of GL-side bookkeeping: every call succeeds and is
// counted; shaders compile unless `failCompile` says otherwise for their source.
export interface FakeGl {
  gl: WebGL2RenderingContext;
  calls: Map<string, number>;
  /** Shader sources passed to shaderSource, in order. */
  sources: string[];
  failCompile: (source: string) => boolean;
}

export function fakeGl(): FakeGl {
  const calls = new Map<string, number>();
  const sources: string[] = [];
  const shaderSources = new Map<object, string>();
  const fake: FakeGl = { gl: null as unknown as WebGL2RenderingContext, calls, sources, failCompile: () => false };
  const methods: Record<string, (...a: unknown[]) => unknown> = {
    createShader: () => ({}),
    createProgram: () => ({}),
    shaderSource: (s, src) => { shaderSources.set(s as object, src as string); sources.push(src as string); },
    getShaderParameter: (s) => !fake.failCompile(shaderSources.get(s as object) ?? ''),
    getProgramParameter: () => true,
    getShaderInfoLog: () => 'ERROR: 0:1: injected failure',
    isContextLost: () => false,
  };
  fake.gl = new Proxy({}, {
    get(_t, name: string) {
      if (/^[A-Z_0-9]+$/.test(name)) return name; // enums: any distinct value will do
      return (...args: unknown[]) => {
        calls.set(name, (calls.get(name) ?? 0) + 1);
        return methods[name]?.(...args);
      };
    },
  }) as WebGL2RenderingContext;
  return fake;
}
