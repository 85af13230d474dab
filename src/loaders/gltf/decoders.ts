// The official decoders of compressed glTF (docs/gltf.md#compression), each imported only when a
// file needs it: a chunk of its own, never fetched for an uncompressed file. Draco's WebAssembly is
// a file beside its chunk, fetched with it.
// Stryker disable all: imported only in a page or its worker (a unit test injects its own decoders); the browser table judges it (scripts/mutations/lazy.mjs, Z40–Z42)
import type { DracoModule } from './draco';
import type { MeshoptDecoderLike } from './meshopt';

export interface GltfDecoders {
  meshopt(): Promise<MeshoptDecoderLike>;
  draco(): Promise<DracoModule>;
}

let draco: Promise<DracoModule> | null = null;

export const DECODERS: GltfDecoders = {
  meshopt: () => import('meshoptimizer/decoder').then((m) => m.MeshoptDecoder),
  // One module per page (or worker): its instantiation is the costly part.
  draco: () => (draco ??= loadDraco().catch((e: unknown) => {
    draco = null;
    throw e;
  })),
};

async function loadDraco(): Promise<DracoModule> {
  const [{ default: create }, { default: wasmUrl }] = await Promise.all([
    import('draco3d/draco_decoder_nodejs.js'), import('virtual:draco-wasm-url'),
  ]);
  const response = await fetch(wasmUrl);
  if (!response.ok) throw new Error(`${wasmUrl}: HTTP ${response.status}`);
  return create({ wasmBinary: await response.arrayBuffer() });
}
