// The course's Bézier .byu (docs/course-files.md#bezier-byu): header, E and its override, the index order chosen by
// the shorter control net, the degenerate edge, and the load errors.
import { describe, expect, it } from 'vitest';
import { netLength, parseByuBezier } from '../../src/loaders/course/byu-bezier';
import { parseByu } from '../../src/loaders/course/byu';
import { evaluateBezierPatch } from '../../src/scene/geometry/bezier';
import { length } from './helpers/obj';
import { expectLoadError, sample, xyz } from './helpers/course';

/** The nets the samples were written from: P(i, j) = (i·dx, j·dy, 0.25·sin(i + 2j)), rounded. */
function heightNet(m: number, n: number, dx: number, dy: number): number[] {
  const out: number[] = [];
  for (let i = 0; i <= m; i++) for (let j = 0; j <= n; j++) out.push(i * dx, j * dy, Math.round(0.25 * Math.sin(i + 2 * j) * 1e6) / 1e6);
  return out;
}

describe('parseByuBezier: index order', () => {
  it('reads a (2, 5) net written either way as the same net, and says which way it was', () => {
    const want = heightNet(2, 5, 1, 0.5);
    const rowWise = parseByuBezier(sample('patch-2x5-second-fastest.byu'), { url: 's.byu' });
    const columnWise = parseByuBezier(sample('patch-2x5-first-fastest.byu'), { url: 'f.byu' });
    expect(rowWise.order).toBe('second-fastest');
    expect(columnWise.order).toBe('first-fastest');
    expect(Array.from(rowWise.patch.points)).toEqual(want);
    expect(Array.from(columnWise.patch.points)).toEqual(want);
    expect(rowWise.netLength).toBeLessThan(rowWise.otherNetLength);
    expect(columnWise.netLength).toBeCloseTo(rowWise.netLength, 12);
    expect(columnWise.otherNetLength).toBeGreaterThan(columnWise.netLength * 1.2);
    expect([...columnWise.mesh.positions]).toEqual([...rowWise.mesh.positions]);
  });

  it('reads a bicubic net written either way as the same surface (m = n: the readings are transposes)', () => {
    const a = parseByuBezier(sample('patch-3x3-second-fastest.byu'));
    const b = parseByuBezier(sample('patch-3x3-first-fastest.byu')); // CRLF too
    // Equal lengths: the tie goes to 'second-fastest', so b is a's net transposed.
    expect(b.netLength).toBeCloseTo(b.otherNetLength, 12);
    expect([a.order, b.order]).toEqual(['second-fastest', 'second-fastest']);
    const e = a.resolution;
    expect(e).toBe(10);
    for (let s = 0; s < e; s++) {
      for (let t = 0; t < e; t++) {
        expect(xyz(b.mesh.positions, t * e + s)).toEqual(xyz(a.mesh.positions, s * e + t));
      }
    }
  });

  it('picks whichever reading has the shorter net, for random nets of several shapes', () => {
    let seed = 12345;
    const r = (): number => ((seed = (Math.imul(seed, 1103515245) + 12345) >>> 0) / 2 ** 32);
    for (const [m, n] of [[1, 3], [3, 1], [2, 5], [4, 2]]) {
      const net = heightNet(m, n, 1, 1).map((x) => x + 0.05 * r());
      const rows: string[] = [], columns: string[] = [];
      for (let i = 0; i <= m; i++) for (let j = 0; j <= n; j++) rows.push(xyz(net, i * (n + 1) + j).join(' '));
      for (let j = 0; j <= n; j++) for (let i = 0; i <= m; i++) columns.push(xyz(net, i * (n + 1) + j).join(' '));
      const head = `${m} ${n}\n4\n`;
      expect(parseByuBezier(head + rows.join('\n')).order, `${m} ${n}`).toBe('second-fastest');
      expect(parseByuBezier(head + columns.join('\n')).order, `${m} ${n}`).toBe('first-fastest');
      expect(Array.from(parseByuBezier(head + columns.join('\n')).patch.points)).toEqual(net);
    }
  });

  it('measures a net by the sum of its edges', () => {
    // 2×2 points (1, 1): a unit square has 4 edges of length 1.
    expect(netLength([0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0], 1, 1)).toBe(4);
  });
});

describe('parseByuBezier: the grid', () => {
  it('evaluates E×E points, E from the file or from `resolution`', () => {
    const text = sample('patch-2x5-second-fastest.byu');
    const r = parseByuBezier(text);
    expect(r.fileResolution).toBe(8);
    expect(r.mesh.positions.length).toBe(3 * 64);
    expect(r.mesh.indices.length).toBe(6 * 49);
    const finer = parseByuBezier(text, { resolution: 21 });
    expect(finer.resolution).toBe(21);
    expect(finer.mesh.positions.length).toBe(3 * 21 * 21);
    const mid = evaluateBezierPatch(finer.patch, 0.5, 0.5).point;
    xyz(finer.mesh.positions, 10 * 21 + 10).forEach((c, k) => expect(c).toBeCloseTo(mid[k], 6));
    expect(finer.warnings).toEqual([]);
  });

  it('clamps E to 2..1024 with a warning, and rejects an E below 2', () => {
    const r = parseByuBezier('1 1\n5000\n0 0 0\n0 1 0\n1 0 0\n1 1 0\n');
    expect(r.resolution).toBe(1024);
    expect(r.warnings).toEqual([{ line: 2, message: 'E = 5000 (line 2) is outside 2..1024; using 1024' }]);
    expect(parseByuBezier('1 1\n4\n0 0 0\n0 1 0\n1 0 0\n1 1 0\n', { resolution: 1 }).resolution).toBe(2);
    expectLoadError(() => parseByuBezier('1 1\n1\n0 0 0\n', { url: 'e.byu' }), 'e.byu', 2, /evaluations E: "1" is not a whole number ≥ 2/);
  });

  it('has finite unit normals all over a patch with a degenerate edge', () => {
    const r = parseByuBezier(sample('patch-degenerate-edge.byu'), { url: 'dome.byu' });
    expect(r.resolution).toBe(6);
    for (let k = 0; k < 36; k++) expect(length(xyz(r.mesh.normals, k))).toBeCloseTo(1, 5);
    // The apex, u = 0 (vertices b·E): its normal is the dome's axis.
    for (let b = 0; b < 6; b++) {
      expect(xyz(r.mesh.positions, 6 * b)).toEqual([0, 0, 1]);
      expect(Math.abs(r.mesh.normals[3 * 6 * b + 2])).toBeGreaterThan(0.999);
    }
  });
});

describe('parseByuBezier: faults', () => {
  it('ignores lines after the control points with one warning', () => {
    const r = parseByuBezier('1 1\n3\n0 0 0\n0 1 0\n1 0 0\n1 1 0\n\n5 5 5\n6 6 6\n', { url: 'b.byu' });
    expect(r.warnings).toEqual([{ line: 8, message: expect.stringMatching(/^2 lines after the 4 control points/) }]);
  });

  it('is a load error, with its line, for too few points, a bad token, a missing or bad degree', () => {
    expectLoadError(() => parseByuBezier('1 1\n3\n0 0 0\n0 1 0\n1 0 0\n', { url: 'b.byu' }), 'b.byu', 5, /after 3 of the 4 control points/);
    expectLoadError(() => parseByuBezier('1 1\n3\n0 0 0\n0 1 0\n1 O 0\n1 1 0\n', { url: 'b.byu' }), 'b.byu', 5, /control point 3: "O" is not a number/);
    expectLoadError(() => parseByuBezier('3\n3\n', { url: 'b.byu' }), 'b.byu', 1, /second is missing/);
    expectLoadError(() => parseByuBezier('0 3\n3\n', { url: 'b.byu' }), 'b.byu', 1, /degree m: "0" is not a whole number ≥ 1/);
    expectLoadError(() => parseByuBezier('40 3\n3\n', { url: 'b.byu' }), 'b.byu', 1, /above 32/);
  });
});

describe('parseByu', () => {
  it('tells a Bézier .byu (second line one number) from a mesh .byu', () => {
    expect(parseByu(sample('patch-3x3-first-fastest.byu')).kind).toBe('bezier');
    expect(parseByu(sample('tetra-crlf-bom.byu')).kind).toBe('mesh');
    expect(parseByu(sample('tetra.byu')).kind).toBe('mesh');
    const r = parseByu(sample('patch-2x5-first-fastest.byu'), { resolution: 3 });
    expect(r.kind === 'bezier' && r.order).toBe('first-fastest');
    expect(r.mesh.positions.length).toBe(27);
  });

  it('refuses a camera or lighting file, and reports a broken mesh by its line', () => {
    expectLoadError(() => parseByu(sample('camera.cfg'), { url: 'camera.cfg' }), 'camera.cfg', undefined, /camera .cfg file, not a .byu/);
    expectLoadError(() => parseByu(sample('iluminacao.txt'), { url: 'i.txt' }), 'i.txt', undefined, /lighting file, not a .byu/);
    expectLoadError(() => parseByu(sample('mesh-bad-token.byu'), { url: 'b.byu' }), 'b.byu', 4, /"1,5"/);
  });
});
