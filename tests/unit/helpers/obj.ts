// Small readers over an ObjResult for the loader tests: vertices, triangles, areas.
import type { ObjResult } from '../../../src/loaders/obj';

export type V3 = [number, number, number];

export function position(r: ObjResult, i: number): V3 {
  return [r.positions[3 * i], r.positions[3 * i + 1], r.positions[3 * i + 2]];
}

export function normal(r: ObjResult, i: number): V3 {
  return [r.normals[3 * i], r.normals[3 * i + 1], r.normals[3 * i + 2]];
}

/** Every triangle as its three corner positions. */
export function triangles(r: ObjResult): V3[][] {
  const out: V3[][] = [];
  for (let t = 0; t < r.indices.length; t += 3) {
    out.push([position(r, r.indices[t]), position(r, r.indices[t + 1]), position(r, r.indices[t + 2])]);
  }
  return out;
}

export function sub(a: V3, b: V3): V3 {
  return [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
}
export function cross(a: V3, b: V3): V3 {
  return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
}
export function dot(a: V3, b: V3): number {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
export function length(a: V3): number {
  return Math.hypot(a[0], a[1], a[2]);
}
export function unit(a: V3): V3 {
  const l = length(a);
  return [a[0] / l, a[1] / l, a[2] / l];
}

/** Twice the signed area vector of a triangle (its unnormalised normal). */
export function triangleNormal(t: V3[]): V3 {
  return cross(sub(t[1], t[0]), sub(t[2], t[0]));
}

/** Shoelace area of a 2D polygon (positive when counter-clockwise). */
export function polygonArea(p: [number, number][]): number {
  let a = 0;
  for (let i = 0; i < p.length; i++) {
    const [x0, y0] = p[i];
    const [x1, y1] = p[(i + 1) % p.length];
    a += x0 * y1 - x1 * y0;
  }
  return a / 2;
}

/** Even-odd ray crossing; points on the boundary are not asked about by the tests. */
export function insidePolygon(q: [number, number], p: [number, number][]): boolean {
  let inside = false;
  for (let i = 0, j = p.length - 1; i < p.length; j = i++) {
    const [xi, yi] = p[i];
    const [xj, yj] = p[j];
    if (yi > q[1] !== yj > q[1] && q[0] < ((xj - xi) * (q[1] - yi)) / (yj - yi) + xi) inside = !inside;
  }
  return inside;
}

/** `n` points of a star, alternating outer radius 1 and inner radius `inner`, counter-clockwise. */
export function star(points: number, inner: number): [number, number][] {
  const out: [number, number][] = [];
  for (let k = 0; k < 2 * points; k++) {
    const a = Math.PI / 2 + (k * Math.PI) / points;
    const r = k % 2 === 0 ? 1 : inner;
    out.push([r * Math.cos(a), r * Math.sin(a)]);
  }
  return out;
}

/** OBJ text for one polygon: its vertices, then one `f` line using them all. */
export function polygonObj(points: V3[]): string {
  const vs = points.map((p) => `v ${p[0]} ${p[1]} ${p[2]}`).join('\n');
  return `${vs}\nf ${points.map((_, i) => i + 1).join(' ')}\n`;
}
