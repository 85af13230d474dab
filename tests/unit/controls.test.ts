// The pure parts of docs/interaction.md: Shoemake's arcball with Bell's sheet, inertia exact for any frame time,
// the release velocity, the orbit camera, and the trackball's rotation of the scene value.
import { describe, expect, it } from 'vitest';
import { mat3, mat4, quat, vec3 } from 'gl-matrix';
import { arcballAngle, arcballPoint } from '../../src/element/controls/arcball';
import { Inertia, INERTIA_STOP, INERTIA_TAU, MAX_RATE, MAX_STEP, REST_MS, VelocityTracker } from '../../src/element/controls/inertia';
import { OrbitCamera } from '../../src/element/controls/orbit';
import { boundsCenter, eulerToQuat, quatToEuler, rotateLight, rotateObjects } from '../../src/scene/group-rotation';
import { forwardFromYawPitch, type CameraPose } from '../../src/math/camera';
import type { Light, SceneObject } from '../../src/scene/scene';

const DEG = Math.PI / 180;
// gl-matrix's create() is float32: the controls work in float64, and so do these checks.
const q64 = () => new Float64Array([0, 0, 0, 1]) as unknown as quat;
const v64 = () => new Float64Array(3) as unknown as vec3;
const m64 = () => mat4.identity(new Float64Array(16) as unknown as mat4);

describe('arcball (Shoemake, Bell\'s hyperbolic sheet)', () => {
  it('maps the centre to the pole and keeps every point unit length', () => {
    expect([...arcballPoint(v64(), 100, 50, 200, 100)]).toEqual([0, 0, 1]);
    for (const [x, y] of [[0, 0], [150, 20], [199, 99], [1000, -500]]) {
      expect(vec3.length(arcballPoint(v64(), x, y, 200, 100))).toBeCloseTo(1, 12);
    }
  });

  it('is the sphere inside r² = ½ and the sheet z = ½/r outside, meeting continuously', () => {
    // 200×200: radius 100 px. At r = 0.5 on the sphere z = √(1 − ¼).
    const p = arcballPoint(v64(), 150, 100, 200, 200);
    expect(p[2] / p[0]).toBeCloseTo(Math.sqrt(0.75) / 0.5, 12);
    // At r = 2 on the sheet: z = ¼ before normalising.
    const q = arcballPoint(v64(), 300, 100, 200, 200);
    expect(q[2] / q[0]).toBeCloseTo(0.25 / 2, 12);
    // Either side of r = 1/√2 the two agree to first order.
    const r = 100 / Math.SQRT2;
    const inner = arcballPoint(v64(), 100 + r - 1e-6, 100, 200, 200), outer = arcballPoint(v64(), 100 + r + 1e-6, 100, 200, 200);
    expect(vec3.distance(inner, outer)).toBeLessThan(1e-7);
  });

  it('a drag of d px from the centre turns by asin(d/r) on the sphere, and keeps turning past the rim', () => {
    expect(arcballAngle(100, 100, 130, 100, 200, 200)).toBeCloseTo(Math.asin(0.3), 12);
    const past = arcballAngle(100, 100, 400, 100, 200, 200);
    expect(past).toBeGreaterThan(arcballAngle(100, 100, 170, 100, 200, 200));
    expect(past).toBeLessThan(Math.PI / 2);
  });
});

describe('inertia', () => {
  function run(hz: number, seconds: number, rate = 2): number {
    const it = new Inertia(1), out = new Float64Array(1);
    it.start([rate]);
    let total = 0;
    for (let t = 0; t < seconds && it.active; t += 1 / hz) {
      it.step(1 / hz, out);
      total += out[0];
    }
    return total;
  }

  it('turns r₀·τ·(1 − e^(−T/τ)) by time T whatever the frame rate (30, 60, 144 Hz)', () => {
    const T = 0.5;
    const exact = 2 * INERTIA_TAU * (1 - Math.exp(-T / INERTIA_TAU));
    for (const hz of [30, 60, 144]) {
      const it = new Inertia(1), out = new Float64Array(1);
      it.start([2]);
      const n = Math.round(T * hz);
      let total = 0;
      for (let i = 0; i < n; i++) { it.step(1 / hz, out); total += out[0]; }
      expect(total).toBeCloseTo(exact, 12);
    }
  });

  it('ends in the same place at 30 and 144 Hz (within a stop-threshold\'s remainder)', () => {
    const a = run(30, 20), b = run(144, 20);
    expect(Math.abs(a - b)).toBeLessThan(INERTIA_STOP * INERTIA_TAU * 2);
    expect(a).toBeCloseTo(2 * INERTIA_TAU, 3);
  });

  it('stops at the first step once below 0.05°/s: τ·ln(r₀ ÷ 0.05°/s) after the start', () => {
    const it = new Inertia(1), out = new Float64Array(1);
    it.start([1]);
    let frames = 0;
    while (it.active && frames < 10_000) { it.step(1 / 60, out); frames++; }
    // ln(1 rad/s ÷ 0.05°/s)·τ = 2.756 s: the 166th frame at 60 Hz is the first at or past it.
    const T = INERTIA_TAU * Math.log(1 / INERTIA_STOP);
    expect(INERTIA_STOP).toBeCloseTo(0.05 * DEG, 15);
    expect(frames).toBe(Math.ceil(T * 60));
  });

  it('decays by the wall clock at any frame time: 13 Hz frames, or one of 1 s, take the rates down by e^(−dt/τ)', () => {
    const it = new Inertia(1), out = new Float64Array(1);
    it.start([2]);
    for (let i = 0; i < 13; i++) it.step(1 / 13, out);
    expect(it.rates[0]).toBeCloseTo(2 * Math.exp(-1 / INERTIA_TAU), 12);
    const a = new Inertia(1), oa = new Float64Array(1);
    a.start([2]);
    a.step(1, oa);
    expect(a.rates[0]).toBeCloseTo(2 * Math.exp(-1 / INERTIA_TAU), 12);
  });

  it('a stall turns no further than a MAX_STEP frame (a quarter second), and a 13 Hz frame is not a stall', () => {
    const turn = (dt: number) => { const it = new Inertia(1), out = new Float64Array(1); it.start([2]); it.step(dt, out); return out[0]; };
    expect(turn(1)).toBe(turn(MAX_STEP));
    expect(turn(1 / 13)).toBeCloseTo(2 * INERTIA_TAU * (1 - Math.exp(-1 / 13 / INERTIA_TAU)), 12);
  });

  it('caps the release rate at MAX_RATE and ignores non-finite rates', () => {
    const it = new Inertia(2);
    it.start([100, 0]);
    expect(Math.hypot(...it.rates)).toBeCloseTo(MAX_RATE, 12);
    it.start([NaN, Infinity]);
    expect(it.active).toBe(false);
  });
});

describe('VelocityTracker', () => {
  it('measures a steady drag\'s rate over the last 80 ms', () => {
    const v = new VelocityTracker(1);
    v.reset(0);
    for (let t = 10; t <= 300; t += 10) v.add(t, [0.02]); // 2 per second
    expect(v.rates(305, new Float64Array(1))[0]).toBeCloseTo(2, 12);
  });

  it('gives no rate when the pointer rested more than 100 ms before release', () => {
    const v = new VelocityTracker(1);
    v.reset(0);
    for (let t = 10; t <= 100; t += 10) v.add(t, [0.02]);
    expect(v.rates(100 + REST_MS + 1, new Float64Array(1))[0]).toBe(0);
    expect(v.rates(100 + REST_MS - 1, new Float64Array(1))[0]).toBeGreaterThan(0);
  });

  it('keeps working when more events than its capacity come', () => {
    const v = new VelocityTracker(1, 4);
    v.reset(0);
    for (let t = 5; t <= 1000; t += 5) v.add(t, [0.01]);
    expect(v.rates(1000, new Float64Array(1))[0]).toBeCloseTo(2, 12);
  });
});

describe('OrbitCamera', () => {
  const pose = (): CameraPose => ({ position: [3.6, 2.4, 0.2], yaw: -169, pitch: -23.6 });

  it('begins without moving the camera, about the point on its view axis at the target\'s depth', () => {
    const p = pose(), o = new OrbitCamera();
    o.begin(p, [0, 0, 0]);
    expect(p).toEqual(pose());
    const f = forwardFromYawPitch([0, 0, 0], p.yaw, p.pitch);
    const depth = -(3.6 * f[0] + 2.4 * f[1] + 0.2 * f[2]);
    expect(o.distance).toBeCloseTo(depth, 12);
    for (let i = 0; i < 3; i++) expect(o.target[i]).toBeCloseTo(p.position[i] + f[i] * depth, 12);
  });

  it('turns about the target at a fixed distance, still looking at it', () => {
    const p = pose(), o = new OrbitCamera();
    o.begin(p, [0, 0, 0]);
    const t = [...o.target], d = o.distance;
    o.rotate(p, 30, 10);
    expect(p.yaw).toBeCloseTo(-139, 9);
    expect(Math.hypot(p.position[0] - t[0], p.position[1] - t[1], p.position[2] - t[2])).toBeCloseTo(d, 9);
    const f = forwardFromYawPitch([0, 0, 0], p.yaw, p.pitch);
    for (let i = 0; i < 3; i++) expect(p.position[i] + f[i] * d).toBeCloseTo(t[i], 9);
  });

  it('dollies along the view and pans camera and target together across it', () => {
    const p = pose(), o = new OrbitCamera();
    o.begin(p, [0, 0, 0]);
    const d = o.distance, t0 = [...o.target];
    o.dolly(p, 0.5);
    expect(o.distance).toBeCloseTo(d / 2, 12);
    const before = [...p.position];
    o.pan(p, 10, 0, 100, 60);
    const moved = [0, 1, 2].map((i) => p.position[i] - before[i]);
    const tm = [0, 1, 2].map((i) => o.target[i] - t0[i]);
    for (let i = 0; i < 3; i++) expect(moved[i]).toBeCloseTo(tm[i], 12);
    // 10 px of a 100 px view at distance d/2 under 60°: 0.1 · 2·(d/2)·tan 30°, perpendicular to the view.
    expect(Math.hypot(...moved)).toBeCloseTo(0.1 * d * Math.tan(30 * DEG), 12);
    const f = forwardFromYawPitch([0, 0, 0], p.yaw, p.pitch);
    expect(moved[0] * f[0] + moved[1] * f[1] + moved[2] * f[2]).toBeCloseTo(0, 12);
    // A drag to the right carries the scene right: camera and target go left, along −right.
    const h = Math.hypot(f[0], f[2]), right = [-f[2] / h, 0, f[0] / h];
    expect(moved[0] * right[0] + moved[2] * right[2]).toBeCloseTo(-0.1 * d * Math.tan(30 * DEG), 12);
    // And a drag down carries it down: they go up (+Y, the view's up having a positive Y).
    const y0 = p.position[1];
    o.pan(p, 0, 10, 100, 60);
    expect(p.position[1] - y0).toBeGreaterThan(0);
    o.dolly(p, NaN);
    expect(o.distance).toBeCloseTo(d / 2, 12);
  });
});

describe('the trackball\'s rotation of the scene', () => {
  const obj = (position: [number, number, number], rotation: [number, number, number]): SceneObject => ({
    geometry: { kind: 'box', size: 1 }, transform: { position, rotation, scale: [1, 2, 1], spin: 0 },
    material: { ambient: [0, 0, 0], diffuse: [1, 1, 1], specular: [0, 0, 0], shininess: 1, opacity: 1, texture: { kind: 'procedural' }, mapping: 'uv' },
    bounds: { center: [0, 0, 0], radius: 1 },
  });
  const model = (o: SceneObject) => {
    const m = mat4.fromTranslation(new Float64Array(16) as unknown as mat4, o.transform.position);
    mat4.rotateZ(m, m, o.transform.rotation[2] * DEG);
    mat4.rotateY(m, m, o.transform.rotation[1] * DEG);
    mat4.rotateX(m, m, o.transform.rotation[0] * DEG);
    return m;
  };

  it('Euler degrees to a quaternion, worked by hand: x 90° is (√½, 0, 0, √½); y 90° then x 90° is (½, ½, −½, ½)', () => {
    const h = Math.SQRT1_2;
    expect([...eulerToQuat(q64(), [90, 0, 0])].map((x) => +x.toFixed(12))).toEqual([+h.toFixed(12), 0, 0, +h.toFixed(12)]);
    // Rz·Ry·Rx with x applied first: qy·qx = (0, h, 0, h)·(h, 0, 0, h).
    expect([...eulerToQuat(q64(), [90, 90, 0])].map((x) => +x.toFixed(12))).toEqual([0.5, 0.5, -0.5, 0.5]);
  });

  it('Euler degrees (Rz·Ry·Rx) ↔ quaternion round-trips, gimbal lock included', () => {
    for (const e of [[10, 20, 30], [-170, 45, 100], [0, 90, 30], [5, -89.99, 0]] as [number, number, number][]) {
      const q = eulerToQuat(q64(), e);
      const back = eulerToQuat(q64(), quatToEuler(q));
      expect(Math.abs(quat.dot(q, back))).toBeCloseTo(1, 9);
    }
  });

  it('turns each object about the centre: model\' = T(c)·Q·T(−c)·model', () => {
    const objects = [obj([1, 0, 0], [10, 20, 30]), obj([-1, 2, 0.5], [0, -40, 0])];
    const c = boundsCenter(objects, [0, 0, 0]);
    expect(c).toEqual([0, 1, 0.25]);
    const q = quat.setAxisAngle(q64(), vec3.normalize(v64(), [1, 2, -1]), 0.7);
    const turned = rotateObjects(objects, q, c);
    for (let i = 0; i < objects.length; i++) {
      const expected = m64();
      mat4.translate(expected, expected, c);
      mat4.multiply(expected, expected, mat4.fromQuat(new Float64Array(16) as unknown as mat4, q));
      mat4.translate(expected, expected, [-c[0], -c[1], -c[2]]);
      mat4.multiply(expected, expected, model(objects[i]));
      const got = model(turned[i]);
      for (let k = 0; k < 16; k++) expect(got[k]).toBeCloseTo(expected[k], 9);
    }
    expect(rotateObjects(objects, q64(), c)).toBe(objects);
  });

  it('turns a point light about the centre and a directional light\'s direction', () => {
    const q = quat.setAxisAngle(q64(), [0, 1, 0], Math.PI / 2);
    const base = { ambient: [0, 0, 0], diffuse: [1, 1, 1], specular: [1, 1, 1] } as const;
    const p = rotateLight({ ...base, kind: 'point', vector: [2, 1, 0] } as never, q, [1, 1, 0]);
    expect(p.vector.map((x) => Math.round(x * 1e9) / 1e9)).toEqual([1, 1, -1]);
    const d = rotateLight({ ...base, kind: 'directional', vector: [1, 0, 0] } as never, q, [1, 1, 0]);
    expect(d.vector.map((x) => Math.round(x * 1e9) / 1e9)).toEqual([0, 0, -1]);
  });
});

describe('the group rotation\'s own quaternion arithmetic (the core does without gl-matrix\'s quat and vec3)', () => {
  // Random unit quaternions, Euler angles, centres and lights: the results equal, bit for bit,
  // the same computations through gl-matrix (quat.multiply, vec3.transformQuat, mat3.fromQuat).
  const rand = (seed: number) => () => ((seed = (seed * 16807) % 2147483647) / 2147483647) * 2 - 1;
  const r = rand(7);
  const obj = (position: [number, number, number], rotation: [number, number, number]): SceneObject => ({
    geometry: { kind: 'box', size: 1 }, transform: { position, rotation, scale: [1 + r(), 2, 1 - r() / 2], spin: 0 },
    material: { ambient: [0, 0, 0], diffuse: [1, 1, 1], specular: [0, 0, 0], shininess: 1, opacity: 1, texture: { kind: 'procedural' }, mapping: 'uv' },
    bounds: { center: [0, 0, 0], radius: 1 },
  });
  /** quatToEuler through gl-matrix's mat3.fromQuat (column-major m[c*3 + r]). */
  const eulerOf = (q: quat) => {
    const m = mat3.fromQuat(new Float64Array(9) as unknown as mat3, q);
    const y = Math.asin(Math.max(-1, Math.min(1, -m[2])));
    if (Math.abs(m[2]) < 0.9999999) return [Math.atan2(m[5], m[8]) / DEG, y / DEG, Math.atan2(m[1], m[0]) / DEG];
    return [0, y / DEG, Math.atan2(-m[3], m[4]) / DEG];
  };
  it('boundsCenter, rotateObjects and rotateLight equal their gl-matrix forms on 200 random cases', () => {
    for (let k = 0; k < 200; k++) {
      const q = quat.normalize(q64(), [r(), r(), r(), r()] as unknown as quat);
      const e: [number, number, number] = [180 * r(), 90 * r(), 180 * r()];
      const o = { ...obj([3 * r(), 3 * r(), 3 * r()], e), bounds: { center: [r(), r(), r()], radius: 1 + r() } } as SceneObject;
      // gl-matrix's forms, written out here.
      const qx = quat.setAxisAngle(q64(), [1, 0, 0], e[0] * DEG), qy = quat.setAxisAngle(q64(), [0, 1, 0], e[1] * DEG), qz = quat.setAxisAngle(q64(), [0, 0, 1], e[2] * DEG);
      const qe = quat.multiply(q64(), quat.multiply(q64(), qz, qy), qx);
      expect([...eulerToQuat(q64(), e)]).toEqual([...qe]);
      const c = vec3.add(v64(), vec3.transformQuat(v64(), vec3.multiply(v64(), o.bounds.center as vec3, o.transform.scale as vec3), qe), o.transform.position as vec3);
      // One object: the middle of its box is its centre, (c − r + c + r) / 2, to rounding.
      const b = boundsCenter([o], [0, 0, 0]), rad = o.bounds.radius * Math.max(...o.transform.scale.map(Math.abs));
      expect(b).toEqual([0, 1, 2].map((i) => (c[i] - rad + (c[i] + rad)) / 2));
      const centre: [number, number, number] = [r(), r(), r()];
      const p = vec3.add(v64(), vec3.transformQuat(v64(), vec3.subtract(v64(), o.transform.position as vec3, centre), q), centre);
      const [turned] = rotateObjects([o], q, centre);
      expect(turned.transform.position).toEqual([p[0], p[1], p[2]]);
      expect(turned.transform.rotation).toEqual(eulerOf(quat.multiply(q64(), q, qe)));
      const light = { ambient: [0, 0, 0], diffuse: [1, 1, 1], specular: [1, 1, 1], kind: 'point', vector: [r(), r(), r()] } as never as Light;
      const lp = vec3.add(v64(), vec3.transformQuat(v64(), vec3.subtract(v64(), light.vector as vec3, centre), q), centre);
      expect(rotateLight(light, q, centre).vector).toEqual([lp[0], lp[1], lp[2]]);
      const dir = { ...light, kind: 'directional' } as Light, ld = vec3.transformQuat(v64(), dir.vector as vec3, q);
      expect(rotateLight(dir, q, centre).vector).toEqual([ld[0], ld[1], ld[2]]);
    }
  });
});
