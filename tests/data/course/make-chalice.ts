// A chalice-like surface of revolution as a course mesh `.byu` (docs/course-files.md#mesh-byu), generated at test
// time (nothing committed): one sheet from the pole under the foot, out along the foot, up
// the stem and the cup, over the rim and down the inside to the pole at the bottom of the cup.
// Faces are wound so that (b − a) × (c − a) points to the sheet's outer side.

/** (radius, height) along the profile; both ends on the axis. */
const PROFILE: [number, number][] = [
  [0, 0], [0.5, 0], [1, 0], [1, 0.08], [0.6, 0.14], [0.25, 0.22], [0.15, 0.4], [0.15, 0.9], [0.15, 1.2],
  [0.3, 1.3], [0.15, 1.4], [0.2, 1.6], [0.55, 1.75], [0.85, 2.0], [1, 2.4], [1.05, 2.8], [1, 2.84],
  [0.95, 2.8], [0.9, 2.42], [0.75, 2.07], [0.45, 1.85], [0, 1.78],
];

export interface Chalice {
  text: string;
  vertexCount: number;
  faceCount: number;
  /** (radius, height) of each ring (poles excluded), for tests that know where a ring lies. */
  rings: [number, number][];
  segments: number;
}

/**
 * `segments` vertices around each ring and `subdivisions` rings per profile segment:
 * the defaults give 41 rings, 2 + 41·64 = 2626 vertices and 2·64 + 2·40·64 = 5248 triangles.
 */
export function makeChalice(segments = 64, subdivisions = 2): Chalice {
  const rings: [number, number][] = [];
  for (let k = 0; k + 1 < PROFILE.length; k++) {
    const [r0, y0] = PROFILE[k], [r1, y1] = PROFILE[k + 1];
    for (let s = k === 0 ? 1 : 0; s < subdivisions; s++) {
      const t = s / subdivisions;
      rings.push([r0 + t * (r1 - r0), y0 + t * (y1 - y0)]);
    }
  }
  const lines: string[] = [];
  const [bottom, top] = [PROFILE[0], PROFILE[PROFILE.length - 1]];
  lines.push(`0 ${num(bottom[1])} 0`);
  for (const [r, y] of rings) {
    for (let s = 0; s < segments; s++) {
      const a = (2 * Math.PI * s) / segments;
      lines.push(`${num(r * Math.cos(a))} ${num(y)} ${num(r * Math.sin(a))}`);
    }
  }
  lines.push(`0 ${num(top[1])} 0`);
  const vertexCount = lines.length;
  const at = (ring: number, s: number): number => 2 + ring * segments + (s % segments); // 1-based
  const faces: string[] = [];
  for (let s = 0; s < segments; s++) faces.push(`1 ${at(0, s)} ${at(0, s + 1)}`);
  for (let k = 0; k + 1 < rings.length; k++) {
    for (let s = 0; s < segments; s++) {
      faces.push(`${at(k, s)} ${at(k + 1, s)} ${at(k + 1, s + 1)}`);
      faces.push(`${at(k, s)} ${at(k + 1, s + 1)} ${at(k, s + 1)}`);
    }
  }
  const last = rings.length - 1;
  for (let s = 0; s < segments; s++) faces.push(`${at(last, s)} ${vertexCount} ${at(last, s + 1)}`);
  const text = `${vertexCount} ${faces.length}\r\n${lines.join('\r\n')}\r\n${faces.join('\r\n')}\r\n`;
  return { text, vertexCount, faceCount: faces.length, rings, segments };
}

/** Seven significant digits, as a C program's `%g`-like output would give (exponents and all). */
function num(x: number): string {
  return Math.abs(x) < 1e-12 ? '0' : String(Number(x.toPrecision(7)));
}
