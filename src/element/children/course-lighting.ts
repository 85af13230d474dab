// The course's `iluminacao.txt` (docs/course-files.md#lighting-file) in the scene's terms: its point light and its
// material mapped onto the scene's Blinn-Phong (docs/scene-model.md#lights). Pure.
//
// The course computes, on 0..255:  I = ka·Ia + Il ⊙ (kd·Od·(N·L) + ks·(R·V)^n)
// the scene computes, on 0..1:     I = Ka⊙Ia + Kd⊙Id·(N·L) + Ks⊙Is·(N·H)^shininess
// so, term by term: Ia/255 → Ia, Il/255 → Id and Is; ka → Ka = (ka, ka, ka) (the course's
// ambient has no Od), kd·Od → Kd, ks → Ks = (ks, ks, ks) (a white highlight), and n →
// shininess = 4n: Blinn's (N·H)^(4n) matches Phong's (R·V)^n near the highlight's peak (the
// half-angle is about half the reflection angle). Limits: only the peak matches — the lobes
// differ away from it, most at grazing light (Blinn's lobe is wider and stretched); the scene
// clamps the sum to 1 as the course clamps to 255, and the scene's lights add ambient once each.
import type { CourseLight, CourseMaterial } from '../../math/course-phong';
import type { Light, Vec3 } from '../../scene/scene';
import type { MtlValues } from './object-material';

/** The Blinn exponent standing for the course's Phong n. */
export const BLINN_PER_PHONG = 4;
const MAX_SHININESS = 10000;

export function courseMaterialValues(m: CourseMaterial): MtlValues {
  const grey = (k: number): Vec3 => [k, k, k];
  return {
    ambient: grey(m.ka),
    diffuse: [m.kd * m.od[0], m.kd * m.od[1], m.kd * m.od[2]],
    specular: grey(m.ks),
    shininess: Math.min(MAX_SHININESS, BLINN_PER_PHONG * m.n),
  };
}

/** A point light at Pl: Ia/255, and Il/255 as both Id and Is. */
export function courseLight(l: CourseLight): Light {
  const scale = (v: Vec3): Vec3 => [v[0] / 255, v[1] / 255, v[2] / 255];
  return { kind: 'point', vector: [...l.position], ambient: scale(l.ambient), diffuse: scale(l.intensity), specular: scale(l.intensity) };
}
