// The neutral studio (src/math/studio.ts, docs/pbr.md#the-studio): its radiance in directions worked
// by hand (each panel's centre and an edge, the wrap past 180°, the room's walls, floor and blend),
// each panel's solid angle by its formula and by counting, the whole sphere's light against its
// sum by hand, and panel samples landing on their panel, uniformly in φ and sin e.
import { describe, expect, it } from 'vitest';
import { panelSolidAngle, samplePanel, studioRadiance, STUDIO_BLEND, STUDIO_FLOOR, STUDIO_PANELS, STUDIO_WALL } from '../../src/math/studio';

const DEG = Math.PI / 180;
/** The unit direction at azimuth φ (from +Z toward +X) and elevation e, in degrees. */
const dir = (phi: number, e: number): [number, number, number] => [Math.cos(e * DEG) * Math.sin(phi * DEG), Math.sin(e * DEG), Math.cos(e * DEG) * Math.cos(phi * DEG)];
const at = (phi: number, e: number) => studioRadiance(...dir(phi, e));
const panel = (name: string) => STUDIO_PANELS.find((p) => p.name === name)!;

describe('radiance', () => {
  it('is each panel\'s at its centre, the wall\'s just past its edge', () => {
    expect([at(-45, 45), at(55, 20), at(180, 30), at(0, 80)]).toEqual([6, 2, 4, 3]);
    expect([at(-19, 45), at(-71, 45), at(-45, 61), at(-45, 29)]).toEqual([STUDIO_WALL, STUDIO_WALL, STUDIO_WALL, STUDIO_WALL]);
    // The rim spans 150°–210°: −170° is 190°.
    expect([at(-170, 30), at(-149, 30), at(149, 30)]).toEqual([4, STUDIO_WALL, STUDIO_WALL]);
    // Straight up is the top panel's, whatever the azimuth (atan2(0, 0) = 0).
    expect(studioRadiance(0, 1, 0)).toBe(3);
  });

  it('is the wall\'s above 5°, the floor\'s below −5°, and blends linearly in y between', () => {
    expect([at(100, 20), at(100, 5.01), at(100, -5.01), studioRadiance(0, -1, 0)]).toEqual([STUDIO_WALL, STUDIO_WALL, STUDIO_FLOOR, STUDIO_FLOOR]);
    expect(studioRadiance(0, 0, 1)).toBeCloseTo((STUDIO_WALL + STUDIO_FLOOR) / 2, 15);
    expect(studioRadiance(0.6, STUDIO_BLEND / 2, 0.8)).toBeCloseTo(STUDIO_FLOOR + 0.75 * (STUDIO_WALL - STUDIO_FLOOR), 12);
    expect([STUDIO_WALL, STUDIO_FLOOR, STUDIO_BLEND]).toEqual([0.3, 0.1, Math.sin(5 * DEG)]);
  });
});

describe('solid angles and the light of the whole sphere', () => {
  it('gives each panel Δφ·(sin e₁ − sin e₀): the key 50° × (sin 60° − sin 30°) = 0.319417', () => {
    expect(STUDIO_PANELS.map((p) => p.name)).toEqual(['key', 'fill', 'rim', 'top']);
    expect(panelSolidAngle(panel('key'))).toBeCloseTo(50 * DEG * (Math.sin(60 * DEG) - 0.5), 14);
    expect(panelSolidAngle(panel('key'))).toBeCloseTo(0.319417, 6);
    expect(panelSolidAngle(panel('top'))).toBeCloseTo(2 * Math.PI * (1 - Math.sin(75 * DEG)), 14);
  });

  it('counts the same solid angles and total light on a fine grid of φ and sin e (each cell the same solid angle)', () => {
    const N = 1440, cell = (2 * Math.PI / N) * (2 / N);
    const count = new Map<number, number>();
    let total = 0;
    for (let i = 0; i < N; i++) {
      const phi = -Math.PI + (i + 0.5) * (2 * Math.PI / N);
      for (let j = 0; j < N; j++) {
        const s = -1 + (j + 0.5) * (2 / N), c = Math.sqrt(1 - s * s);
        const L = studioRadiance(c * Math.sin(phi), s, c * Math.cos(phi));
        total += L * cell;
        if (L > 1) count.set(L, (count.get(L) ?? 0) + cell);
      }
    }
    // Counting is exact up to one row or column of cells along each edge.
    for (const p of STUDIO_PANELS) {
      const edges = (2 / N) / (Math.sin(p.e1) - Math.sin(p.e0)) + (2 * Math.PI / N) / (p.phi1 - p.phi0);
      expect(Math.abs(count.get(p.radiance)! / panelSolidAngle(p) - 1), p.name).toBeLessThan(edges);
    }
    // By hand: the room (wall above 5°, floor below −5°, their mean across the band of 2π·2·sin 5°)
    // plus each panel's excess over the wall it covers.
    const band = 2 * Math.PI * 2 * STUDIO_BLEND, cap = 2 * Math.PI * (1 - STUDIO_BLEND);
    const byHand = cap * STUDIO_WALL + cap * STUDIO_FLOOR + band * (STUDIO_WALL + STUDIO_FLOOR) / 2
      + STUDIO_PANELS.reduce((sum, p) => sum + panelSolidAngle(p) * (p.radiance - STUDIO_WALL), 0);
    // Within the counting's edge error: the top panel's ~2 % of its 0.58 is 0.15 % of the whole (about 7.4).
    expect(total / byHand).toBeCloseTo(1, 2);
  });
});

describe('samplePanel', () => {
  it('draws unit directions on the panel, φ linear in u and sin e in v, the corners at the corners', () => {
    const out = [0, 0, 0];
    for (const p of STUDIO_PANELS) {
      for (const [u, v] of [[0.5, 0.5], [0.01, 0.99], [0.99, 0.01], [0.25, 0.75]]) {
        const [x, y, z] = samplePanel(out, p, u, v);
        expect(Math.hypot(x, y, z)).toBeCloseTo(1, 14);
        expect(studioRadiance(x, y, z), `${p.name} at ${u}, ${v}`).toBe(p.radiance);
        expect(y).toBeCloseTo(Math.sin(p.e0) + v * (Math.sin(p.e1) - Math.sin(p.e0)), 14);
      }
    }
    const key = panel('key');
    expect(samplePanel(out, key, 0, 0).map((x) => Number(x.toFixed(12)))).toEqual(dir(-70, 30).map((x) => Number(x.toFixed(12))));
    expect(samplePanel(out, key, 1, 1).map((x) => Number(x.toFixed(12)))).toEqual(dir(-20, 60).map((x) => Number(x.toFixed(12))));
  });
});
