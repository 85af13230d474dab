// The course's Phong equation (docs/course-files.md#course-phong), on the 0..255 scale of its files.
// Not shared with the renderers or the reference: none calls it (the element turns the course's
// light and material into the scene's Blinn-Phong (docs/scene-model.md#lights), element/children/course-lighting.ts). Tied down
// by tests/unit/course-lighting.test.ts's values worked out by hand.
import type { Vec3 } from './course-camera';

/** The light of `iluminacao.txt`: a point light at Pl, ambient Ia and intensity Il (0..255). */
export interface CourseLight {
  position: Vec3;
  ambient: Vec3;
  intensity: Vec3;
}

/** The material of `iluminacao.txt`: ka, kd, ks (0..1), Od (rgb 0..1) and the exponent n (η). */
export interface CourseMaterial {
  ka: number;
  kd: number;
  ks: number;
  od: Vec3;
  n: number;
}

/**
 * I = ka·Ia + Il ⊙ (kd·Od·(N·L) + ks·(R·V)^n) at `point` with surface normal `normal` (any
 * length) seen from `eye`: N turned towards the viewer, L the unit vector towards Pl, V
 * towards the eye, R = 2(N·L)N − L; diffuse and specular only where N·L > 0, specular only
 * where R·V > 0 (clamped to 1 before the power); each channel clamped to 0..255.
 */
export function coursePhong(light: CourseLight, material: CourseMaterial, point: Vec3, normal: Vec3, eye: Vec3): Vec3 {
  const nn = unit(normal);
  const l = unit([light.position[0] - point[0], light.position[1] - point[1], light.position[2] - point[2]]);
  const v = unit([eye[0] - point[0], eye[1] - point[1], eye[2] - point[2]]);
  if (dot(nn, v) < 0) {
    // Stryker disable next-line EqualityOperator: c ≤ 3 also writes nn[3], which nothing reads
    for (let c = 0; c < 3; c++) nn[c] = -nn[c];
  }
  const nl = dot(nn, l);
  let diffuse = 0, specular = 0;
  if (nl > 0) {
    diffuse = nl;
    const r: Vec3 = [2 * nl * nn[0] - l[0], 2 * nl * nn[1] - l[1], 2 * nl * nn[2] - l[2]];
    const rv = Math.min(1, dot(r, v));
    if (rv > 0) specular = material.ks * rv ** material.n;
  }
  // Stryker disable next-line ArrayDeclaration: every element is written below
  const out: Vec3 = [0, 0, 0];
  for (let c = 0; c < 3; c++) {
    const i = material.ka * light.ambient[c] + light.intensity[c] * (material.kd * material.od[c] * diffuse + specular);
    out[c] = Math.min(255, Math.max(0, i));
  }
  return out;
}

function dot(a: Vec3, b: Vec3): number {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/** a / |a|, or a zero vector left as it is. */
function unit(a: Vec3): Vec3 {
  const length = Math.hypot(a[0], a[1], a[2]);
  // Stryker disable next-line ConditionalExpression,EqualityOperator,ArrayDeclaration: a zero vector (normal, or P at the light or the eye) is only dotted, and its NaN dots (0/0, or [] read) fail every > 0 and < 0 here as 0 does
  return length > 0 ? [a[0] / length, a[1] / length, a[2] / length] : [a[0], a[1], a[2]];
}
