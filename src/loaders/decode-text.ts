// Bytes to text for the text loaders: UTF-8 (BOM or not), UTF-16 LE/BE only with a BOM.

export type Bytes = ArrayBuffer | Uint8Array;

export function asUint8(bytes: Bytes): Uint8Array {
  return bytes instanceof Uint8Array ? bytes : new Uint8Array(bytes);
}

/** The encoding named by a byte-order mark, and the mark's length. */
export function bomOf(b: Uint8Array): { encoding: 'utf-8' | 'utf-16le' | 'utf-16be'; skip: number } {
  if (b.length >= 3 && b[0] === 0xef && b[1] === 0xbb && b[2] === 0xbf) return { encoding: 'utf-8', skip: 3 };
  if (b.length >= 2 && b[0] === 0xff && b[1] === 0xfe) return { encoding: 'utf-16le', skip: 2 };
  if (b.length >= 2 && b[0] === 0xfe && b[1] === 0xff) return { encoding: 'utf-16be', skip: 2 };
  return { encoding: 'utf-8', skip: 0 };
}

/**
 * Decodes `bytes` (or its first `limit` bytes). Invalid UTF-8 becomes U+FFFD rather than
 * throwing, so the sniffer can count it as a sign of binary content.
 */
export function decodeText(bytes: Bytes, limit = Infinity): string {
  const b = asUint8(bytes);
  const { encoding, skip } = bomOf(b);
  const end = Math.min(b.length, skip + limit);
  // ignoreBOM: the mark is already skipped by hand, so a second U+FEFF stays visible as text.
  return new TextDecoder(encoding, { ignoreBOM: true }).decode(b.subarray(skip, end));
}
