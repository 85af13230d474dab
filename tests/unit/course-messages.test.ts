// The course files' warnings and load errors word for word (docs/course-files.md): what each
// parser says, on which line, for extra values and lines, clamped values, bad counts and numbers.
import { describe, expect, it } from 'vitest';
import { LoadError } from '../../src/loaders/load-error';
import { netLength, parseByuBezier } from '../../src/loaders/course/byu-bezier';
import { parseByu } from '../../src/loaders/course/byu';
import { courseVertexNormals, parseByuMesh } from '../../src/loaders/course/byu-mesh';
import { parseCameraCfg } from '../../src/loaders/course/camera-cfg';
import { parseLightingTxt } from '../../src/loaders/course/lighting-txt';

function detail(run: () => unknown): LoadError['detail'] {
  try {
    run();
  } catch (e) {
    expect(e).toBeInstanceOf(LoadError);
    return (e as LoadError).detail;
  }
  throw new Error('expected a LoadError');
}

const PATCH = '0 0 0\n0 1 0\n1 0 0\n1 1 0\n';

describe('every course parser', () => {
  it('names a file read without a URL by an empty URL, and says what it expected instead of markup', () => {
    const html = '\n<html>';
    const want = (what: string) => ({ type: 'load', url: '', line: 2, message: `an HTML page (or other markup), not ${what}` });
    expect(detail(() => parseByuBezier(html))).toEqual(want('a .byu file'));
    expect(detail(() => parseByuMesh(html))).toEqual(want('a .byu file'));
    expect(detail(() => parseCameraCfg(html))).toEqual(want('a camera .cfg file'));
    expect(detail(() => parseLightingTxt(html))).toEqual(want('a lighting file (iluminacao.txt)'));
  });

  it('parseByu: refuses content that is a camera or lighting file, by content or by name, without a URL too', () => {
    expect(detail(() => parseByu('0 0 10\n0 0 -1\n0 1 0\n1 1 1\n'))).toEqual({ type: 'load', url: '', message: 'a camera .cfg file, not a .byu model' });
    expect(detail(() => parseByu('0 0 0\n1\n1 1 1\n1\n1 1 1\n1\n1 1 1\n1\n'))).toEqual({ type: 'load', url: '', message: 'a lighting file, not a .byu model' });
    expect(detail(() => parseByu('oops\n', { url: 'x/cam.cfg' }))).toEqual({ type: 'load', url: 'x/cam.cfg', message: 'a camera .cfg file, not a .byu model' });
    expect(detail(() => parseByu('oops\n'))).toEqual({ type: 'load', url: '', line: 1, message: 'the header needs two counts, "NV NT"; the face count is missing' });
  });
});

describe('parseByuBezier: messages', () => {
  it('warns about values after "m n", after E, after a point (once) and lines after the points', () => {
    const r = parseByuBezier(`1 1 7\n3 9\n0 0 0 5\n0 1 0 5\n1 0 0\n1 1 0\nx\n`);
    expect(r.warnings).toEqual([
      { line: 1, message: 'values after "m n" ignored' },
      { line: 2, message: 'values after E ignored' },
      { line: 3, message: 'control point lines with more than 3 values: the rest ignored (the first such line)' },
      { line: 7, message: '1 line after the 4 control points; ignored' },
    ]);
  });

  // E above 1024 (a 1024 × 1024 grid, half a second): course-byu-bezier.test.ts.
  it('says where resolution was moved to 2..1024, and leaves 2 alone', () => {
    expect(parseByuBezier(`1 1\n\n4\n${PATCH}`, { resolution: 1 }).warnings)
      .toEqual([{ line: 3, message: 'resolution 1 is outside 2..1024; using 2' }]);
    const half = parseByuBezier(`1 1\n4\n${PATCH}`, { resolution: 2.5 });
    expect(half.resolution).toBe(3);
    expect(half.warnings).toEqual([{ line: 2, message: 'resolution 2.5 is outside 2..1024; using 3' }]);
    const nan = parseByuBezier(`1 1\n4\n${PATCH}`, { resolution: NaN });
    expect(nan.resolution).toBe(2);
    expect(nan.mesh.positions.length).toBe(3 * 4);
    const two = parseByuBezier(`1 1\n2\n${PATCH}`);
    expect([two.resolution, two.fileResolution, two.warnings]).toEqual([2, 2, []]);
  });

  it('names degree n when it is the bad one, and takes n = 32', () => {
    expect(detail(() => parseByuBezier('1 0\n2\n'))).toEqual({ type: 'load', url: '', line: 1, message: 'degree n: "0" is not a whole number ≥ 1' });
    const points = Array.from({ length: 66 }, (_, k) => `${k % 33} ${Math.floor(k / 33)} 0`).join('\n');
    expect(parseByuBezier(`1 32\n2\n${points}\n`).patch.degreeV).toBe(32);
  });

  it('reads a net of one repeated point (both lengths 0) row by row', () => {
    const r = parseByuBezier(`1 2\n2\n${'1 1 1\n'.repeat(6)}`);
    expect([r.order, r.netLength, r.otherNetLength]).toEqual(['second-fastest', 0, 0]);
  });

  it('measures edges in z too', () => {
    expect(netLength([0, 0, 1, 0, 0, 3], 1, 0)).toBe(2);
    expect(netLength([0, 0, 1, 0, 0, 3], 0, 1)).toBe(2);
  });

  it('refuses degrees above 32 in either direction, and takes 32', () => {
    expect(detail(() => parseByuBezier('33 1\n2\n', { url: 'd.byu' })))
      .toEqual({ type: 'load', url: 'd.byu', line: 1, message: 'degrees (33, 1): above 32 is not supported' });
    expect(detail(() => parseByuBezier('\n1 33\n2\n', { url: 'd.byu' })))
      .toEqual({ type: 'load', url: 'd.byu', line: 2, message: 'degrees (1, 33): above 32 is not supported' });
    const points = Array.from({ length: 66 }, (_, k) => `${k % 33} ${Math.floor(k / 33)} 0`).join('\n');
    const r = parseByuBezier(`32 1\n2\n${points}\n`);
    expect(r.patch.degreeU).toBe(32);
    expect(r.warnings).toEqual([]);
  });

  it('says what is missing where the file ends', () => {
    expect(detail(() => parseByuBezier('', { url: 'e.byu' }))).toEqual({ type: 'load', url: 'e.byu', line: 1, message: 'the file ends here, no header "m n"' });
    expect(detail(() => parseByuBezier('\n\n1 1\n', { url: 'e.byu' })))
      .toEqual({ type: 'load', url: 'e.byu', line: 3, message: 'the file ends here, no line with the number of evaluations E' });
    expect(detail(() => parseByuBezier('1 1\n3\n0 0 0\n', { url: 'e.byu' })))
      .toEqual({ type: 'load', url: 'e.byu', line: 3, message: 'the file ends here, after 1 of the 4 control points of a (1, 1) patch' });
    expect(detail(() => parseByuBezier('2\n', { url: 'e.byu' })))
      .toEqual({ type: 'load', url: 'e.byu', line: 1, message: 'the header needs two degrees, "m n"; the second is missing' });
    expect(detail(() => parseByuBezier('1 1\n3\n0 0\n', { url: 'e.byu' })))
      .toEqual({ type: 'load', url: 'e.byu', line: 3, message: 'control point 1 needs 3 numbers, the line has 2' });
  });
});

describe('parseByuMesh: messages', () => {
  it('reads as many vertices as a short file holds before saying where it ends', () => {
    expect(detail(() => parseByuMesh('4 1\n0 0 0\n1 0 0'))).toEqual({
      type: 'load', url: '', line: 3, message: 'the file ends here, after 2 of the 4 vertices the header (line 1) counts',
    });
  });

  it('gives a vertex the normal of its one face though a zero-area face also uses it', () => {
    const n = courseVertexNormals([1, 1, 1, 1, 2, 1, 1, 1, 2], [0, 1, 2, 0, 0, 1]);
    expect(Array.from(n.subarray(0, 6))).toEqual([1, 0, 0, 1, 0, 0]);
    expect(Array.from(n.subarray(6, 9))).toEqual([1, 0, 0]);
  });

  it('warns about values after "NV NT", extra values once per kind of line, and lines after the counts', () => {
    const r = parseByuMesh('3 1 9\n0 0 0 1\n1 0 0 1\n0 1 0\n1 2 3 4\n\n7\n8\n', { url: 'm.byu' });
    expect(r.warnings).toEqual([
      { line: 1, message: 'values after "NV NT" ignored' },
      { line: 2, message: 'vertex lines with more than 3 values: the rest ignored (the first such line)' },
      { line: 5, message: 'face lines with more than 3 values: the rest ignored (the first such line)' },
      { line: 7, message: '2 lines after the 3 vertices and 1 faces the header counts; ignored' },
    ]);
    expect(parseByuMesh('3 1\n0 0 0\n1 0 0\n0 1 0\n1 2 3\n7\n').warnings)
      .toEqual([{ line: 6, message: '1 line after the 3 vertices and 1 faces the header counts; ignored' }]);
  });

  it('drops a face with an index outside 1..NV, not whole, or negative but last, naming the index as written', () => {
    const r = parseByuMesh('3 6\n0 0 0\n1 0 0\n0 1 0\n1 2 4\n1.5 2 3\n-1 2 3\n1 2 -4\n1 2 -3\n0 2 3\n', { url: 'm.byu' });
    expect(r.warnings).toEqual([
      { line: 5, message: 'face 1: index 4 is outside 1..3; face dropped' },
      { line: 6, message: 'face 2: index 1.5 is outside 1..3; face dropped' },
      { line: 7, message: 'face 3: index -1 is outside 1..3; face dropped' },
      { line: 8, message: 'face 4: index -4 is outside 1..3; face dropped' },
      { line: 10, message: 'face 6: index 0 is outside 1..3; face dropped' },
    ]);
    expect([...r.mesh.indices]).toEqual([0, 1, 2]);
    expect([r.faceCount, r.declaredFaceCount, r.vertexCount]).toEqual([1, 6, 3]);
  });

  it('says all faces were dropped on the line of the first, and takes NV 0 as a count', () => {
    expect(detail(() => parseByuMesh('0 2\n\n1 2 3\n1 1 1\n', { url: 'z.byu' })))
      .toEqual({ type: 'load', url: 'z.byu', line: 3, message: 'no faces to draw: all 2 dropped, the first here' });
    expect(detail(() => parseByuMesh('3 0\n', { url: 'z.byu' })))
      .toEqual({ type: 'load', url: 'z.byu', line: 1, message: 'face count NT: "0" is not a whole number ≥ 1' });
    expect(detail(() => parseByuMesh('-1 1\n', { url: 'z.byu' })))
      .toEqual({ type: 'load', url: 'z.byu', line: 1, message: 'vertex count NV: "-1" is not a whole number ≥ 0' });
  });

  it('says what is missing where the file ends', () => {
    expect(detail(() => parseByuMesh('3\n', { url: 'm.byu' })))
      .toEqual({ type: 'load', url: 'm.byu', line: 1, message: 'the header needs two counts, "NV NT"; the face count is missing' });
    expect(detail(() => parseByuMesh('3 1\n0 0 0\n\n', { url: 'm.byu' })))
      .toEqual({ type: 'load', url: 'm.byu', line: 2, message: 'the file ends here, after 1 of the 3 vertices the header (line 1) counts' });
    expect(detail(() => parseByuMesh('\n3 2\n0 0 0\n1 0 0\n0 1 0\n1 2 3\n', { url: 'm.byu' })))
      .toEqual({ type: 'load', url: 'm.byu', line: 6, message: 'the file ends here, after 1 of the 2 faces the header (line 2) counts' });
    expect(detail(() => parseByuMesh('3 1\n0 0 0\n1 0 1e999\n', { url: 'm.byu' })))
      .toEqual({ type: 'load', url: 'm.byu', line: 3, message: 'vertex 2: "1e999" is too large' });
  });

  it('gives the bounds of the vertices the kept faces use, negative ones too', () => {
    const r = parseByuMesh('4 1\n-1 -2 -3\n-1 -5 -3\n-4 -2 -3\n9 9 9\n1 2 3\n');
    expect(r.bounds).toEqual({ min: [-4, -5, -3], max: [-1, -2, -3] });
  });
});

describe('parseCameraCfg: messages', () => {
  it('warns about values after the three of a line and lines after the four', () => {
    const r = parseCameraCfg('0 0 10 1\n0 0 -1\n0 1 0 2\n1 1 1 3\n\nx\n', { url: 'c.cfg' });
    expect(r.warnings).toEqual([
      { line: 1, message: 'values after the 3 of C (focus) ignored' },
      { line: 3, message: 'values after the 3 of V (up) ignored' },
      { line: 4, message: 'values after the 3 of d hx hy ignored' },
      { line: 6, message: '1 line after "d hx hy"; ignored' },
    ]);
    expect(parseCameraCfg('0 0 10\n0 0 -1 5\n0 1 0\n1 1 1\nx\ny\n').warnings).toEqual([
      { line: 2, message: 'values after the 3 of N (view direction) ignored' },
      { line: 5, message: '2 lines after "d hx hy"; ignored' },
    ]);
  });

  it('names the first of d, hx, hy that is 0, and what line is missing', () => {
    const at = (window: string) => detail(() => parseCameraCfg(`0 0 10\n0 0 -1\n0 1 0\n${window}\n`, { url: 'c.cfg' }));
    expect(at('0 1 1')).toEqual({ type: 'load', url: 'c.cfg', line: 4, message: 'd is 0: the screen window has no size' });
    expect(at('1 0 0')).toEqual({ type: 'load', url: 'c.cfg', line: 4, message: 'hx is 0: the screen window has no size' });
    expect(at('1 1 -0')).toEqual({ type: 'load', url: 'c.cfg', line: 4, message: 'hy is 0: the screen window has no size' });
    expect(detail(() => parseCameraCfg('0 0 10\n0 0 -1\n', { url: 'c.cfg' })))
      .toEqual({ type: 'load', url: 'c.cfg', line: 2, message: 'the file ends here, no line for V (up)' });
    expect(detail(() => parseCameraCfg('', { url: 'c.cfg' })))
      .toEqual({ type: 'load', url: 'c.cfg', line: 1, message: 'the file ends here, no line for C (focus)' });
  });

  it('reads the focus, the window and the basis', () => {
    const r = parseCameraCfg('1 2 3\n0 0 -2\n0 5 0\n1.5 2 -3\n');
    expect(r).toMatchObject({ c: [1, 2, 3], d: 1.5, hx: 2, hy: -3, n: [0, 0, -1], v: [0, 1, 0], warnings: [] });
  });
});

describe('parseLightingTxt: messages', () => {
  const GOOD = ['1 2 3', '0.2', '100 90 80', '0.5', '0.7 0.5 0.8', '0.25', '255 200 150', '2'];

  it('warns about values after a line\'s one or three numbers, and lines after n', () => {
    const lines = [...GOOD];
    lines[0] = '1 2 3 4';
    lines[1] = '0.2 9';
    const r = parseLightingTxt(`${lines.join('\n')}\n\n9\n`);
    expect(r.warnings).toEqual([
      { line: 1, message: 'values after the 3 of Pl ignored' },
      { line: 2, message: 'values after the one of ka ignored' },
      { line: 10, message: '1 line after n; ignored' },
    ]);
    expect(parseLightingTxt(`${GOOD.join('\n')}\n9\n9\n`).warnings).toEqual([{ line: 9, message: '2 lines after n; ignored' }]);
  });

  it('clamps to each range, saying from what to what; a Pl far off is no fault', () => {
    const r = parseLightingTxt(['-1e9 0 1e9', '-0.5', '-1 256 0', '2', '0 1 1.5', '1', '0 255 300', '-1'].join('\n'));
    expect(r.warnings).toEqual([
      { line: 2, message: 'ka -0.5 is outside 0..1; using 0' },
      { line: 3, message: 'Ia -1 is outside 0..255; using 0' },
      { line: 3, message: 'Ia 256 is outside 0..255; using 255' },
      { line: 4, message: 'kd 2 is outside 0..1; using 1' },
      { line: 5, message: 'Od 1.5 is outside 0..1; using 1' },
      { line: 7, message: 'Il 300 is outside 0..255; using 255' },
      { line: 8, message: 'n -1 is outside 0..; using 0' },
    ]);
    expect(r.light).toEqual({ position: [-1e9, 0, 1e9], ambient: [0, 255, 0], intensity: [0, 255, 255] });
    expect(r.material).toEqual({ ka: 0, kd: 1, ks: 1, od: [0, 1, 1], n: 0 });
  });

  it('keeps values at the ends of their ranges without a warning', () => {
    const r = parseLightingTxt(['0 0 0', '0', '0 0 255', '1', '0 0 1', '0', '255 0 0', '0'].join('\n'));
    expect(r.warnings).toEqual([]);
    expect(r.material).toEqual({ ka: 0, kd: 1, ks: 0, od: [0, 0, 1], n: 0 });
  });

  it('names the line and what it was for, for a missing line or too few numbers', () => {
    expect(detail(() => parseLightingTxt('1 2 3\n0.2\n', { url: 'l.txt' })))
      .toEqual({ type: 'load', url: 'l.txt', line: 2, message: 'the file ends here, no line for Ia' });
    expect(detail(() => parseLightingTxt('1 2 3\n0.2\n1 2 3\n0.5\n1 1\n', { url: 'l.txt' })))
      .toEqual({ type: 'load', url: 'l.txt', line: 5, message: 'Od needs 3 numbers, the line has 2' });
  });
});
