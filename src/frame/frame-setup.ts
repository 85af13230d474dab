// Per-frame matrices, composed in float64 on the CPU and stored as float32 for upload.
// Positions are relative to the eye (camera-relative rendering) so far cameras keep precision.
// Reads the scene value (docs/scene-model.md#one-scene-value): any number of objects, any glass placement, up to 4 lights.
import { mat3, mat4 } from 'gl-matrix';
import { forwardFromYawPitch, projectionMatrix, rotationOnlyView, viewerSide } from '../math/camera';
import { eyeRelativePlane, MIRROR_CONTACT, reflectPoint, reflectionMatrix, signedDistance } from '../math/mirror';
import type { CourseDepthRange } from '../scene/course-depth';
import type { CourseProjection } from './course-projection';
import type { OrthographicView } from './orthographic-view';
import type { CourseCamera } from '../math/course-camera';
import { CAMERA, DEFAULT_GLASS } from '../scene/default-scene';
import { glassFrame, type GlassFrame } from '../scene/glass-frame';
import { isIdentity, turnMatrix } from '../scene/turn';
import { MAX_LIGHTS, type Glass, type Scene, type SceneObject } from '../scene/scene';
import type { FrameState } from './types';
import { jitterClip, refinementOffset, refines } from './refinement';

/** What one draw of one object needs, for one eye (real or mirrored). */
export class DrawMatrices {
  readonly modelViewProjection = new Float32Array(16);
  readonly modelRelative = new Float32Array(16);
  readonly normal = new Float32Array(9);
}

/** One object's matrices for both eyes, and its bounding sphere in world space. */
export class ObjectMatrices {
  readonly model = new Float64Array(16);
  /** The model's normal matrix (inverse transpose, 3×3), float64: the same for both eyes. */
  readonly normal = new Float64Array(9);
  readonly main = new DrawMatrices();
  readonly mirrored = new DrawMatrices();
  readonly center = new Float64Array(3);
  radius = 0;
  /** The centre's signed distance from the glass plane, positive on the viewer's side. */
  viewerDistance = 0;
}

/** Light vectors (xyz; w 0 directional, 1 point) relative to one eye, for upload. */
export class LightVectors {
  readonly vectors = new Float32Array(4 * MAX_LIGHTS);
}

const f64 = (n: number) => new Float64Array(n);
const TWO_PI = 2 * Math.PI;
const DEG = Math.PI / 180;
/** uViewVector of a perspective eye: V = normalize(−relPos). */
const PERSPECTIVE_VIEW = [0, 0, 0, 1] as const;

export class FrameSetup {
  readonly eye = f64(3);
  readonly mirroredEye = f64(3);
  /**
   * +1 when the camera sees the side the glass normal points to, −1 otherwise: the eye's side
   * in perspective, the side the view direction comes from in orthographic (viewerSide).
   */
  side = 1;
  /** Whether this frame's projection is orthographic (docs/interaction.md#orthographic-projection). */
  // Stryker disable next-line BooleanLiteral: update() sets it before anything reads it
  orthographic = false;
  /** Orthographic half-height in world units (orthoHalfHeight); 0 in perspective. */
  halfHeight = 0;
  /** Unit view direction of the real camera. */
  readonly forward = f64(3);
  /** forward · glass normal: 0 when the view direction lies in the glass plane. */
  viewDot = 0;
  /**
   * uViewVector of each eye (lighting.glsl, glass.frag): V = normalize(xyz − w·relPos).
   * Perspective (0, 0, 0, 1): V points to the eye. Orthographic (−forward, 0): the constant
   * direction towards the viewer, mirrored for the mirrored camera.
   */
  readonly viewVectorMain = new Float32Array([0, 0, 0, 1]);
  readonly viewVectorMirrored = new Float32Array([0, 0, 0, 1]);
  /** Signed distance of the eye from the glass plane. */
  eyeDistance = 0;
  /** The glass this frame (the default one's frame when the scene has none). */
  glass: GlassFrame = glassFrame(DEFAULT_GLASS);
  /** Whether the scene has a glass at all. */
  // Stryker disable next-line BooleanLiteral: the first update() sets it (lastGlass starts undefined, unlike any scene's glass)
  hasGlass = true;
  /**
   * True when the projection mirrors the picture (a course camera with one negative half-size,
   * or looking away from everything, docs/course-files.md#cameras-that-look-away): a triangle counter-clockwise as seen from the
   * eye is clockwise on screen, so whoever culls back faces swaps its front face.
   */
  // Stryker disable next-line BooleanLiteral: viewAndProjection() sets it every frame before anything reads it
  mirrorsWinding = false;
  /** The course camera's near, far and `behind` this frame; null for the flyby camera. */
  courseRange: CourseDepthRange | null = null;
  readonly projection = f64(16);
  /** Per scene object, in scene order; grows with the scene, never shrinks. */
  readonly objects: ObjectMatrices[] = [];
  /** The glass mesh is built in world coordinates: its model matrix is the identity. */
  readonly glassMain = new DrawMatrices();
  readonly glassMirrored = new DrawMatrices();
  readonly lightsMain = new LightVectors();
  readonly lightsMirrored = new LightVectors();
  /** Each light's position (point) or direction (directional) in the world, after the trackball's turn. */
  readonly lightWorld = f64(3 * MAX_LIGHTS);
  /** Ia, Id, Is of each light (rgb), and how many lights there are. */
  readonly lightAmbient = new Float32Array(3 * MAX_LIGHTS);
  readonly lightDiffuse = new Float32Array(3 * MAX_LIGHTS);
  readonly lightSpecular = new Float32Array(3 * MAX_LIGHTS);
  lightCount = 0;
  /** Bit i set: light i is a point light. */
  pointMask = 0;
  /** The glass projected by the mirrored camera (for the reflection lookup). */
  readonly reflectionViewProjection = new Float32Array(16);
  /** Clip plane in mirrored-eye-relative coordinates (float64); keeps the eye's side. */
  readonly mirroredClip = f64(4);
  /** mirroredClip in float32, for upload. */
  readonly clipPlane = new Float32Array(4);

  /** Projection × rotation-only view: maps eye-relative points to clip space. */
  readonly viewProjection = f64(16);
  /** The same for mirrored-eye-relative points: viewProjection · L, L the plane's linear reflection. */
  readonly mirroredViewProjection = f64(16);
  private readonly viewRotation = f64(16);
  private readonly reflectionLinear = f64(16);
  private readonly relative = f64(16);
  private readonly temp = f64(16);
  /** The glass's normal matrix: its mesh is in world coordinates. */
  private readonly identityNormal = mat3.identity(f64(9) as unknown as mat3) as unknown as Float64Array;
  private readonly scratch3 = f64(3);
  /** This frame's offset of the pixel grid when it refines a still view (docs/refinement.md). */
  private readonly jitter = f64(2);
  private readonly identity = mat4.identity(f64(16) as unknown as mat4) as unknown as Float64Array;
  private lastGlass: Glass | null | undefined = undefined;
  /** The trackball's turn of the objects and of the first light this frame (FrameState.turn); null: none. */
  private readonly objectsTurnMatrix = f64(16);
  private readonly lightTurnMatrix = f64(16);
  private objectsTurn: Float64Array | null = null;
  private lightTurn: Float64Array | null = null;

  /**
   * `course`: the course camera's projection (frame/course-projection.ts), which only frames
   * with a course camera need: a renderer loads it when one asks for it. Without it a course
   * camera is ignored (the flyby camera's pose is used). `ortho`: the orthographic projection
   * (frame/orthographic-view.ts), loaded the same way; without it frames are drawn in perspective.
   */
  constructor(public course: CourseProjection | null = null, public ortho: OrthographicView | null = null) {}

  update(s: FrameState, scene: Scene): void {
    const { eye, mirroredEye } = this;
    // Stryker disable next-line ConditionalExpression: the glass's frame worked out every frame is the same numbers; the test saves the work
    if (scene.glass !== this.lastGlass) {
      this.lastGlass = scene.glass;
      this.hasGlass = scene.glass !== null;
      this.glass = glassFrame(scene.glass ?? DEFAULT_GLASS);
    }
    const plane = this.glass.plane;
    const course = this.course ? s.courseCamera ?? null : null;
    const position = course ? course.c : s.cameraPosition;
    eye[0] = position[0]; eye[1] = position[1]; eye[2] = position[2];
    reflectPoint(mirroredEye, eye, plane);
    this.eyeDistance = signedDistance(plane, eye);
    const forward = course ? this.copyForward(course.n) : forwardFromYawPitch(this.forward, s.yaw, s.pitch);
    // Stryker disable next-line StringLiteral: only 'orthographic' is told apart below
    const projection = course || !this.ortho ? 'perspective' : s.projection ?? 'perspective';
    this.orthographic = projection === 'orthographic';
    this.side = viewerSide(plane, eye, forward, projection);
    this.viewDot = plane[0] * forward[0] + plane[1] * forward[1] + plane[2] * forward[2];

    const turn = s.turn ?? null;
    this.objectsTurn = turn && !isIdentity(turn.objects) ? (turnMatrix(this.objectsTurnMatrix as unknown as mat4, turn.objects, turn.center) as unknown as Float64Array) : null;
    this.lightTurn = turn && !isIdentity(turn.light) ? (turnMatrix(this.lightTurnMatrix as unknown as mat4, turn.light, turn.center) as unknown as Float64Array) : null;
    this.viewAndProjection(s, scene, forward, course);
    if (refines(s)) {
      refinementOffset(s.refinement!, s.refinementFrames ?? 1, this.jitter);
      jitterClip(this.viewProjection, this.jitter[0], this.jitter[1], s.width, s.height);
    }
    // Mirrored eye-relative: V·R·x = Vrot·L·(x − mirroredEye), L the plane's linear reflection.
    reflectionMatrix(this.reflectionLinear, plane);
    this.reflectionLinear[12] = this.reflectionLinear[13] = this.reflectionLinear[14] = 0;
    mat4.multiply(this.mirroredViewProjection as unknown as mat4, this.viewProjection as unknown as mat4, this.reflectionLinear as unknown as mat4);
    this.drawMatrices(scene, s.time);
    this.lightValues(scene);

    // Keep what lies on the viewer's side: side·(n·(rel + e′) + d) ≥ MIRROR_CONTACT (exact in
    // either projection), so what touches the glass is not reflected.
    eyeRelativePlane(this.mirroredClip, plane, mirroredEye, this.side);
    this.mirroredClip[3] -= MIRROR_CONTACT;
    this.clipPlane.set(this.mirroredClip);
  }

  /**
   * projection and viewProjection of this frame's camera (the course's, an orthographic or a
   * perspective one), the orthographic half-height and each eye's view vector.
   */
  private viewAndProjection(s: FrameState, scene: Scene, forward: Float64Array, course: CourseCamera | null): void {
    // Same near and far for both projections (docs/default-scene.md#the-camera): the orthographic eye is a point on the
    // view plane's centre like the perspective one, and draws depths near..far ahead of it.
    const aspect = s.width / Math.max(1, s.height);
    this.mirrorsWinding = false;
    this.courseRange = null;
    if (course) {
      this.halfHeight = 0;
      this.viewVectorMain.set(PERSPECTIVE_VIEW);
      this.viewVectorMirrored.set(PERSPECTIVE_VIEW);
      this.course!.apply(this, course, scene, s.time, this.objectsTurn ? s.turn! : null);
      return;
    }
    if (this.orthographic) {
      this.ortho!(this, s, scene.glass?.center ?? null, forward, this.glass.plane, aspect);
    } else {
      this.halfHeight = 0;
      projectionMatrix(this.projection, s.fov, aspect, CAMERA.near, CAMERA.far);
      this.viewVectorMain.set(PERSPECTIVE_VIEW);
      this.viewVectorMirrored.set(PERSPECTIVE_VIEW);
    }
    rotationOnlyView(this.viewRotation, s.yaw, s.pitch, this.scratch3);
    mat4.multiply(this.viewProjection as unknown as mat4, this.projection as unknown as mat4, this.viewRotation as unknown as mat4);
  }

  /** Every object's matrices and the glass's, for both eyes. */
  private drawMatrices(scene: Scene, time: number): void {
    const { eye, mirroredEye } = this;
    const objects = scene.objects;
    // Stryker disable next-line EqualityOperator: one spare slot more is never read
    while (this.objects.length < objects.length) this.objects.push(new ObjectMatrices());
    for (let i = 0; i < objects.length; i++) {
      const o = this.objects[i];
      this.modelMatrix(o, objects[i], time, this.objectsTurn);
      mat3.normalFromMat4(o.normal as unknown as mat3, o.model as unknown as mat4);
      this.compose(o.main, o.model, o.normal, eye, this.viewProjection);
      this.compose(o.mirrored, o.model, o.normal, mirroredEye, this.mirroredViewProjection);
    }
    this.compose(this.glassMain, this.identity, this.identityNormal, eye, this.viewProjection);
    this.compose(this.glassMirrored, this.identity, this.identityNormal, mirroredEye, this.mirroredViewProjection);
    this.reflectionViewProjection.set(this.glassMirrored.modelViewProjection);
  }

  /** The lights' vectors from each eye, their colours, how many and which are points. */
  private lightValues(scene: Scene): void {
    this.lightCount = Math.min(scene.lights.length, MAX_LIGHTS);
    const w = this.lightWorld, g0 = this.lightTurn;
    for (let i = 0; i < this.lightCount; i++) {
      const l = scene.lights[i], x = l.vector[0], y = l.vector[1], z = l.vector[2];
      // The first light turns with the trackball's right-drag: a point light about the centre, a direction by the rotation.
      const g = i === 0 ? g0 : null, t = l.kind === 'point' ? 1 : 0;
      w[3 * i] = g ? g[0] * x + g[4] * y + g[8] * z + t * g[12] : x;
      w[3 * i + 1] = g ? g[1] * x + g[5] * y + g[9] * z + t * g[13] : y;
      w[3 * i + 2] = g ? g[2] * x + g[6] * y + g[10] * z + t * g[14] : z;
    }
    lightVectors(this.lightsMain, scene, w, this.eye);
    lightVectors(this.lightsMirrored, scene, w, this.mirroredEye);
    this.pointMask = 0;
    for (let i = 0; i < this.lightCount; i++) {
      const l = scene.lights[i];
      if (l.kind === 'point') this.pointMask |= 1 << i;
      // Stryker disable next-line EqualityOperator: c = 3 writes the next light's first slot, written after it (past the 4th: dropped)
      for (let c = 0; c < 3; c++) {
        this.lightAmbient[3 * i + c] = l.ambient[c];
        this.lightDiffuse[3 * i + c] = l.diffuse[c];
        this.lightSpecular[3 * i + c] = l.specular[c];
      }
    }
  }

  private copyForward(n: ArrayLike<number>): Float64Array {
    this.forward[0] = n[0]; this.forward[1] = n[1]; this.forward[2] = n[2];
    return this.forward;
  }

  /** turn · T · Rz·Ry·Rx · Ry(spin·t) · S, and the world bounding sphere. */
  private modelMatrix(out: ObjectMatrices, object: SceneObject, time: number, turn: Float64Array | null): void {
    const m = out.model as unknown as mat4;
    const { position, rotation, scale, spin } = object.transform;
    mat4.fromTranslation(m, position);
    // Stryker disable next-line ConditionalExpression: a turn by 0 is exactly the identity (cos 0 = 1, sin 0 = 0); the tests skip work
    if (rotation[2] !== 0) mat4.rotateZ(m, m, rotation[2] * DEG);
    // Stryker disable next-line ConditionalExpression: as above
    if (rotation[1] !== 0) mat4.rotateY(m, m, rotation[1] * DEG);
    // Stryker disable next-line ConditionalExpression: as above
    if (rotation[0] !== 0) mat4.rotateX(m, m, rotation[0] * DEG);
    // Stryker disable next-line ConditionalExpression: spin 0 turns by 0 (or by 0 when 0·time is NaN): the identity
    if (spin !== 0) {
      // spin·time may overflow (both finite, product not): any angle is then as good as another.
      const angle = spin * time;
      mat4.rotateY(m, m, Number.isFinite(angle) ? angle % TWO_PI : 0);
    }
    const scaled = scale[0] !== 1 || scale[1] !== 1 || scale[2] !== 1;
    // Stryker disable next-line ConditionalExpression: a scale by (1, 1, 1) multiplies by exactly 1; the test skips work
    if (scaled) mat4.scale(m, m, scale);
    if (turn) mat4.multiply(m, turn as unknown as mat4, m);
    const c = object.bounds.center;
    const t = this.scratch3;
    t[0] = c[0]; t[1] = c[1]; t[2] = c[2];
    const mm = out.model;
    out.center[0] = mm[0] * t[0] + mm[4] * t[1] + mm[8] * t[2] + mm[12];
    out.center[1] = mm[1] * t[0] + mm[5] * t[1] + mm[9] * t[2] + mm[13];
    out.center[2] = mm[2] * t[0] + mm[6] * t[1] + mm[10] * t[2] + mm[14];
    out.radius = object.bounds.radius * Math.max(Math.abs(scale[0]), Math.abs(scale[1]), Math.abs(scale[2]));
    out.viewerDistance = this.side * signedDistance(this.glass.plane, out.center);
  }

  private compose(out: DrawMatrices, model: Float64Array, normal: Float64Array, eye: Float64Array, viewProjection: Float64Array): void {
    const rel = this.relative;
    rel.set(model);
    rel[12] -= eye[0]; rel[13] -= eye[1]; rel[14] -= eye[2];
    out.modelRelative.set(rel);
    mat4.multiply(this.temp as unknown as mat4, viewProjection as unknown as mat4, rel as unknown as mat4);
    out.modelViewProjection.set(this.temp);
    out.normal.set(normal);
  }
}

/**
 * Directional: the unit vector towards the light (w 0). Point: its position relative to `eye`
 * (w 1). `world` holds each light's vector in the world (FrameSetup.lightWorld).
 */
function lightVectors(out: LightVectors, scene: Scene, world: Float64Array, eye: Float64Array): void {
  const v = out.vectors;
  v.fill(0);
  const n = Math.min(scene.lights.length, MAX_LIGHTS);
  for (let i = 0; i < n; i++) {
    const l = scene.lights[i];
    const x = world[3 * i], y = world[3 * i + 1], z = world[3 * i + 2];
    if (l.kind === 'point') {
      v[4 * i] = x - eye[0]; v[4 * i + 1] = y - eye[1]; v[4 * i + 2] = z - eye[2]; v[4 * i + 3] = 1;
    } else {
      const len = Math.hypot(x, y, z) || 1;
      v[4 * i] = x / len; v[4 * i + 1] = y / len; v[4 * i + 2] = z / len;
    }
  }
}
