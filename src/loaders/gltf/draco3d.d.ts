// draco3d ships no types: the decoder factory this reader imports (its emscripten module).
declare module 'draco3d/draco_decoder_nodejs.js' {
  import type { DracoModule } from './draco';
  const create: (options: { wasmBinary: ArrayBuffer }) => Promise<DracoModule>;
  export default create;
}

// The decoder's wasm, a file beside the built chunks (scripts/draco-wasm.ts).
declare module 'virtual:draco-wasm-url' {
  const url: string;
  export default url;
}
