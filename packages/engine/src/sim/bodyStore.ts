/**
 * Storage of the discs of a World, indexed by slot. A slot holds one body's current motion (see
 * physics/motion.ts) as one record of 8 doubles in `mot` (t0, x0, y0, vx0, vy0, ax, ay, tEnd: a
 * pair test reads both bodies' motions, and one cache line each is fewer misses in large scenes
 * than eight arrays), and its properties and next predicted event in one array per field. Slots of
 * removed bodies are reused; `version` only ever grows, so a prediction made against an older
 * version of a partner is recognised as stale.
 */
import { idOrderKey } from "./idOrder.js";

/** Internal event kinds of a body's next event. Ranks give the canonical order of simultaneous events. */
export const EV_NONE = 0;
export const EV_CROSS = 1;
export const EV_STOP = 2;
export const EV_LINE = 3;
export const EV_POINT = 4;
export const EV_BODY = 5;

const F64_FIELDS = [
  "r",
  "m",
  "mu",
  "version",
  "evTime",
  "evOtherVersion",
  "crossTime",
  "boxMinX",
  "boxMinY",
  "boxMaxX",
  "boxMaxY",
  "idKey",
] as const;
const I32_FIELDS = ["evKind", "evOther", "evAux", "crossDir"] as const;

export class BodyStore {
  // Fields first set in the constructor are `declare`d: a field declared without a value is defined
  // as undefined first (ES2022 class fields), and V8 then no longer knows which array it holds and
  // checks the array's map at every read (docs/engine-throughput.md, session 24).
  declare capacity: number;
  count = 0;
  /** Id of each live slot; undefined for free slots. */
  ids: (string | undefined)[] = [];
  private free: number[] = [];
  /** Current motion, 8 doubles per slot (one cache line): t0, x0, y0, vx0, vy0, ax, ay, tEnd. */
  declare mot: Float64Array;
  declare r: Float64Array;
  declare m: Float64Array;
  declare mu: Float64Array;
  declare version: Float64Array;
  /** Next predicted interaction (collision or stop) and with whom. */
  declare evTime: Float64Array;
  declare evOtherVersion: Float64Array;
  declare evKind: Int32Array;
  declare evOther: Int32Array;
  /** Line events: 0 = the line itself, 1 = its first end point, 2 = its second end point. */
  declare evAux: Int32Array;
  /** Next cell crossing and its direction (0: -x, 1: +x, 2: -y, 3: +y). */
  declare crossTime: Float64Array;
  declare crossDir: Int32Array;
  /** Bounding box of the whole remaining path including the radius (infinite when unbounded). */
  declare boxMinX: Float64Array;
  declare boxMinY: Float64Array;
  declare boxMaxX: Float64Array;
  declare boxMaxY: Float64Array;
  /** Order key of each slot's id (idOrder.ts): the response orders a colliding pair without reading the strings. */
  declare idKey: Float64Array;

  constructor(capacity = 16) {
    this.capacity = capacity;
    this.mot = new Float64Array(capacity * 8);
    this.r = new Float64Array(capacity);
    this.m = new Float64Array(capacity);
    this.mu = new Float64Array(capacity);
    this.version = new Float64Array(capacity);
    this.evTime = new Float64Array(capacity);
    this.evOtherVersion = new Float64Array(capacity);
    this.evKind = new Int32Array(capacity);
    this.evOther = new Int32Array(capacity);
    this.evAux = new Int32Array(capacity);
    this.crossTime = new Float64Array(capacity);
    this.crossDir = new Int32Array(capacity);
    this.boxMinX = new Float64Array(capacity);
    this.boxMinY = new Float64Array(capacity);
    this.boxMaxX = new Float64Array(capacity);
    this.boxMaxY = new Float64Array(capacity);
    this.idKey = new Float64Array(capacity);
  }

  /** Take a free slot for a new body (growing the arrays when full). */
  allocate(id: string): number {
    const slot = this.free.length > 0 ? (this.free.pop() as number) : this.count++;
    if (slot >= this.capacity) this.grow(Math.max(16, this.capacity * 2));
    this.ids[slot] = id;
    this.idKey[slot] = idOrderKey(id);
    return slot;
  }

  release(slot: number): void {
    this.ids[slot] = undefined;
    this.version[slot] = (this.version[slot] as number) + 1;
    this.evKind[slot] = EV_NONE;
    this.free.push(slot);
  }

  /** Number of slots in use or free (iterate 0..slotCount and skip undefined ids). */
  get slotCount(): number {
    return this.count;
  }

  private grow(capacity: number): void {
    for (const f of F64_FIELDS) {
      const a = new Float64Array(capacity);
      a.set(this[f]);
      this[f] = a;
    }
    const mot = new Float64Array(capacity * 8);
    mot.set(this.mot);
    this.mot = mot;
    for (const f of I32_FIELDS) {
      const a = new Int32Array(capacity);
      a.set(this[f]);
      this[f] = a;
    }
    this.capacity = capacity;
  }

  clone(): BodyStore {
    // empty arrays first (not `capacity` of each, thrown away at once: a Timeline clones its World
    // at every apply, where that was most of the cost for a small scene)
    const s = new BodyStore(0);
    s.capacity = this.capacity;
    s.count = this.count;
    s.ids = this.ids.slice();
    s.free = this.free.slice();
    for (const f of F64_FIELDS) s[f] = this[f].slice();
    for (const f of I32_FIELDS) s[f] = this[f].slice();
    s.mot = this.mot.slice();
    return s;
  }
}
