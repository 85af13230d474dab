// Per-frame matrices, composed in float64 on the CPU and stored as float32 for upload.
// Positions are relative to the eye (camera-relative rendering) so far cameras keep precision.
import { mat3, mat4 } from 'gl-matrix';
import { projectionMatrix, rotationOnlyView } from '../math/camera';
import { reflectPoint, reflectionMatrix, signedDistance } from '../math/mirror';
import { CAMERA, CUBE, GLASS, SPHERE } from '../scene/default-scene';
import type { FrameState } from './types';

/** What one draw of one object needs, for one eye (real or mirrored). */
export class DrawMatrices {
  readonly modelViewProjection = new Float32Array(16);
  readonly modelRelative = new Float32Array(16);
  readonly normal = new Float32Array(9);
}

export type ObjectName = 'cube' | 'sphere' | 'glass';

const f64 = (n: number) => new Float64Array(n);
const TWO_PI = 2 * Math.PI;
const OBJECTS: readonly ObjectName[] = ['cube', 'sphere', 'glass'];

export class FrameSetup {
  readonly eye = f64(3);
  readonly mirroredEye = f64(3);
  /** +1 when the eye is on the +Z side of the glass, −1 otherwise. */
  side = 1;
  /** Signed distance of the eye from the glass plane. */
  eyeDistance = 0;
  readonly projection = f64(16);
  readonly models: Record<ObjectName, Float64Array> = { cube: f64(16), sphere: f64(16), glass: f64(16) };
  readonly main: Record<ObjectName, DrawMatrices> = { cube: new DrawMatrices(), sphere: new DrawMatrices(), glass: new DrawMatrices() };
  readonly mirrored: Record<ObjectName, DrawMatrices> = { cube: new DrawMatrices(), sphere: new DrawMatrices(), glass: new DrawMatrices() };
  /** The glass projected by the mirrored camera (for the reflection lookup). */
  readonly reflectionViewProjection = new Float32Array(16);
  /** Clip plane in mirrored-eye-relative coordinates; keeps the eye's side. */
  readonly clipPlane = new Float32Array(4);

  /** Projection × rotation-only view: maps eye-relative points to clip space. */
  readonly viewProjection = f64(16);
  private readonly viewRotation = f64(16);
  private readonly mirroredViewProjection = f64(16);
  private readonly reflectionLinear = f64(16);
  private readonly relative = f64(16);
  private readonly temp = f64(16);
  private readonly normal3 = f64(9);
  private readonly scratch3 = f64(3);

  constructor() {
    for (const m of [this.models.cube, this.models.sphere, this.models.glass]) mat4.identity(m as unknown as mat4);
  }

  update(s: FrameState): void {
    const { eye, mirroredEye } = this;
    eye[0] = s.cameraPosition[0]; eye[1] = s.cameraPosition[1]; eye[2] = s.cameraPosition[2];
    reflectPoint(mirroredEye, eye, GLASS.plane);
    this.eyeDistance = signedDistance(GLASS.plane, eye);
    this.side = this.eyeDistance >= 0 ? 1 : -1;

    projectionMatrix(this.projection, s.fov, s.width / Math.max(1, s.height), CAMERA.near, CAMERA.far);
    rotationOnlyView(this.viewRotation, s.yaw, s.pitch, this.scratch3);
    mat4.multiply(this.viewProjection as unknown as mat4, this.projection as unknown as mat4, this.viewRotation as unknown as mat4);
    // Mirrored eye-relative: V·R·x = Vrot·L·(x − mirroredEye), L the plane's linear reflection.
    reflectionMatrix(this.reflectionLinear, GLASS.plane);
    this.reflectionLinear[12] = this.reflectionLinear[13] = this.reflectionLinear[14] = 0;
    mat4.multiply(this.mirroredViewProjection as unknown as mat4, this.viewProjection as unknown as mat4, this.reflectionLinear as unknown as mat4);

    const cube = this.models.cube as unknown as mat4;
    const t = this.scratch3;
    t[0] = CUBE.x; t[1] = CUBE.y; t[2] = s.cubeDistance;
    mat4.fromTranslation(cube, t);
    // spin·time may overflow (both finite, product not): any angle is then as good as another.
    const angle = s.spin * s.time;
    mat4.rotateY(cube, cube, Number.isFinite(angle) ? angle % TWO_PI : 0);
    const sphere = this.models.sphere as unknown as mat4;
    mat4.fromTranslation(sphere, SPHERE.centre);

    for (const name of OBJECTS) {
      this.compose(this.main[name], this.models[name], eye, this.viewProjection);
      this.compose(this.mirrored[name], this.models[name], mirroredEye, this.mirroredViewProjection);
    }
    this.reflectionViewProjection.set(this.mirrored.glass.modelViewProjection);

    // Keep what lies on the eye's side: side·(n·(rel + e′) + d) ≥ 0.
    const p = GLASS.plane;
    this.clipPlane[0] = this.side * p[0];
    this.clipPlane[1] = this.side * p[1];
    this.clipPlane[2] = this.side * p[2];
    this.clipPlane[3] = this.side * signedDistance(p, mirroredEye);
  }

  private compose(out: DrawMatrices, model: Float64Array, eye: Float64Array, viewProjection: Float64Array): void {
    const rel = this.relative;
    rel.set(model);
    rel[12] -= eye[0]; rel[13] -= eye[1]; rel[14] -= eye[2];
    out.modelRelative.set(rel);
    mat4.multiply(this.temp as unknown as mat4, viewProjection as unknown as mat4, rel as unknown as mat4);
    out.modelViewProjection.set(this.temp);
    mat3.normalFromMat4(this.normal3 as unknown as mat3, model as unknown as mat4);
    out.normal.set(this.normal3);
  }
}
