// Format sniffing from content (docs/scene-model.md#loading): OBJ, .byu mesh or Bézier, HTML, binary.
import { describe, expect, it } from 'vitest';
import { sniffModel } from '../../src/loaders/sniff';

const utf16 = (text: string, littleEndian: boolean): Uint8Array => {
  const bytes = new Uint8Array(2 + 2 * text.length);
  const view = new DataView(bytes.buffer);
  view.setUint16(0, 0xfeff, littleEndian);
  for (let i = 0; i < text.length; i++) view.setUint16(2 + 2 * i, text.charCodeAt(i), littleEndian);
  return bytes;
};

describe('sniffModel', () => {
  it('recognises OBJ text, with comments, blank lines and any first statement', () => {
    expect(sniffModel('v 0 0 0\n')).toBe('obj');
    expect(sniffModel('# Blender 4.1\n\nmtllib cube.mtl\no Cube\n')).toBe('obj');
    expect(sniffModel('\r\n\tg group\r\n')).toBe('obj');
    expect(sniffModel('# only a comment')).toBe('obj');
  });

  it('recognises OBJ bytes behind a UTF-8 or UTF-16 BOM', () => {
    expect(sniffModel(new TextEncoder().encode('\uFEFFv 1 2 3\n'))).toBe('obj');
    expect(sniffModel(utf16('v 1 2 3\nf 1 1 1\n', true))).toBe('obj');
    expect(sniffModel(utf16('v 1 2 3\nf 1 1 1\n', false).buffer as ArrayBuffer)).toBe('obj');
  });

  it('calls anything opening with < an HTML page: doctype, html, comments, leading space', () => {
    expect(sniffModel('<!DOCTYPE html>\n<html>')).toBe('html');
    expect(sniffModel('<html lang="en"><head>')).toBe('html');
    expect(sniffModel('\uFEFF\n  <!-- vite 404 -->\n')).toBe('html');
    expect(sniffModel(new TextEncoder().encode('<?xml version="1.0"?><Error/>'))).toBe('html');
  });

  it('calls control bytes and invalid UTF-8 binary: a PNG, random bytes, UTF-16 without BOM', () => {
    const png = new Uint8Array([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0, 0, 0, 0x0d, 0x49, 0x48, 0x44, 0x52, 0, 0, 1, 0]);
    expect(sniffModel(png)).toBe('binary');
    const noise = new Uint8Array(5000).map((_, i) => (i * 2654435761) >>> 24);
    expect(sniffModel(noise)).toBe('binary');
    expect(sniffModel(utf16('v 1 2 3\n', true).subarray(2))).toBe('binary');
  });

  it('does not call a long UTF-8 file binary because the sample cuts a character', () => {
    const text = `#  ${'é'.repeat(3000)}\nv 0 0 0\n`; // 3 ASCII bytes: byte 4096 is mid-'é'
    const bytes = new TextEncoder().encode(text);
    expect(bytes.length).toBeGreaterThan(4096);
    expect(sniffModel(bytes)).toBe('obj');
  });

  it('recognises a .byu mesh: a first line of two counts, CRLF and blank lines allowed', () => {
    expect(sniffModel('4 2\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n1 2 3\n1 3 4\n')).toBe('byu-mesh');
    expect(sniffModel('\r\n  1204   2400 \r\n\r\n-1.0E-14 9.5e-005 3\r\n')).toBe('byu-mesh');
  });

  it('recognises a Bézier .byu: two degrees, then a line with one number', () => {
    expect(sniffModel('3 3\n10\n0 0 0\n')).toBe('byu-bezier');
    expect(sniffModel('2 2\r\n\r\n 20 \r\n')).toBe('byu-bezier');
  });

  it('says unknown for text that is none of these, and for an empty file', () => {
    expect(sniffModel('hello world\n')).toBe('unknown');
    // JSON is read as glTF, whose reader names what a JSON that is not glTF lacks (gltf-errors.test.ts).
    expect(sniffModel('{"positions": []}')).toBe('gltf');
    expect(sniffModel('1 2 3\n')).toBe('unknown');
    expect(sniffModel('')).toBe('unknown');
    expect(sniffModel('   \n\n')).toBe('unknown');
  });

  it('recognises a GLB by its header and a .gltf by its JSON, BOM or not, whatever the URL says', () => {
    const glb = new Uint8Array([0x67, 0x6c, 0x54, 0x46, 2, 0, 0, 0, 12, 0, 0, 0]);
    expect(sniffModel(glb)).toBe('gltf');
    expect(sniffModel(glb.buffer)).toBe('gltf');
    // Version 1 (and any other) is not a GLB 2.0 header: binary, as before.
    expect(sniffModel(new Uint8Array([0x67, 0x6c, 0x54, 0x46, 1, 0, 0, 0, 12, 0, 0, 0]))).toBe('binary');
    expect(sniffModel(new TextEncoder().encode('\uFEFF\r\n  {"asset": {"version": "2.0"}}'))).toBe('gltf');
    expect(sniffModel(' {"asset":')).toBe('gltf');
  });
});
