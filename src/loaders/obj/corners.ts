// The kept face corners' lists: per corner its position index, and its uv and normal index
// once any corner has one; and which elements bad lines left unusable.
import { I32List } from './growable';

export class CornerLists {
  readonly corners: I32List;
  /** Per corner: its uv index, −1 for none; null while no corner has one (then filled with −1 back to the first). */
  uvs: I32List | null = null;
  /** Per corner: its normal index, −1 for none; null while no corner has one. */
  normals: I32List | null = null;
  // A bad v/vt/vn keeps its slot (so later indices still mean the same element), flagged here.
  private readonly badLine = [new Map<number, number>(), new Map<number, number>(), new Map<number, number>()];
  private anyBad = false;

  constructor(capacity: number) {
    this.corners = new I32List(capacity);
  }

  /** Element `index` of list `kind` (v, vt, vn) is unusable, from a bad `line`. */
  markBad(kind: number, index: number, line: number): void {
    this.badLine[kind].set(index, line);
    this.anyBad = true;
  }

  /** One corner's OBJ indices resolved onto the lists, of `vCount` vertices and so on read so far; else the fault ('' for none). */
  add(v: number, t: number, nn: number, vCount: number, tCount: number, nCount: number): string {
    const vi = resolve(v, vCount), ti = t === 0 ? -1 : resolve(t, tCount), ni = nn === 0 ? -1 : resolve(nn, nCount);
    if (vi < 0) return `vertex index ${v} is outside the ${vCount} vertices read so far`;
    if (t !== 0 && ti < 0) return `texture coordinate index ${t} is outside the ${tCount} read so far`;
    if (nn !== 0 && ni < 0) return `normal index ${nn} is outside the ${nCount} read so far`;
    // Stryker disable next-line ConditionalExpression: with no bad element, unusable() finds none in its empty maps: ''
    if (this.anyBad) {
      const unusable = this.unusable(vi, ti, ni);
      if (unusable !== '') return unusable;
    }
    this.corners.push(vi);
    if (ti >= 0 || this.uvs !== null) (this.uvs ??= this.absentSoFar()).push(ti);
    if (ni >= 0 || this.normals !== null) (this.normals ??= this.absentSoFar()).push(ni);
    return '';
  }

  /**
   * A plain face's `count` corners, 3 raw indices each in `raw`, as `add` would put them, but
   * written straight into the lists; false, the lengths unchanged, for a corner `add` would
   * fault or one that starts the uv or normal list (`add` does those).
   */
  addPlain(raw: Int32Array, count: number, vCount: number, tCount: number, nCount: number): boolean {
    if (this.anyBad) return false;
    const { corners, uvs, normals } = this;
    const cd = corners.reserve(count), td = uvs?.reserve(count), nd = normals?.reserve(count);
    let at = corners.length;
    for (let k = 0; k < 3 * count; k += 3, at++) {
      const v = raw[k], t = raw[k + 1], n = raw[k + 2];
      const vi = resolve(v, vCount);
      if (vi < 0) return false;
      cd[at] = vi;
      if (td) td[at] = t === 0 ? -1 : resolve(t, tCount);
      else if (t !== 0) return false;
      if (nd) nd[at] = n === 0 ? -1 : resolve(n, nCount);
      else if (n !== 0) return false;
      if ((td && td[at] === -2) || (nd && nd[at] === -2)) return false;
    }
    corners.length = at;
    if (uvs) uvs.length = at;
    if (normals) normals.length = at;
    return true;
  }

  /** True while a corner of bare position index goes onto `corners` alone: no uv or normal list yet, no bad element. */
  positionsOnly(): boolean {
    return !this.anyBad && this.uvs === null && this.normals === null;
  }

  /** Forgets the corners from `start` on. */
  truncate(start: number): void {
    this.corners.length = start;
    if (this.uvs) this.uvs.length = start;
    if (this.normals) this.normals.length = start;
  }

  /** A list of −1 for each corner before the one just pushed: the first uv or normal of the file. */
  private absentSoFar(): I32List {
    const list = new I32List(this.corners.data.length);
    // Stryker disable next-line ArithmeticOperator: the 2 slots more filled are written by push before length lets them be read
    list.data.fill(-1, 0, this.corners.length - 1);
    list.length = this.corners.length - 1;
    return list;
  }

  /** Which element of the corner a bad line left unusable ('' for none). */
  private unusable(vi: number, ti: number, ni: number): string {
    const badLine = this.badLine;
    if (badLine[0].has(vi)) return `vertex ${vi + 1} (line ${badLine[0].get(vi)}) is not usable`;
    // Stryker disable next-line ConditionalExpression: markBad's indices count from 0: ti = −1 (no uv) is never bad
    if (ti >= 0 && badLine[1].has(ti)) return `texture coordinate ${ti + 1} (line ${badLine[1].get(ti)}) is not usable`;
    // Stryker disable next-line ConditionalExpression: the same (no normal −1 is ever bad)
    if (ni >= 0 && badLine[2].has(ni)) return `normal ${ni + 1} (line ${badLine[2].get(ni)}) is not usable`;
    return '';
  }
}

/** 1-based or negative (relative) OBJ index → 0-based, or −2 when outside 0 .. count − 1. */
export function resolve(index: number, count: number): number {
  // Stryker disable next-line EqualityOperator: index 0 gives −2 below (index !== 0) from either branch
  const i = index > 0 ? index - 1 : count + index;
  // Stryker disable next-line ConditionalExpression: index 0 takes i = count above, which i < count refuses too
  return index !== 0 && i >= 0 && i < count ? i : -2;
}
