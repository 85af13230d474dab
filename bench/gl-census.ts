// GL memory census for the many-elements bench: wraps the WebGL2 calls that allocate (bufferData,
// texImage2D, texStorage2D, renderbufferStorage[Multisample], generateMipmap) and delete, and
// keeps the bytes of each live object. Independent of the renderer's own bookkeeping: an
// estimate from what was asked of GL (drivers pad and may keep more), not a measurement of VRAM.
// Default framebuffers (canvases) are not GL objects and are reported apart.
const P = WebGL2RenderingContext.prototype;
const GL = WebGL2RenderingContext;

type Kind = 'buffers' | 'textures' | 'renderbuffers';
const bytes = new Map<object, { kind: Kind; levels: Map<number, number> }>();
const boundBuffer = new Map<number, WebGLBuffer | null>();
let activeUnit: number = GL.TEXTURE0;
const boundTexture = new Map<string, WebGLTexture | null>();
let boundRenderbuffer: WebGLRenderbuffer | null = null;
let bufferUploads: number[] = [];

/** Bytes per texel of the formats the renderer and peers use. */
function texelBytes(internalFormat: number, type?: number): number {
  switch (internalFormat) {
    case GL.RGBA16F: return 8;
    case GL.RGBA32F: return 16;
    case GL.RGB8: case GL.RGB: return type === GL.FLOAT ? 12 : 3;
    case GL.R8: case GL.LUMINANCE: case GL.ALPHA: return 1;
    case GL.RG8: return 2;
    case GL.DEPTH_COMPONENT16: return 2;
    default: return 4; // RGBA8, RGBA, SRGB8_ALPHA8, DEPTH_COMPONENT24, DEPTH24_STENCIL8, DEPTH_COMPONENT32F
  }
}

function record(obj: object | null | undefined, kind: Kind, level: number, n: number): void {
  if (!obj) return;
  const e = bytes.get(obj) ?? { kind, levels: new Map() };
  e.levels.set(level, n);
  bytes.set(obj, e);
}

const wrap = <K extends keyof WebGL2RenderingContext>(name: K, after: (...args: any[]) => void) => {
  const original = P[name] as unknown as (...args: unknown[]) => unknown;
  (P as any)[name] = function (this: WebGL2RenderingContext, ...args: unknown[]) {
    const r = original.apply(this, args);
    after(...args);
    return r;
  };
};

wrap('bindBuffer', (target: number, b: WebGLBuffer | null) => boundBuffer.set(target, b));
wrap('bufferData', (target: number, data: number | ArrayBufferView | ArrayBuffer | null) => {
  const n = typeof data === 'number' ? data : data ? data.byteLength : 0;
  record(boundBuffer.get(target), 'buffers', 0, n);
  bufferUploads.push(n);
});
wrap('activeTexture', (unit: number) => { activeUnit = unit; });
wrap('bindTexture', (target: number, t: WebGLTexture | null) => boundTexture.set(`${activeUnit}:${target}`, t));
const texture = (target: number) => boundTexture.get(`${activeUnit}:${target === GL.TEXTURE_2D ? target : GL.TEXTURE_CUBE_MAP}`);
wrap('texImage2D', (target: number, level: number, internalFormat: number, ...rest: any[]) => {
  let w: number, h: number, type: number;
  if (rest.length >= 5) [w, h, , , type] = rest; // (w, h, border, format, type, …)
  else { const src = rest[2] as { width: number; height: number }; w = src.width; h = src.height; type = rest[1]; }
  record(texture(target), 'textures', target * 100 + level, w * h * texelBytes(internalFormat, type));
});
wrap('texStorage2D', (target: number, levels: number, internalFormat: number, w: number, h: number) => {
  for (let l = 0; l < levels; l++) record(texture(target), 'textures', target * 100 + l, Math.max(1, w >> l) * Math.max(1, h >> l) * texelBytes(internalFormat));
});
wrap('generateMipmap', (target: number) => {
  const t = texture(target);
  const e = t && bytes.get(t);
  const base = e?.levels.get(target * 100) ?? 0;
  if (e) e.levels.set(target * 100 + 1, Math.round(base / 3)); // the whole chain below level 0: ⅓ of it
});
wrap('bindRenderbuffer', (_: number, r: WebGLRenderbuffer | null) => { boundRenderbuffer = r; });
wrap('renderbufferStorage', (_: number, fmt: number, w: number, h: number) => record(boundRenderbuffer, 'renderbuffers', 0, w * h * texelBytes(fmt)));
wrap('renderbufferStorageMultisample', (_: number, samples: number, fmt: number, w: number, h: number) =>
  record(boundRenderbuffer, 'renderbuffers', 0, Math.max(1, samples) * w * h * texelBytes(fmt)));
for (const name of ['deleteBuffer', 'deleteTexture', 'deleteRenderbuffer'] as const) wrap(name, (o: object | null) => { if (o) bytes.delete(o); });

export interface Census {
  buffers: number;
  textures: number;
  renderbuffers: number;
  total: number;
  /** Sizes of every bufferData call since the last reset, largest first. */
  bufferUploads: number[];
}

const api = {
  census(): Census {
    const c: Census = { buffers: 0, textures: 0, renderbuffers: 0, total: 0, bufferUploads: [...bufferUploads].sort((a, b) => b - a) };
    for (const { kind, levels } of bytes.values()) {
      let n = 0;
      for (const v of levels.values()) n += v;
      c[kind] += n;
      c.total += n;
    }
    return c;
  },
  resetUploads(): void {
    bufferUploads = [];
  },
};
(window as unknown as { __census: typeof api }).__census = api;
await import('../src/index');
(window as unknown as { __ready: boolean }).__ready = true;
