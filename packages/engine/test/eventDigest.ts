/**
 * Test support: what a World showed, as exact bits, for comparisons bit for bit. `bits(v)` maps
 * every number in a value (arrays and plain objects too) to the hex of its float64 bits (+0 and -0
 * differ, NaN payloads too). `EventLog` records an advance's events: the first EVENTS_KEPT whole,
 * for a readable diff, and all of them through their count and two FNV-1a-style hashes of every
 * field's bits (a scene running into a Zeno state reports millions of events).
 */
import type { WorldEvent } from "../src/sim/types.js";

/** Numbers as their exact bits (+0 and -0, NaN payloads all distinct). */
export function bits(v: unknown): unknown {
  if (typeof v === "number") {
    const f = new Float64Array([v]);
    return `${new BigUint64Array(f.buffer)[0]?.toString(16)}`;
  }
  if (Array.isArray(v)) return v.map(bits);
  if (v && typeof v === "object")
    return Object.fromEntries(Object.entries(v).map(([key, x]) => [key, bits(x)]));
  return v;
}

/** Events kept whole for a readable diff; the rest are compared through a digest of their bits. */
const EVENTS_KEPT = 200;
const F64 = new Float64Array(1);
const U32 = new Uint32Array(F64.buffer);

/**
 * The events an advance reported: the first EVENTS_KEPT as copies, and how many there were with two
 * FNV-1a hashes of every field's bits (a scene that runs into a Zeno state reports millions of
 * events before the watch stops it: kept whole, their copies and comparison took a minute).
 */
export class EventLog {
  readonly first: WorldEvent[] = [];
  count = 0;
  private h1 = 0x811c9dc5;
  private h2 = 0x01000193;
  push(e: WorldEvent): void {
    if (this.first.length < EVENTS_KEPT) this.first.push({ ...e });
    this.count++;
    for (const v of Object.values(e)) {
      if (typeof v === "number") {
        F64[0] = v;
        this.mix(U32[0] as number);
        this.mix(U32[1] as number);
      } else if (typeof v === "string") for (let i = 0; i < v.length; i++) this.mix(v.charCodeAt(i));
      else this.mix(0xffffffff);
    }
  }
  private mix(x: number): void {
    this.h1 = Math.imul(this.h1 ^ x, 0x01000193) >>> 0;
    this.h2 = Math.imul(this.h2 ^ x ^ (this.h1 >>> 7), 0x85ebca6b) >>> 0;
  }
  /** What two runs must agree on. */
  summary(): unknown {
    return { first: this.first, count: this.count, digest: [this.h1, this.h2] };
  }
}
