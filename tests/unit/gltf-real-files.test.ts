// Real files from exporters and test suites (tests/data/gltf/SOURCES.md), read as the element reads
// them: what each must give, or the error that names what stops it.
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { LoadError } from '../../src/loaders/load-error';
import { parse } from './helpers/gltf';

const file = (name: string) => new Uint8Array(readFileSync(new URL(`../data/gltf/${name}`, import.meta.url)));

function refusal(bytes: Uint8Array, url: string): LoadError {
  try {
    parse(bytes, url);
  } catch (e) {
    if (e instanceof LoadError) return e;
    throw e;
  }
  throw new Error(`${url} was read without an error`);
}

describe('real glTF files', () => {
  it("the Khronos validator's truncated GLB: its header promises a byte the file lacks", () => {
    const e = refusal(file('truncated_chunk_data.glb'), 'truncated_chunk_data.glb');
    expect(e.detail).toEqual({
      type: 'load', url: 'truncated_chunk_data.glb', path: 'GLB header',
      message: 'the GLB header declares 48 bytes, the file has 47: it is truncated',
    });
  });

  it('TextureTransformTest (.gltf, .bin beside it, five PNGs): twelve quads, six texture transforms as the sample states them', () => {
    const bin = file('TextureTransformTest/TextureTransformTest.bin');
    const r = parse(file('TextureTransformTest/TextureTransformTest.gltf'), 'TextureTransformTest.gltf', { 'TextureTransformTest.bin': bin });
    expect(r.warnings).toEqual([]);
    expect(r.images.map((i) => i.kind === 'uri' && i.uri)).toEqual(['UV.png', 'Arrow.png', 'Correct.png', 'NotSupported.png', 'Error.png']);
    const byName = new Map(r.materials.map((m) => [m.name, m.baseColorTexture]));
    expect(byName.get('Offset U')!.transform).toEqual([1, 0, 0.5, -0, 1, 0]);
    expect(byName.get('Scale')!.transform).toEqual([1.5, 0, 0, -0, 1.5, 0]);
    const [a, b, c, d, e, f] = byName.get('Rotation')!.transform!;
    const t = 0.39269908169872414;
    expect([a, b, c, d, e, f]).toEqual([Math.cos(t), Math.sin(t), 0, -Math.sin(t), Math.cos(t), 0]);
    expect(byName.get('Correct')!.transform).toBeNull();
    // Every quad's two triangles, none lost: twelve nodes draw the nine quad meshes, some twice or three times.
    expect(r.indices.length).toBe(12 * 2 * 3);
    expect(r.groups.length).toBe(r.materials.length);
  });

  // The meshopt duck and the Draco box: gltf-compression.test.ts.
});
