// The Draco decoder's WebAssembly as a file beside the built chunks (docs/gltf.md#compression):
// `virtual:draco-wasm-url` is its URL. In a build the file is emitted as an asset and the URL
// resolved against the importing chunk (a page's chunk or the glTF worker's); on the dev server it
// is the package's own file. Library builds would inline an imported `.wasm?url` as base64 in a
// script; this keeps it the binary it is, fetched only by a Draco file.
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import type { Plugin } from 'vite';

const ID = 'virtual:draco-wasm-url';
// Under a path, so that the chunk table can put it in the decoder's chunk (src/frame/chunks.ts).
const RESOLVED = '\0/virtual/draco-wasm-url.js';

export function dracoWasm(): Plugin {
  let serve = false;
  const file = createRequire(import.meta.url).resolve('draco3d/draco_decoder.wasm');
  return {
    name: 'draco-wasm',
    configResolved(config) {
      serve = config.command === 'serve';
    },
    resolveId(id) {
      return id === ID ? RESOLVED : null;
    },
    load(id) {
      if (id !== RESOLVED) return null;
      if (serve) return `export default ${JSON.stringify(`/@fs${file}`)};`;
      const ref = this.emitFile({ type: 'asset', name: 'draco_decoder.wasm', source: readFileSync(file) });
      return `export default import.meta.ROLLUP_FILE_URL_${ref};`;
    },
  };
}
