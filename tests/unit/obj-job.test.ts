// The OBJ worker's job: the parsed arrays come back with their buffers listed for transfer.
import { describe, expect, it } from 'vitest';
import { runObjJob } from '../../src/loaders/obj-job';

const bytes = (text: string): ArrayBuffer => new TextEncoder().encode(text).buffer as ArrayBuffer;

describe('runObjJob', () => {
  it('returns the result and every typed array buffer to transfer', () => {
    const { response, transfer } = runObjJob({ id: 7, url: 'm.obj', bytes: bytes('v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1\n') });
    expect(response.id).toBe(7);
    if (!response.ok) throw new Error('expected a result');
    const r = response.result;
    expect([...r.indices]).toEqual([0, 1, 2]);
    expect(transfer).toEqual([r.positions.buffer, r.normals.buffer, r.uvs!.buffer, r.indices.buffer]);
    // Transferring really moves them: a structured clone with transfer detaches the buffers.
    structuredClone(response, { transfer });
    expect(r.positions.byteLength).toBe(0);
  });

  it('returns a load error detail for an HTML page, nothing to transfer', () => {
    const { response, transfer } = runObjJob({ id: 1, url: 'm.obj', bytes: bytes('<!doctype html><p>404</p>') });
    expect(response).toEqual({ id: 1, ok: false, error: { type: 'load', url: 'm.obj', line: 1, message: expect.stringMatching(/HTML/) } });
    expect(transfer).toEqual([]);
  });

  it('parses a course .byu mesh and a Bézier .byu (with its order and E) when asked for format byu', () => {
    const mesh = runObjJob({ id: 2, url: 't.byu', format: 'byu', bytes: bytes('4 2\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 2 3\n1 2 4\n') });
    if (!mesh.response.ok) throw new Error('expected a result');
    expect([...mesh.response.result.indices]).toEqual([0, 1, 2, 0, 1, 3]);
    expect(mesh.response.result.uvs).toBeNull();
    expect(mesh.response.bezier).toBeNull();
    const bezier = runObjJob({ id: 3, url: 'p.byu', format: 'byu', bytes: bytes('1 1\n5\n0 0 0\n0 1 0\n1 0 0\n1 1 1\n') });
    if (!bezier.response.ok) throw new Error('expected a result');
    expect(bezier.response.result.positions.length).toBe(3 * 25);
    expect(bezier.response.bezier).toMatchObject({ order: 'second-fastest', fileResolution: 5, patch: { degreeU: 1, degreeV: 1 } });
  });

  it('gives a .byu load error its line', () => {
    const { response } = runObjJob({ id: 4, url: 'bad.byu', format: 'byu', bytes: bytes('3 1\n0 0 0\n1 x 0\n0 1 0\n1 2 3\n') });
    expect(response).toMatchObject({ ok: false, error: { url: 'bad.byu', line: 3 } });
  });
});
