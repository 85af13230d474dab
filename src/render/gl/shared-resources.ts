// What every renderer on one WebGL2 context shares (docs/knobs.md#many-elements): compiled programs by
// variant, the procedural texture, and meshes by content. Reference-counted per context and per
// entry; the last renderer to let go frees them. A lost context's renderers all let go, so a
// restored one starts afresh.
import type { Mesh } from './mesh';
import type { Program } from './program';
import { ResourceCounter } from './resource-counter';
import { Texture } from './texture';
import { proceduralTexture } from '../../scene/procedural-texture';
import { TEXTURE_SIZE } from '../../scene/default-scene';

interface Entry<T> {
  value: T;
  users: number;
}

export class SharedResources {
  private static readonly byContext = new WeakMap<WebGL2RenderingContext, SharedResources>();

  /** The GL objects held here (not by any one renderer). */
  readonly counter = new ResourceCounter();
  /** The procedural texture as stored (RGBA8) and as sRGB colour data (SRGB8_ALPHA8). */
  private procedural: Texture | null = null;
  private proceduralSrgb: Texture | null = null;
  private readonly programs = new Map<string, Entry<Program>>();
  private readonly meshes = new Map<string, Entry<Mesh>>();
  private users = 0;

  private constructor(private readonly gl: WebGL2RenderingContext) {}

  /**
   * The procedural texture (docs/default-scene.md#the-procedural-texture): ~1.4 MB with its mipmaps, uploaded once per context and colour space
   * (`srgb`: its levels are encoded colour, decoded by the GPU; docs/colour.md#the-transfer-curve), not per element.
   * In linear light it is read anisotropically (+3 dB against the reference on the bench's
   * glass floor); `none` keeps the isotropic reads of the frames it must reproduce bit for bit.
   */
  texture(srgb: boolean): Texture {
    if (srgb) return (this.proceduralSrgb ??= this.uploadProcedural(true));
    return (this.procedural ??= this.uploadProcedural(false));
  }

  private uploadProcedural(srgb: boolean): Texture {
    return new Texture(this.gl, this.counter, {
      width: TEXTURE_SIZE, height: TEXTURE_SIZE, data: proceduralTexture(), mipmap: true, repeat: true, srgb, anisotropic: srgb,
    });
  }

  /** The context's shared resources, created for its first renderer. */
  static acquire(gl: WebGL2RenderingContext): SharedResources {
    let s = SharedResources.byContext.get(gl);
    if (!s) {
      s = new SharedResources(gl);
      SharedResources.byContext.set(gl, s);
    }
    s.users++;
    return s;
  }

  /** A renderer is done: the last one frees everything. */
  release(): void {
    if (--this.users > 0) return;
    for (const e of this.programs.values()) e.value.dispose();
    for (const e of this.meshes.values()) e.value.dispose();
    this.programs.clear();
    this.meshes.clear();
    this.procedural?.dispose();
    this.proceduralSrgb?.dispose();
    this.procedural = this.proceduralSrgb = null;
    SharedResources.byContext.delete(this.gl);
  }

  /** The program for `key`, built (by `build`, counting on `counter`) for its first user. */
  program(key: string, build: (counter: ResourceCounter) => Program): Program {
    return this.take(this.programs, key, build);
  }

  releaseProgram(key: string): void {
    this.drop(this.programs, key);
  }

  /** The mesh for a content key, built for its first user. */
  mesh(key: string, build: (counter: ResourceCounter) => Mesh): Mesh {
    return this.take(this.meshes, key, build);
  }

  releaseMesh(key: string): void {
    this.drop(this.meshes, key);
  }

  private take<T>(map: Map<string, Entry<T>>, key: string, build: (counter: ResourceCounter) => T): T {
    let e = map.get(key);
    if (!e) {
      e = { value: build(this.counter), users: 0 };
      map.set(key, e);
    }
    e.users++;
    return e.value;
  }

  private drop<T extends { dispose(): void }>(map: Map<string, Entry<T>>, key: string): void {
    const e = map.get(key);
    if (!e || --e.users > 0) return;
    e.value.dispose();
    map.delete(key);
  }
}
