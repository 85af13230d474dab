// Surface codes: small integers naming what a sample saw, the digits of its key (sample-tracer.ts).
import type { Scene } from '../scene/scene';
import { SURFACE_NONE } from './surface-hit';

/** Codes above this are shared, so keys (≤ 2·base³) stay within an Int32. */
const MAX_OBJECT_CODE = 1000;

/**
 * 0 is nothing; objects in scene order take 1.. (a box six, one per face in BOX_FACES order,
 * so creases are edges; anything else one); the glass takes the next. The default scene gets
 * cube faces 1..6, sphere 7, glass 8 and base 9, as the analytic reference always had.
 */
export class SurfaceCodes {
  /** Per object, its first code. */
  readonly first: Int32Array;
  readonly glass: number;
  /** Codes per key digit. */
  readonly base: number;
  /** Per code, the object index (−1 for none and the glass). */
  private readonly objectOf: Int32Array;

  constructor(scene: Scene) {
    this.first = new Int32Array(scene.objects.length);
    let next = 1;
    // Stryker disable next-line ArrayDeclaration, UnaryOperator: objectOf[0] is never read (code ≤ 0 answers −1)
    const owner: number[] = [-1];
    scene.objects.forEach((object, i) => {
      const count = object.geometry.kind === 'box' ? 6 : 1;
      // Stryker disable next-line EqualityOperator: when the last code is exactly MAX_OBJECT_CODE both branches set next to the same value
      if (next + count - 1 > MAX_OBJECT_CODE) next = MAX_OBJECT_CODE - count + 1;
      this.first[i] = next;
      // Stryker disable next-line EqualityOperator: owner[next + count] is always written again, by the next object or the glass
      for (let k = 0; k < count; k++) owner[next + k] = i;
      next += count;
    });
    this.glass = next;
    owner[next] = -1;
    this.base = next + 1;
    // Stryker disable next-line UnaryOperator: owner has no holes (codes 0..glass are all written), so the −1 is never used
    this.objectOf = Int32Array.from(owner, (x) => x ?? -1);
  }

  /** The object a code names (−1: nothing or the glass; where codes are shared, the last object). */
  objectOfCode(code: number): number {
    return code > SURFACE_NONE && code < this.objectOf.length ? this.objectOf[code] : -1;
  }

  /** The key's three digits: primary surface, what lies behind it, what the glass reflects. */
  digits(key: number): [number, number, number] {
    const b = this.base;
    const k = key % (b * b * b);
    return [k % b, Math.floor(k / b) % b, Math.floor(k / (b * b)) % b];
  }
}
