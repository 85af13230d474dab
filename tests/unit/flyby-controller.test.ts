// Flyby controller: keys and mouse → camera pose, frame-rate independent (docs/interaction.md#flyby).
import { describe, expect, it } from 'vitest';
import { FlybyController, MAX_LOOK_STEP } from '../../src/element/controls/flyby-controller';
import { wrapYaw } from '../../src/math/camera';
import { forwardFromYawPitch, PITCH_LIMIT } from '../../src/math/camera';

const SENS = 0.002 * (180 / Math.PI);

function at(position: [number, number, number], yaw = -90, pitch = 0, options = {}): FlybyController {
  const c = new FlybyController(options);
  c.setPose(position, yaw, pitch);
  return c;
}

function hold(c: FlybyController, ...codes: string[]): void {
  for (const code of codes) expect(c.keyDown(code), code).toBe(true);
}

function run(c: FlybyController, seconds: number, step = 0.05): void {
  for (let t = 0; t < seconds - 1e-9; t += step) c.update(step);
}

function expectPosition(c: FlybyController, expected: [number, number, number], eps = 1e-9): void {
  for (let i = 0; i < 3; i++) {
    expect(Math.abs(c.pose.position[i] - expected[i]), `axis ${i}: ${c.pose.position} vs ${expected}`).toBeLessThanOrEqual(eps);
  }
}

const dist = (c: FlybyController, from: readonly number[]) =>
  Math.hypot(c.pose.position[0] - from[0], c.pose.position[1] - from[1], c.pose.position[2] - from[2]);

describe('movement', () => {
  it('W for 0.5 s at yaw −90 moves 1.5 units down −Z (speed 3)', () => {
    const c = at([0, 0, 0]);
    hold(c, 'KeyW');
    run(c, 0.5, 0.1);
    expectPosition(c, [0, 0, -1.5]);
  });

  it('S moves back, A strafes left (−X), D strafes right (+X) when looking down −Z', () => {
    const cases: [string, [number, number, number]][] = [['KeyS', [0, 0, 0.3]], ['KeyA', [-0.3, 0, 0]], ['KeyD', [0.3, 0, 0]]];
    for (const [key, expected] of cases) {
      const c = at([0, 0, 0]);
      hold(c, key);
      expect(c.update(0.1)).toBe(true);
      expectPosition(c, expected);
    }
  });

  it('W follows the yaw: yaw 0 moves along +X, yaw 90 along +Z', () => {
    const a = at([1, 2, 3], 0);
    hold(a, 'KeyW');
    a.update(0.1);
    expectPosition(a, [1.3, 2, 3]);
    const b = at([1, 2, 3], 90);
    hold(b, 'KeyW');
    b.update(0.1);
    expectPosition(b, [1, 2, 3.3]);
  });

  it('scales with dt: two updates of 0.05 equal one of 0.1', () => {
    const a = at([0, 0, 0], -30, 10);
    const b = at([0, 0, 0], -30, 10);
    hold(a, 'KeyW', 'KeyD', 'Space');
    hold(b, 'KeyW', 'KeyD', 'Space');
    a.update(0.05);
    a.update(0.05);
    b.update(0.1);
    expectPosition(a, b.pose.position as [number, number, number], 1e-12);
    expect(dist(b, [0, 0, 0])).toBeCloseTo(0.3, 12);
  });

  it('caps dt at 0.1 s (update(5) moves like update(0.1)) and honours a custom maxDt', () => {
    const c = at([0, 0, 0]);
    hold(c, 'KeyW');
    c.update(5);
    expectPosition(c, [0, 0, -0.3]);
    c.update(Infinity);
    expectPosition(c, [0, 0, -0.6]);
    const d = at([0, 0, 0], -90, 0, { maxDt: 1, speed: 2 });
    hold(d, 'KeyW');
    d.update(5);
    expectPosition(d, [0, 0, -2]);
  });

  it('ignores negative, zero and NaN dt', () => {
    const c = at([1, 1, 1]);
    hold(c, 'KeyW', 'ArrowLeft');
    for (const dt of [-1, 0, NaN, -Infinity]) expect(c.update(dt), `dt ${dt}`).toBe(false);
    expectPosition(c, [1, 1, 1], 0);
    expect(c.pose.yaw).toBe(-90);
  });

  it('normalizes diagonals: W + D still moves at speed 3', () => {
    const c = at([0, 0, 0]);
    hold(c, 'KeyW', 'KeyD');
    c.update(0.1);
    const s = 0.3 / Math.SQRT2;
    expectPosition(c, [s, 0, -s]);
    const e = at([0, 0, 0], 17, -40);
    hold(e, 'KeyS', 'KeyA', 'ShiftLeft');
    e.update(0.1);
    expect(dist(e, [0, 0, 0])).toBeCloseTo(0.3, 12);
  });

  it('Space goes up and either Shift goes down along world Y, whatever the pitch', () => {
    const c = at([0, 0, 0], 33, 60);
    hold(c, 'Space');
    c.update(0.1);
    expectPosition(c, [0, 0.3, 0]);
    c.releaseAll();
    hold(c, 'ShiftLeft');
    c.update(0.1);
    c.keyUp('ShiftLeft');
    hold(c, 'ShiftRight');
    c.update(0.1);
    expectPosition(c, [0, -0.3, 0]);
  });

  it('keeps sinking while one Shift is still held after the other is released', () => {
    const c = at([0, 0, 0]);
    hold(c, 'ShiftLeft', 'ShiftRight');
    c.keyUp('ShiftLeft');
    expect(c.active).toBe(true);
    c.update(0.1);
    expectPosition(c, [0, -0.3, 0]);
  });

  it('cancels opposite keys: W + S, A + D, Space + Shift', () => {
    for (const pair of [['KeyW', 'KeyS'], ['KeyA', 'KeyD'], ['Space', 'ShiftRight']]) {
      const c = at([2, 2, 2]);
      hold(c, ...pair);
      expect(c.update(0.1), pair.join('+')).toBe(false);
      expectPosition(c, [2, 2, 2], 0);
    }
    const c = at([0, 0, 0]);
    hold(c, 'KeyW', 'KeyS', 'KeyD');
    c.update(0.1);
    expectPosition(c, [0.3, 0, 0]);
  });

  it('W while pitched moves horizontally only, at full speed', () => {
    for (const pitch of [45, -45, 89.9, -89.9]) {
      const c = at([0, 5, 0], -90, pitch);
      hold(c, 'KeyW');
      c.update(0.1);
      expect(c.pose.position[1], `pitch ${pitch}`).toBe(5);
      expectPosition(c, [0, 5, -0.3], 1e-9);
    }
  });

  it('never produces NaN even looking straight up or down', () => {
    const c = at([0, 0, 0], 0, 0);
    c.pose.pitch = 90; // written directly, bypassing the clamp
    hold(c, 'KeyW', 'KeyA');
    c.update(0.1);
    for (const x of c.pose.position) expect(Number.isFinite(x)).toBe(true);
  });
});

describe('looking', () => {
  it('look() turns by sensitivity per pixel: +dx right (+yaw), +dy down (−pitch)', () => {
    const c = at([0, 0, 0], -90, 0);
    expect(c.look(30, 15)).toBe(true);
    expect(c.pose.yaw).toBeCloseTo(-90 + 30 * SENS, 12);
    expect(c.pose.pitch).toBeCloseTo(-15 * SENS, 12);
    expect(SENS).toBeCloseTo(0.11459, 5);
  });

  it('look() turns at most 5° per event, in the direction of the movement (docs/interaction.md#no-jumps)', () => {
    const c = at([0, 0, 0], -90, 0);
    c.look(-528, -377); // what Chromium reported once on entering pointer lock
    const yaw = c.pose.yaw + 90, pitch = c.pose.pitch;
    expect(Math.hypot(yaw, pitch)).toBeCloseTo(MAX_LOOK_STEP, 12);
    expect(Math.atan2(pitch, yaw)).toBeCloseTo(Math.atan2(377, -528), 12);
  });

  it('look() clamps pitch at ±89.9', () => {
    const c = at([0, 0, 0]);
    for (let i = 0; i < 40; i++) c.look(0, -1000);
    expect(c.pose.pitch).toBe(PITCH_LIMIT);
    expect(c.look(0, -10)).toBe(false); // already at the limit: nothing changed
    for (let i = 0; i < 40; i++) c.look(0, 1000);
    expect(c.pose.pitch).toBe(-PITCH_LIMIT);
  });

  it('look(0, 0) and non-finite deltas change nothing', () => {
    const c = at([0, 0, 0], 12, 3);
    expect(c.look(0, 0)).toBe(false);
    expect(c.look(NaN, 5)).toBe(false);
    expect(c.look(3, Infinity)).toBe(false);
    expect([c.pose.yaw, c.pose.pitch]).toEqual([12, 3]);
  });

  it('+yaw turns right: from looking down −Z, a small look right faces slightly toward +X', () => {
    const c = at([0, 0, 0], -90, 0);
    c.look(10, 0);
    const f = forwardFromYawPitch(new Float64Array(3), c.pose.yaw, c.pose.pitch);
    expect(f[0]).toBeGreaterThan(0);
    expect(f[2]).toBeLessThan(0);
  });

  it('arrows turn at turnRate (90°/s) and look up/down', () => {
    const c = at([0, 0, 0], -90, 0);
    hold(c, 'ArrowRight');
    expect(c.update(0.1)).toBe(true);
    expect(c.pose.yaw).toBeCloseTo(-81, 12);
    c.keyUp('ArrowRight');
    hold(c, 'ArrowLeft');
    run(c, 0.5, 0.1);
    expect(c.pose.yaw).toBeCloseTo(-126, 9);
    c.releaseAll();
    hold(c, 'ArrowUp');
    c.update(0.1);
    expect(c.pose.pitch).toBeCloseTo(9, 12);
    c.releaseAll();
    hold(c, 'ArrowDown');
    run(c, 3, 0.1);
    expect(c.pose.pitch).toBe(-PITCH_LIMIT);
    expectPosition(c, [0, 0, 0], 0); // turning does not move
  });

  it('honours a custom turnRate and sensitivity', () => {
    const c = at([0, 0, 0], 0, 0, { turnRate: 30, sensitivity: 1 });
    hold(c, 'ArrowRight');
    c.update(0.1);
    expect(c.pose.yaw).toBeCloseTo(3, 12);
    c.look(5, 0);
    expect(c.pose.yaw).toBeCloseTo(8, 12);
  });

  it('moves along the turned direction when turning and walking together', () => {
    const c = at([0, 0, 0], -90, 0);
    hold(c, 'KeyW', 'ArrowRight');
    c.update(0.1);
    expect(dist(c, [0, 0, 0])).toBeCloseTo(0.3, 12);
    expect(c.pose.position[0]).toBeGreaterThan(0);
  });

  it('keeps yaw wrapped into [−180, 180) like the camera-rotation attribute', () => {
    const c = at([0, 0, 0], 170, 0);
    hold(c, 'ArrowRight');
    c.update(0.1);
    expect(c.pose.yaw).toBeCloseTo(179, 9);
    c.update(0.1);
    expect(c.pose.yaw).toBeCloseTo(-172, 9);
    c.setPose([0, 0, 0], 370, 0);
    expect(c.pose.yaw).toBeCloseTo(10, 12);
    for (const y of [-540, -180, 180, 359.5, 1e6, -1e6]) {
      const w = wrapYaw(y);
      expect(w).toBeGreaterThanOrEqual(-180);
      expect(w).toBeLessThan(180);
      expect(Math.abs(Math.cos(((w - y) * Math.PI) / 180) - 1)).toBeLessThan(1e-9);
    }
  });
});

describe('keys and state', () => {
  it('handles exactly the flyby keys', () => {
    const c = new FlybyController();
    for (const code of ['KeyW', 'KeyA', 'KeyS', 'KeyD', 'Space', 'ShiftLeft', 'ShiftRight', 'ArrowLeft', 'ArrowRight', 'ArrowUp', 'ArrowDown']) {
      expect(c.keyDown(code), code).toBe(true);
      expect(c.keyUp(code), code).toBe(true);
    }
    for (const code of ['KeyQ', 'KeyF', 'Escape', 'Tab', 'w', 'W', '', 'Enter', 'ControlLeft']) {
      expect(c.keyDown(code), code).toBe(false);
      expect(c.keyUp(code), code).toBe(false);
    }
    expect(c.active).toBe(false);
  });

  it('is active while any movement or turn key is held', () => {
    const c = new FlybyController();
    expect(c.active).toBe(false);
    c.keyDown('KeyQ');
    expect(c.active).toBe(false);
    c.keyDown('KeyW');
    c.keyDown('ArrowLeft');
    expect(c.active).toBe(true);
    c.keyUp('KeyW');
    expect(c.active).toBe(true);
    c.keyUp('ArrowLeft');
    expect(c.active).toBe(false);
    c.keyUp('ArrowLeft'); // a stray keyup is harmless
    expect(c.active).toBe(false);
  });

  it('releaseAll stops all motion', () => {
    const c = at([0, 0, 0]);
    hold(c, 'KeyW', 'KeyD', 'Space', 'ArrowLeft', 'ArrowUp');
    expect(c.active).toBe(true);
    c.releaseAll();
    expect(c.active).toBe(false);
    expect(c.update(0.1)).toBe(false);
    expectPosition(c, [0, 0, 0], 0);
    expect([c.pose.yaw, c.pose.pitch]).toEqual([-90, 0]);
  });

  it('update with nothing held returns false and changes nothing', () => {
    const c = at([1, 2, 3], 45, 10);
    expect(c.update(0.1)).toBe(false);
    expectPosition(c, [1, 2, 3], 0);
  });

  it('setPose copies (later changes to the source do not leak in), wraps yaw, clamps pitch', () => {
    const c = new FlybyController();
    const src: [number, number, number] = [4, 5, 6];
    c.setPose(src, 190, 120);
    src[0] = 99;
    expect(c.pose.position).toEqual([4, 5, 6]);
    expect(c.pose.yaw).toBeCloseTo(-170, 12);
    expect(c.pose.pitch).toBe(PITCH_LIMIT);
  });

  it('setPose ignores non-finite components instead of poisoning the pose', () => {
    const c = at([1, 2, 3], 10, 20);
    c.setPose([NaN, 7, Infinity], NaN, -Infinity);
    expect(c.pose.position).toEqual([1, 7, 3]);
    expect([c.pose.yaw, c.pose.pitch]).toEqual([10, 20]);
  });

  it('falls back to defaults for nonsense options', () => {
    const c = at([0, 0, 0], -90, 0, { speed: NaN, maxDt: -1, turnRate: Infinity });
    hold(c, 'KeyW', 'ArrowRight');
    c.update(1);
    expect(dist(c, [0, 0, 0])).toBeCloseTo(0.3, 12);
    expect(c.pose.yaw).toBeCloseTo(-81, 12);
  });
});

describe('allocation', () => {
  it('update keeps the same pose and position objects', () => {
    const c = at([0, 0, 0]);
    const pose = c.pose;
    const position = c.pose.position;
    hold(c, 'KeyW', 'ArrowLeft');
    run(c, 1);
    expect(c.pose).toBe(pose);
    expect(c.pose.position).toBe(position);
  });
});
