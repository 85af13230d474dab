// Append-only typed arrays that double when full: no per-element objects, amortised O(1) pushes.
// Two classes, not one generic over the array type, on purpose: each keeps its `data` of one
// kind, so the parser's hot loops stay monomorphic in the JIT.

export class F64List {
  data: Float64Array;
  length = 0;

  constructor(capacity = 1024) {
    this.data = new Float64Array(capacity);
  }

  push(x: number): void {
    // Stryker disable next-line ArithmeticOperator: a full list's doubling is always more than one more
    if (this.length === this.data.length) this.grow(this.length + 1);
    this.data[this.length++] = x;
  }

  push3(x: number, y: number, z: number): void {
    // Stryker disable next-line EqualityOperator,ArithmeticOperator: growing one push early, or asking for less than the doubling gives, only moves when memory is taken
    if (this.length + 3 > this.data.length) this.grow(this.length + 3);
    const d = this.data;
    d[this.length] = x;
    d[this.length + 1] = y;
    d[this.length + 2] = z;
    this.length += 3;
  }

  private grow(needed: number): void {
    const next = new Float64Array(Math.max(needed, this.data.length * 2));
    next.set(this.data);
    this.data = next;
  }
}

export class I32List {
  data: Int32Array;
  length = 0;

  constructor(capacity = 1024) {
    this.data = new Int32Array(capacity);
  }

  push(x: number): void {
    // Stryker disable next-line ArithmeticOperator: a full list's doubling is always more than one more
    if (this.length === this.data.length) this.grow(this.length + 1);
    this.data[this.length++] = x;
  }

  push3(x: number, y: number, z: number): void {
    // Stryker disable next-line EqualityOperator,ArithmeticOperator: growing one push early, or asking for less than the doubling gives, only moves when memory is taken
    if (this.length + 3 > this.data.length) this.grow(this.length + 3);
    const d = this.data;
    d[this.length] = x;
    d[this.length + 1] = y;
    d[this.length + 2] = z;
    this.length += 3;
  }

  /** Room for `extra` more; returns `data` (written from `length` on, then `length` set by the caller). */
  reserve(extra: number): Int32Array {
    // Stryker disable next-line EqualityOperator: growing when exactly full changes only when memory is taken
    if (this.length + extra > this.data.length) this.grow(this.length + extra);
    return this.data;
  }

  clear(): void {
    this.length = 0;
  }

  private grow(needed: number): void {
    const next = new Int32Array(Math.max(needed, this.data.length * 2));
    next.set(this.data);
    this.data = next;
  }
}
