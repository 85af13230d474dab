// Tells the model formats apart by content (docs/scene-model.md#loading: "sniffed from the content, not only the
// extension"), from the first few KB: an OBJ, a course .byu, a glTF (GLB bytes or JSON text), or something that is no model.
import { asUint8, decodeText, type Bytes } from './decode-text';

export type ModelFormat = 'obj' | 'byu-mesh' | 'byu-bezier' | 'gltf' | 'html' | 'binary' | 'unknown';

export const SAMPLE = 4096;

/** Statements that open an OBJ file in practice (the geometry ones and the common headers). */
const OBJ_KEYWORDS = new Set([
  'v', 'vt', 'vn', 'vp', 'f', 'fo', 'l', 'p', 'o', 'g', 's', 'usemtl', 'mtllib', 'cstype', 'deg', 'curv', 'surf',
]);

/**
 * The format of a model file's content. A load sniffs once and hands the result on to the
 * parsers (their `sniffed` option), which sniff again only when called without it.
 */
export function sniffModel(input: string | Bytes): ModelFormat {
  if (typeof input !== 'string' && startsAsGlb(asUint8(input))) return 'gltf';
  const sample = typeof input === 'string' ? input.slice(0, SAMPLE) : decodeText(input, SAMPLE);
  const text = sample.charCodeAt(0) === 0xfeff ? sample.slice(1) : sample;
  if (looksBinary(text)) return 'binary';
  const start = text.search(/\S/);
  if (start < 0) return 'unknown';
  // No OBJ or .byu line starts with '<'; a dev server's 404 page, an XML error or an SVG does.
  if (text.charCodeAt(start) === 0x3c) return 'html';
  // No OBJ or .byu line starts with '{': JSON, read as glTF (which names what is missing if it is not).
  if (text.charCodeAt(start) === 0x7b) return 'gltf';

  const lines = text.split(/\r\n|\r|\n/).map((l) => l.trim()).filter((l) => l !== '');
  const first = lines[0].split(/\s+/);
  if (first.length === 2 && first.every(isCount)) {
    const second = lines.length > 1 ? lines[1].split(/\s+/) : [];
    return second.length === 1 && Number.isFinite(Number(second[0])) ? 'byu-bezier' : 'byu-mesh';
  }
  for (const line of lines) {
    if (line.startsWith('#')) continue;
    return OBJ_KEYWORDS.has(line.split(/\s/, 1)[0]) ? 'obj' : 'unknown';
  }
  return 'obj'; // only comments: an OBJ header with nothing after it (the parser says so)
}

function isCount(token: string): boolean {
  return /^\d+$/.test(token);
}

/**
 * Many control characters (NUL above all) or undecodable bytes: an image, an archive, a
 * UTF-16 file without its BOM. Text files have none beyond tab, CR, LF and form feed. At
 * least 2 are needed: the sample's end may cut one multi-byte character into a U+FFFD.
 */
function looksBinary(text: string): boolean {
  let bad = 0;
  for (let i = 0; i < text.length; i++) {
    const c = text.charCodeAt(i);
    if ((c < 32 && c !== 9 && c !== 10 && c !== 12 && c !== 13) || c === 0x7f || c === 0xfffd) bad++;
  }
  return bad >= 2 && bad * 50 > text.length;
}

/** "glTF" then version 2, little-endian: a GLB's header (docs/gltf.md#containers). */
function startsAsGlb(b: Uint8Array): boolean {
  return b.length >= 8 && b[0] === 0x67 && b[1] === 0x6c && b[2] === 0x54 && b[3] === 0x46 && b[4] === 2 && b[5] === 0 && b[6] === 0 && b[7] === 0;
}
