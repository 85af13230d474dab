// A model's content is sniffed once per load: the page sniffs it, and the parsers (on the page
// or in the worker) take that format instead of sniffing the same bytes again.
import { beforeEach, describe, expect, it, vi } from 'vitest';

vi.mock('../../src/loaders/sniff', async (original) => {
  const m = await original<typeof import('../../src/loaders/sniff')>();
  return { ...m, sniffModel: vi.fn(m.sniffModel) };
});

const { sniffModel } = await import('../../src/loaders/sniff');
const { parseModelBytes } = await import('../../src/element/children/model-parse');
const { runObjJob } = await import('../../src/loaders/obj-job');
const { LoadError } = await import('../../src/loaders/load-error');
const { parseMtlBytes } = await import('../../src/loaders/mtl');

const bytes = (text: string) => new TextEncoder().encode(text);
const OBJ = 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n';
const BYU_MESH = '3 1\n0 0 0\n1 0 0\n0 1 0\n1 2 3\n';
const BYU_BEZIER = '1 1\n4\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n';
const calls = () => vi.mocked(sniffModel).mock.calls.length;

describe('one sniff per load', () => {
  beforeEach(() => vi.mocked(sniffModel).mockClear());

  for (const [name, text, url] of [['an OBJ', OBJ, 'a.obj'], ['a mesh .byu', BYU_MESH, 'a.byu'], ['a Bézier .byu', BYU_BEZIER, 'b.byu']]) {
    it(`${name}, parsed on the page`, async () => {
      const model = await parseModelBytes(bytes(text), url);
      expect(model.obj.indices.length).toBeGreaterThan(0);
      expect(calls()).toBe(1);
    });
  }

  it('an HTML page is refused after that one sniff', async () => {
    await expect(parseModelBytes(bytes('<!doctype html><p>404</p>'), 'a.obj')).rejects.toBeInstanceOf(LoadError);
    expect(calls()).toBe(1);
  });

  it('a material library, once too', () => {
    expect(parseMtlBytes(bytes('newmtl red\nKd 1 0 0\n'), { url: 'a.mtl' }).materials.get('red')?.diffuse).toEqual([1, 0, 0]);
    expect(calls()).toBe(1);
  });

  it('the worker takes the page\'s format and does not sniff', () => {
    const buffer = (t: string) => bytes(t).buffer as ArrayBuffer;
    expect(runObjJob({ id: 1, url: 'a.obj', bytes: buffer(OBJ), format: 'obj', sniffed: 'obj' }).response.ok).toBe(true);
    expect(runObjJob({ id: 2, url: 'a.byu', bytes: buffer(BYU_BEZIER), format: 'byu', sniffed: 'byu-bezier' }).response.ok).toBe(true);
    expect(calls()).toBe(0);
  });
});
