/**
 * Records: the compact event log of a Timeline, one fixed-size record per logged event in growable
 * typed arrays (structure of arrays):
 *   time f64 · kind u8 · a u32 · b u32 · new velocity of a (2 × f64) · new velocity of b (2 × f64)
 * = 49 bytes per record. `a` is a body number (see MotionTable), or the action's index for an action
 * record; `b` is the other body's number, or the line's / point's obstacle number. Positions are not
 * stored: they follow from the previous motion (closed form). Contact point, normal and impulse are
 * derived on demand from the motions before and after (see logEvents.ts).
 * Truncation keeps the arrays (it only moves `length`), so recomputing after a cut reuses memory.
 * dropBefore(n) forgets the first n records (Timeline.forgetBefore, forget.ts): the rest move to the
 * front, and the arrays shrink when at most a quarter of them would be used.
 *
 * Why this layout (rather than per-body motion segments): a segment per affected body would cost
 * 40 bytes per body per event (t0, x0, y0, vx, vy), 80 for a collision, over the 64-byte budget; and
 * storing the contact point, normal and impulse would add 40 more. A record of the new velocities is
 * enough, because the World itself starts every motion from the closed-form position at the event
 * (so replaying from a keyframe reproduces its positions bit for bit), and because the contact data
 * follow from the motions just before the event with the World's own formulas. Reading a state is
 * then "nearest keyframe + replay of at most K records" (keyframe.ts), and reading the log is the
 * same replay. Measured: 58 bytes per event with 1,000 bodies and 2·10^5 events, keyframes
 * included (keyframes hold no World clones: a restart rebuilds the World from a keyframe's motions).
 */

export const K_BODY_BODY = 0;
export const K_BODY_LINE = 1;
export const K_BODY_POINT = 2;
export const K_STOP = 3;
export const K_ACTION = 4;
export const KIND_NAMES = ["bodyBody", "bodyLine", "bodyPoint", "stop", "action"] as const;

/** Bytes of one record. */
const RECORD_BYTES = 8 + 1 + 4 + 4 + 4 * 8;
/** Capacity of a new log, and the least dropBefore shrinks to. */
const MIN_CAPACITY = 1024;

export class Records {
  length = 0;
  time: Float64Array;
  kind: Uint8Array;
  a: Uint32Array;
  b: Uint32Array;
  /** new velocities: [vax, vay, vbx, vby] per record */
  vel: Float64Array;

  constructor(capacity = MIN_CAPACITY) {
    this.time = new Float64Array(capacity);
    this.kind = new Uint8Array(capacity);
    this.a = new Uint32Array(capacity);
    this.b = new Uint32Array(capacity);
    this.vel = new Float64Array(capacity * 4);
  }

  get capacity(): number {
    return this.time.length;
  }

  private grow(): void {
    const cap = this.capacity * 2;
    const time = new Float64Array(cap);
    time.set(this.time);
    this.time = time;
    const kind = new Uint8Array(cap);
    kind.set(this.kind);
    this.kind = kind;
    const a = new Uint32Array(cap);
    a.set(this.a);
    this.a = a;
    const b = new Uint32Array(cap);
    b.set(this.b);
    this.b = b;
    const vel = new Float64Array(cap * 4);
    vel.set(this.vel);
    this.vel = vel;
  }

  push(
    time: number,
    kind: number,
    a: number,
    b: number,
    vax: number,
    vay: number,
    vbx: number,
    vby: number,
  ): void {
    if (this.length === this.capacity) this.grow();
    const i = this.length++;
    this.time[i] = time;
    this.kind[i] = kind;
    this.a[i] = a;
    this.b[i] = b;
    const o = 4 * i;
    this.vel[o] = vax;
    this.vel[o + 1] = vay;
    this.vel[o + 2] = vbx;
    this.vel[o + 3] = vby;
  }

  /** Drop records [0, n): record n becomes record 0. When what is left fills at most a quarter of
   *  the capacity, the arrays are reallocated at twice its size (at least MIN_CAPACITY), so a long
   *  run that forgets as it goes does not hold its peak for ever. */
  dropBefore(n: number): void {
    const left = this.length - n;
    const end = this.length;
    if (this.capacity > MIN_CAPACITY && 4 * left <= this.capacity) {
      const old = { time: this.time, kind: this.kind, a: this.a, b: this.b, vel: this.vel };
      const cap = Math.max(MIN_CAPACITY, 2 * left);
      this.time = new Float64Array(cap);
      this.kind = new Uint8Array(cap);
      this.a = new Uint32Array(cap);
      this.b = new Uint32Array(cap);
      this.vel = new Float64Array(cap * 4);
      this.time.set(old.time.subarray(n, end));
      this.kind.set(old.kind.subarray(n, end));
      this.a.set(old.a.subarray(n, end));
      this.b.set(old.b.subarray(n, end));
      this.vel.set(old.vel.subarray(4 * n, 4 * end));
    } else {
      this.time.copyWithin(0, n, end);
      this.kind.copyWithin(0, n, end);
      this.a.copyWithin(0, n, end);
      this.b.copyWithin(0, n, end);
      this.vel.copyWithin(0, 4 * n, 4 * end);
    }
    this.length = left;
  }

  /** Bytes of the records held (not of the spare capacity). */
  bytes(): number {
    return this.length * RECORD_BYTES;
  }

  /** First record index with time > t (binary search; records are in time order). */
  upperBound(t: number): number {
    let lo = 0;
    let hi = this.length;
    while (lo < hi) {
      const mid = (lo + hi) >>> 1;
      if ((this.time[mid] as number) <= t) lo = mid + 1;
      else hi = mid;
    }
    return lo;
  }

  /** First record index with time >= t. */
  lowerBound(t: number): number {
    let lo = 0;
    let hi = this.length;
    while (lo < hi) {
      const mid = (lo + hi) >>> 1;
      if ((this.time[mid] as number) < t) lo = mid + 1;
      else hi = mid;
    }
    return lo;
  }

  /** A copy of records [from, length) (to restore after a failed recompute). */
  saveTail(from: number): Records {
    const n = this.length - from;
    const r = new Records(Math.max(1, n));
    r.length = n;
    r.time.set(this.time.subarray(from, this.length));
    r.kind.set(this.kind.subarray(from, this.length));
    r.a.set(this.a.subarray(from, this.length));
    r.b.set(this.b.subarray(from, this.length));
    r.vel.set(this.vel.subarray(4 * from, 4 * this.length));
    return r;
  }

  /** Truncate to `from` records and append `tail` (undo of a cut). */
  restoreTail(from: number, tail: Records): void {
    this.length = from;
    for (let i = 0; i < tail.length; i++) {
      const o = 4 * i;
      this.push(
        tail.time[i] as number,
        tail.kind[i] as number,
        tail.a[i] as number,
        tail.b[i] as number,
        tail.vel[o] as number,
        tail.vel[o + 1] as number,
        tail.vel[o + 2] as number,
        tail.vel[o + 3] as number,
      );
    }
  }
}
