// An MTL file's faults, word for word (docs/scene-model.md#obj-and-mtl): each warning's text and
// line, values at the edges of their ranges, and the texture options' argument counts.
import { describe, expect, it } from 'vitest';
import { LoadError } from '../../src/loaders/load-error';
import { parseMtl, parseMtlBytes } from '../../src/loaders/mtl';
import { readMapStatement } from '../../src/loaders/mtl-map';

const parse = (text: string) => parseMtl(text, { url: 'a.mtl' });
const material = (text: string, name = 'm') => parse(text).materials.get(name);

describe('parseMtl: values at the edges of their ranges', () => {
  it('keeps 0 and 1 for d, 0 for Ns and 1 for Ni without a warning', () => {
    const r = parse('newmtl m\nd 0\nNs 0\nNi 1\nnewmtl n\nd 1\nTr 0\nnewmtl o\nTr 1\n');
    expect(r.warnings).toEqual([]);
    expect(r.materials.get('m')).toEqual({ name: 'm', opacity: 0, shininess: 0, ior: 1 });
    expect(r.materials.get('n')).toEqual({ name: 'n', opacity: 1 });
    expect(r.materials.get('o')).toEqual({ name: 'o', opacity: 0 });
  });

  it('clamps Ns below 0, d and Tr outside 0..1 and Ni below 1, saying from what to what', () => {
    const r = parse('newmtl m\nNs -5\nd -0.5\nNi 0.5\nnewmtl n\nTr 2\nnewmtl o\nTr -1\nNs 1e9\n');
    expect(r.warnings).toEqual([
      { line: 2, message: 'Ns -5 is outside 0..; using 0' },
      { line: 3, message: 'd -0.5 is outside 0..1; using 0' },
      { line: 4, message: 'Ni (ior) 0.5 is outside 1..; using 1' },
      { line: 6, message: 'Tr 2 is outside 0..1; using 1' },
      { line: 8, message: 'Tr -1 is outside 0..1; using 0' },
    ]);
    expect(r.materials.get('m')).toEqual({ name: 'm', shininess: 0, opacity: 0, ior: 1 });
    expect(r.materials.get('n')).toEqual({ name: 'n', opacity: 0 });
    expect(r.materials.get('o')).toEqual({ name: 'o', opacity: 1, shininess: 1e9 });
  });

  it('reads illum, Ka, Ks, and keywords in any case', () => {
    expect(material('NEWMTL m\nILLUM 7\nka 0.1 0.2 0.3\nKS 0.5\nkD 0 0 1\n')).toEqual({
      name: 'm', illum: 7, ambient: [0.1, 0.2, 0.3], specular: [0.5, 0.5, 0.5], diffuse: [0, 0, 1],
    });
  });
});

describe('parseMtl: warnings, word for word', () => {
  it('reads a colour of 2 values as grey of the first, with a warning', () => {
    const r = parse('newmtl m\nKa 0.25 0.75\nKs 0.5 0.1\nKd 0.3 0.9\n');
    expect(r.materials.get('m')).toEqual({ name: 'm', ambient: [0.25, 0.25, 0.25], specular: [0.5, 0.5, 0.5], diffuse: [0.3, 0.3, 0.3] });
    expect(r.warnings).toEqual([
      { line: 2, message: '"Ka" with 2 values; read as grey 0.25' },
      { line: 3, message: '"Ks" with 2 values; read as grey 0.5' },
      { line: 4, message: '"Kd" with 2 values; read as grey 0.3' },
    ]);
  });

  it('ignores a statement with too few, too many or non-numeric values, naming what it needs', () => {
    const r = parse('newmtl m\nKd\nKd 1 2 3 4\nNs 1 2\nd x\nNi\nillum 2 3\nTr 0.5 0.5\nKa 1 x 1\n');
    expect(r.materials.get('m')).toEqual({ name: 'm' });
    expect(r.warnings).toEqual([
      { line: 2, message: '"Kd" needs 1 to 3 numbers, got ""; ignored' },
      { line: 3, message: '"Kd" needs 1 to 3 numbers, got "1 2 3 4"; ignored' },
      { line: 4, message: '"Ns" needs 1 numbers, got "1 2"; ignored' },
      { line: 5, message: '"d" needs 1 numbers, got "x"; ignored' },
      { line: 6, message: '"Ni" needs 1 numbers, got ""; ignored' },
      { line: 7, message: '"illum" needs 1 numbers, got "2 3"; ignored' },
      { line: 8, message: '"Tr" needs 1 numbers, got "0.5 0.5"; ignored' },
      { line: 9, message: '"Ka" needs 1 to 3 numbers, got "1 x 1"; ignored' },
    ]);
  });

  it('warns about a material defined again (the later one used) and statements before any newmtl', () => {
    const r = parse('Kd 1 0 0\nNs 3\nnewmtl m\nKd 0 1 0\nnewmtl m\nd 0.5\n');
    expect(r.warnings).toEqual([
      { line: 1, message: '"Kd" before any newmtl; ignored' },
      { line: 2, message: '"Ns" before any newmtl; ignored' },
      { line: 5, message: 'material "m" defined again; the later one is used' },
    ]);
    expect(r.materials.get('m')).toEqual({ name: 'm', opacity: 0.5 });
  });

  it('says an unknown statement once per keyword, the known unused ones never', () => {
    const r = parse('newmtl m\nfoo 1\nKe 1 1 1\nbar\nfoo 2\nmap_Bump n.png\nbump n.png\nPr 0.5\nnewmtl n\nbar 3\n');
    expect(r.warnings).toEqual([
      { line: 2, message: 'unknown statement "foo"; ignored' },
      { line: 4, message: 'unknown statement "bar"; ignored' },
    ]);
  });

  it('says two long unknown keywords once when their first 64 characters are the same', () => {
    const long = 'k'.repeat(64);
    const r = parse(`newmtl m\n${long}a 1\n${long}b 1\n`);
    expect(r.warnings).toEqual([{ line: 2, message: `unknown statement "${'k'.repeat(40)}…"; ignored` }]);
  });

  it('rejects an HTML page and binary content, naming the file', () => {
    expect(() => parse('\n<html>')).toThrow(new LoadError('a.mtl', 'an HTML page (or other markup), not an MTL file'));
    expect(() => parseMtl('Kd 1 1 1', { url: 'b.mtl', sniffed: 'binary' })).toThrow('glass-plane-scene: b.mtl: binary content, not an MTL file');
    expect(() => parseMtlBytes(new Uint8Array(64).fill(2))).toThrow('glass-plane-scene: (inline): binary content, not an MTL file');
    expect(() => parseMtlBytes(new Uint8Array(64).fill(2), { url: 'c.mtl' })).toThrow('glass-plane-scene: c.mtl: binary content');
  });

  it('names a file read without a URL by an empty URL', () => {
    expect(() => parseMtl('<html>')).toThrow(new LoadError('', 'an HTML page (or other markup), not an MTL file'));
    let url: string | undefined;
    try { parseMtl('<html>'); } catch (e) { url = (e as LoadError).url; }
    expect(url).toBe('');
  });

  it('reads what was sniffed as given: an OBJ-looking MTL is still read', () => {
    expect(parseMtl('newmtl m\nKd 1 1 1\n', { sniffed: 'obj' }).materials.get('m')).toEqual({ name: 'm', diffuse: [1, 1, 1] });
    expect(parseMtlBytes(new TextEncoder().encode('newmtl q\nd 0.5\n'), { url: 'q.mtl' }).materials.get('q')).toEqual({ name: 'q', opacity: 0.5 });
  });
});

describe('parseMtl: texture options', () => {
  const map = (rest: string, url = 'a.mtl') => {
    const r = parseMtl(`newmtl m\nmap_Kd ${rest}\n`, { url });
    return { map: r.materials.get('m')?.diffuseMap, warnings: r.warnings.map((w) => w.message) };
  };

  it('fills -o with 0 and -s with 1 where values are missing', () => {
    expect(map('-o 0.5 a.png').map).toEqual({ path: 'a.png', offset: [0.5, 0, 0] });
    expect(map('-s 2 3 a.png').map).toEqual({ path: 'a.png', scale: [2, 3, 1] });
    expect(map('-o 1 2 3 -s 4 5 6 a.png').map).toEqual({ path: 'a.png', offset: [1, 2, 3], scale: [4, 5, 6] });
  });

  it('takes at most three numbers after -s: a fourth is the path', () => {
    expect(map('-s 1 2 3 4 a.png').map).toEqual({ path: '4 a.png', scale: [1, 2, 3] });
    expect(map('-t 1 2 3 b.png').map).toEqual({ path: 'b.png' });
  });

  it('warns about -s, -o or -t without a number, and reads on', () => {
    expect(map('-s a.png')).toEqual({ map: { path: 'a.png' }, warnings: ['map_Kd: -s without a number'] });
    expect(map('-o -clamp on a.png')).toEqual({ map: { path: 'a.png', clamp: true }, warnings: ['map_Kd: -o without a number'] });
    expect(map('-t')).toEqual({ map: undefined, warnings: ['map_Kd: -t without a number', 'map_Kd: no file name; ignored'] });
  });

  it('reads options in any case, -clamp on or off in any case, and -mm with its two arguments', () => {
    expect(map('-CLAMP ON a.png').map).toEqual({ path: 'a.png', clamp: true });
    expect(map('-clamp Off a.png').map).toEqual({ path: 'a.png', clamp: false });
    expect(map('-mm 0.1 0.9 a.png').map).toEqual({ path: 'a.png' });
    expect(map('-imfchan r -texres 512 -type sphere a.png').map).toEqual({ path: 'a.png' });
  });

  it('takes a token that is a negative number for the path, not an option', () => {
    expect(map('-5').map).toEqual({ path: '-5' });
    expect(map('-bm 1 -0.5 x.png').map).toEqual({ path: '-0.5 x.png' });
  });

  it('says what is missing: an option that runs out of arguments, or no path at all', () => {
    expect(map('-bm')).toEqual({ map: undefined, warnings: ['map_Kd: no file name; ignored'] });
    expect(map('-weird')).toEqual({ map: undefined, warnings: ['map_Kd: unknown option "-weird" skipped', 'map_Kd: no file name; ignored'] });
    const long = `-${'w'.repeat(60)}`;
    expect(map(`${long} a.png`).warnings).toEqual([`map_Kd: unknown option ${JSON.stringify(long.slice(0, 40))} skipped`]);
  });

  it('sets map_Ka apart from map_Kd, with its own keyword in warnings', () => {
    const r = parseMtl('newmtl m\nmap_Ka -s a.png\nmap_Kd b.png\n', { url: 'a.mtl' });
    expect(r.materials.get('m')).toEqual({ name: 'm', ambientMap: { path: 'a.png' }, diffuseMap: { path: 'b.png' } });
    expect(r.warnings).toEqual([{ line: 2, message: 'map_Ka: -s without a number' }]);
  });

  it('warns about a map with no path in a file with a URL, and reads on', () => {
    expect(map('-s 1', 'https://h/a.mtl')).toEqual({ map: undefined, warnings: ['map_Kd: no file name; ignored'] });
  });

  it('readMapStatement: the path is the rest of the statement, trimmed', () => {
    expect(readMapStatement('-clamp on  a b.png  ', () => {})).toEqual({ path: 'a b.png', clamp: true });
  });

  it('resolves a path only against an absolute URL', () => {
    expect(map('t/a.png', 'https://h/m/a.mtl').map).toEqual({ path: 't/a.png', url: 'https://h/m/t/a.png' });
    expect(map('t/a.png', 'm/a.mtl').map).toEqual({ path: 't/a.png' });
    expect(map('t/a.png', '').map).toEqual({ path: 't/a.png' });
  });
});
