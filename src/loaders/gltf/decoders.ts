// The official decoders of compressed glTF (docs/gltf.md#compression), each imported only when a
// file needs it: a chunk of its own, never fetched for an uncompressed file.
import type { MeshoptDecoderLike } from './meshopt';

export interface GltfDecoders {
  meshopt(): Promise<MeshoptDecoderLike>;
}

export const DECODERS: GltfDecoders = {
  meshopt: () => import('meshoptimizer/decoder').then((m) => m.MeshoptDecoder),
};
