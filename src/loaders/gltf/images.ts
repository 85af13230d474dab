// A glTF file's images as references (docs/gltf.md#images): a URI (relative to the model's URL, or
// data:) or bytes of a buffer view with their MIME type. Decoding is the element's (off the main
// thread where the browser can); an image that fails costs its textures, not the model.
import { bufferView } from './buffers';
import { GltfFile, int, object, str } from './fields';

export type GltfImage =
  | { kind: 'uri'; uri: string; name: string }
  | { kind: 'bytes'; bytes: Uint8Array; mimeType: string; name: string };

const MIME_TYPES = new Set(['image/png', 'image/jpeg', 'image/webp', 'image/ktx2']);

export function readImages(file: GltfFile, buffers: readonly Uint8Array[]): GltfImage[] {
  return file.list('images').map((i, index): GltfImage => {
    const path = `images[${index}]`;
    const image = object(file, i, path);
    const name = image.name === undefined ? path : `${path} ${JSON.stringify(str(file, image, 'name', path)).slice(0, 60)}`;
    if (image.uri !== undefined) return { kind: 'uri', uri: str(file, image, 'uri', path), name };
    if (image.bufferView === undefined) file.fail(path, `${path} has neither a uri nor a bufferView`);
    const mimeType = str(file, image, 'mimeType', path, '');
    if (!MIME_TYPES.has(mimeType)) file.warn(`${path}.mimeType`, `${path}.mimeType is ${JSON.stringify(mimeType)}: read by its content`);
    const view = bufferView(file, buffers, int(file, image, 'bufferView', path), `${path}.bufferView`);
    return { kind: 'bytes', bytes: view.bytes, mimeType, name };
  });
}
