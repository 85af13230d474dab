// Polygon → triangles. Ear clipping on the polygon projected onto the plane of its Newell
// normal, because a fan (what three.js's OBJLoader does) covers the outside of a concave
// face. Triangles keep the polygon's winding. Never throws, never loops forever.
import type { I32List } from './growable';

/** Containment tests allowed per polygon before the rest is fanned (a few tens of ms). */
const WORK_LIMIT = 30_000_000;

/**
 * Corners a face may have; a longer face is dropped with a warning (reader.ts). Triangulating
 * is linear past the work limit, but a face of n corners still becomes up to n − 2 triangles
 * drawn in every frame, and an `f` line spends about 2 bytes a corner where a file of
 * triangles spends 8 a triangle: unbounded, one 10 MB line is 5 million triangles that stop
 * the page. Real models' largest n-gons (a finely cut circle, a font outline) have
 * a few thousand corners; 65 536 leaves room for ten times that while bounding one line's
 * triangles by what a 0.5 MB file of triangles could hold anyway.
 */
export const MAX_FACE_CORNERS = 65_536;

let px = new Float64Array(64);
let py = new Float64Array(64);
let prev = new Int32Array(64);
let next = new Int32Array(64);
let state = new Uint8Array(64); // 0 convex, 1 reflex or flat, 2 clipped
let reflexList = new Int32Array(64);

/**
 * Appends the triangles of the polygon whose corners are `start .. start + count - 1` (global
 * corner numbers) to `out`; `corners` holds each corner's position index. Returns false
 * when the polygon was too large to ear-clip within the work limit and its rest was fanned.
 */
export function triangulate(
  positions: Float64Array, corners: Int32Array, start: number, count: number, out: I32List,
): boolean {
  if (count === 3) {
    out.push3(start, start + 1, start + 2);
    return true;
  }
  // Newell normal: robust for non-planar faces, its length is twice the area.
  let nx = 0, ny = 0, nz = 0;
  let j = 3 * corners[start + count - 1];
  for (let k = 0; k < count; k++) {
    const i = 3 * corners[start + k];
    const xi = positions[i], yi = positions[i + 1], zi = positions[i + 2];
    const xj = positions[j], yj = positions[j + 1], zj = positions[j + 2];
    nx += (yj - yi) * (zj + zi);
    ny += (zj - zi) * (xj + xi);
    nz += (xj - xi) * (yj + yi);
    j = i;
  }
  if (count === 4) {
    quad(positions, corners, start, nx, ny, nz, out);
    return true;
  }
  const ax = Math.abs(nx), ay = Math.abs(ny), az = Math.abs(nz);
  if (ax + ay + az === 0 || !Number.isFinite(ax + ay + az)) {
    fan(start, 0, count, out);
    return true;
  }
  project(positions, corners, start, count, ax, ay, az, nx, ny, nz);
  return earClip(start, count, out);
}

/** A quad has at most one reflex corner; the diagonal from it is the one that stays inside. */
function quad(p: Float64Array, corners: Int32Array, s: number, nx: number, ny: number, nz: number, out: I32List): void {
  const turn1 = turn(p, corners, s, 0, 1, 2, nx, ny, nz);
  const turn3 = turn(p, corners, s, 2, 3, 0, nx, ny, nz);
  if (turn1 < 0 || turn3 < 0) {
    out.push3(s + 1, s + 2, s + 3);
    out.push3(s + 1, s + 3, s);
  } else {
    out.push3(s, s + 1, s + 2);
    out.push3(s, s + 2, s + 3);
  }
}

/** (b − a) × (c − b) · n: negative where the polygon turns against its normal at b. */
function turn(p: Float64Array, corners: Int32Array, s: number, a: number, b: number, c: number, nx: number, ny: number, nz: number): number {
  const ia = 3 * corners[s + a], ib = 3 * corners[s + b], ic = 3 * corners[s + c];
  const ux = p[ib] - p[ia], uy = p[ib + 1] - p[ia + 1], uz = p[ib + 2] - p[ia + 2];
  const vx = p[ic] - p[ib], vy = p[ic + 1] - p[ib + 1], vz = p[ic + 2] - p[ib + 2];
  return (uy * vz - uz * vy) * nx + (uz * vx - ux * vz) * ny + (ux * vy - uy * vx) * nz;
}

/** Drops the normal's largest axis; mirrors when needed so the 2D polygon is counter-clockwise. */
function project(
  p: Float64Array, corners: Int32Array, s: number, count: number,
  ax: number, ay: number, az: number, nx: number, ny: number, nz: number,
): void {
  ensure(count);
  let u = 0, v = 1, flip = nz < 0; // drop z: (x, y)
  if (ax >= ay && ax >= az) {
    u = 1; v = 2; flip = nx < 0; // drop x: (y, z)
  } else if (ay >= az) {
    u = 2; v = 0; flip = ny < 0; // drop y: (z, x)
  }
  for (let k = 0; k < count; k++) {
    const i = 3 * corners[s + k];
    px[k] = flip ? -p[i + u] : p[i + u];
    py[k] = p[i + v];
  }
}

function earClip(s: number, count: number, out: I32List): boolean {
  let reflexCount = 0;
  for (let k = 0; k < count; k++) {
    prev[k] = k === 0 ? count - 1 : k - 1;
    next[k] = k === count - 1 ? 0 : k + 1;
  }
  for (let k = 0; k < count; k++) {
    state[k] = cross(prev[k], k, next[k]) > 0 ? 0 : 1;
    if (state[k] === 1) reflexList[reflexCount++] = k;
  }
  let remaining = count;
  let work = 0;
  let i = 0;
  let sinceLastEar = 0;
  while (remaining > 3) {
    // Convex from here on (no reflex corner left): a fan is exact and linear. Past the work
    // limit or with no ear at all (a self-intersecting polygon) a fan is the fallback.
    if (reflexCount === 0 || work > WORK_LIMIT || sinceLastEar > remaining) {
      fanRemaining(s, i, remaining, out);
      return work <= WORK_LIMIT;
    }
    const a = prev[i], c = next[i];
    let ear = state[i] === 0;
    if (ear) {
      let live = 0;
      for (let r = 0; r < reflexCount; r++) {
        const q = reflexList[r];
        if (state[q] !== 1) continue;
        reflexList[live++] = q; // compact: corners that turned convex or were clipped drop out
        // Stryker disable next-line LogicalOperator: inTriangle is false for a point on one of the triangle's corners anyway
        if (q === a || q === c || q === i) continue;
        if (inTriangle(a, i, c, q)) ear = false;
      }
      work += reflexCount;
      reflexCount = live;
    }
    if (!ear) {
      i = c;
      sinceLastEar++;
      continue;
    }
    out.push3(s + a, s + i, s + c);
    state[i] = 2;
    next[a] = c;
    prev[c] = a;
    remaining--;
    sinceLastEar = 0;
    // Only the two neighbours change shape; a reflex one may have become convex.
    if (state[a] === 1 && cross(prev[a], a, c) > 0) state[a] = 0;
    if (state[c] === 1 && cross(a, c, next[c]) > 0) state[c] = 0;
    i = a;
  }
  out.push3(s + prev[i], s + i, s + next[i]);
  return true;
}

function cross(a: number, b: number, c: number): number {
  return (px[b] - px[a]) * (py[c] - py[b]) - (py[b] - py[a]) * (px[c] - px[b]);
}

/** q inside or on triangle abc (counter-clockwise), unless q sits on one of its corners. */
function inTriangle(a: number, b: number, c: number, q: number): boolean {
  const x = px[q], y = py[q];
  if ((x === px[a] && y === py[a]) || (x === px[b] && y === py[b]) || (x === px[c] && y === py[c])) return false;
  return (px[b] - px[a]) * (y - py[a]) - (py[b] - py[a]) * (x - px[a]) >= 0
    && (px[c] - px[b]) * (y - py[b]) - (py[c] - py[b]) * (x - px[b]) >= 0
    && (px[a] - px[c]) * (y - py[c]) - (py[a] - py[c]) * (x - px[c]) >= 0;
}

/**
 * Removes the triangles from `first` (a triangle number) on whose corners are collinear or
 * repeated in space: they cover nothing and add nothing to the area-weighted normals, and a
 * polygon that walks back over its own corners (`f 1 2 3 4 1 2 3 4 …`) is mostly made of
 * them. One pass, order kept. Returns how many triangles from `first` remain.
 */
export function dropZeroArea(positions: Float64Array, corners: Int32Array, out: I32List, first: number): number {
  const t = out.data;
  let w = 3 * first;
  for (let r = 3 * first; r < out.length; r += 3) {
    const a = 3 * corners[t[r]], b = 3 * corners[t[r + 1]], c = 3 * corners[t[r + 2]];
    const ux = positions[b] - positions[a], uy = positions[b + 1] - positions[a + 1], uz = positions[b + 2] - positions[a + 2];
    const vx = positions[c] - positions[a], vy = positions[c + 1] - positions[a + 1], vz = positions[c + 2] - positions[a + 2];
    if (uy * vz - uz * vy === 0 && uz * vx - ux * vz === 0 && ux * vy - uy * vx === 0) continue;
    t[w] = t[r];
    t[w + 1] = t[r + 1];
    t[w + 2] = t[r + 2];
    w += 3;
  }
  out.length = w;
  return w / 3 - first;
}

function fan(s: number, from: number, count: number, out: I32List): void {
  for (let k = 1; k < count - 1; k++) out.push3(s + from, s + from + k, s + from + k + 1);
}

/** Fans what is left of the linked polygon from corner `i`. */
function fanRemaining(s: number, i: number, remaining: number, out: I32List): void {
  let b = next[i];
  for (let k = 0; k < remaining - 2; k++) {
    const c = next[b];
    out.push3(s + i, s + b, s + c);
    b = c;
  }
}

/** Scratch arrays shared by every call (single-threaded), grown to the largest polygon. */
function ensure(count: number): void {
  if (px.length >= count) return;
  // Stryker disable next-line ArithmeticOperator: growing to the count alone only reallocates more often
  const n = Math.max(count, px.length * 2);
  px = new Float64Array(n);
  py = new Float64Array(n);
  prev = new Int32Array(n);
  next = new Int32Array(n);
  state = new Uint8Array(n);
  reflexList = new Int32Array(n);
}
