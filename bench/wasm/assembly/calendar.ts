/**
 * The calendar event queue of the WebAssembly ceiling loop (minimalGas.ts), the port of
 * bench/engine/minimalCalendar.mjs: the same buckets, front heap, ring, overflow list, width
 * estimates and rebuilds, the same arithmetic in the same order, so items come out in the same
 * (key, item index) order bit for bit. Items 0..n-1, each queued at most once; keys must be >= the
 * key of the last item returned by first(). Module state (one queue per instance); the loop
 * imports reset, setKey, first and firstKey, which Binaryen inlines where they are small. When to
 * rebuild and with what width: calendarWidth.ts.
 */
import { rebuildDue, widthFor } from "./calendarWidth";

const INF: f64 = Infinity;
const ABSENT: i32 = -1;
const FRONT: i32 = -2;
const OVERFLOW: i32 = -3;
const MAX_BUCKET: f64 = 4503599627370496; // 2^52
const FRONT_CROWDED: i32 = 64;
const FRONT_OPS_PER_ENTRY: i32 = 4;
let qkey: StaticArray<f64> = new StaticArray<f64>(0);
let loc: StaticArray<i32> = new StaticArray<i32>(0);
let qnext: StaticArray<i32> = new StaticArray<i32>(0);
let qprev: StaticArray<i32> = new StaticArray<i32>(0);
let fpos: StaticArray<i32> = new StaticArray<i32>(0);
let fslots: StaticArray<i32> = new StaticArray<i32>(0);
let fkeys: StaticArray<f64> = new StaticArray<f64>(0);
let allSlots: StaticArray<i32> = new StaticArray<i32>(0);
let allKeys: StaticArray<f64> = new StaticArray<f64>(0);
let fn: i32 = 0;
let ring: StaticArray<i32> = new StaticArray<i32>(0);
let mask: i32 = 15;
let overHead: i32 = -1;
let queued: i32 = 0;
let ringCount: i32 = 0;
let overCount: i32 = 0;
let origin: f64 = 0;
let invW: f64 = 1;
let cur: f64 = 0;
let ringEnd: f64 = 16;
let advances: i32 = 0;
let loaded: i32 = 0;
let frontOps: i32 = 0;
let overScanned: i32 = 0;

/** Empties the queue and sizes it for items 0..count-1. */
export function reset(count: i32): void {
  qkey = new StaticArray<f64>(count);
  loc = new StaticArray<i32>(count);
  qnext = new StaticArray<i32>(count);
  qprev = new StaticArray<i32>(count);
  fpos = new StaticArray<i32>(count);
  fslots = new StaticArray<i32>(count);
  fkeys = new StaticArray<f64>(count);
  allSlots = new StaticArray<i32>(count);
  allKeys = new StaticArray<f64>(count);
  for (let i = 0; i < count; i++) {
    unchecked((loc[i] = ABSENT));
    unchecked((qnext[i] = -1));
    unchecked((qprev[i] = -1));
  }
  ring = new StaticArray<i32>(16);
  for (let i = 0; i < 16; i++) unchecked((ring[i] = -1));
  fn = 0;
  mask = 15;
  overHead = -1;
  queued = 0;
  ringCount = 0;
  overCount = 0;
  origin = 0;
  invW = 1;
  cur = 0;
  ringEnd = 16;
  advances = 0;
  loaded = 0;
  frontOps = 0;
  overScanned = 0;
}
function up(i: i32, s: i32, k: f64): void {
  while (i > 0) {
    const p = (i - 1) >> 1;
    const pk = unchecked(fkeys[p]);
    const ps = unchecked(fslots[p]);
    if (!(k < pk || (k == pk && s < ps))) break;
    unchecked((fkeys[i] = pk));
    unchecked((fslots[i] = ps));
    unchecked((fpos[ps] = i));
    i = p;
  }
  unchecked((fkeys[i] = k));
  unchecked((fslots[i] = s));
  unchecked((fpos[s] = i));
}
function down(i: i32, s: i32, k: f64): void {
  for (;;) {
    let c = 2 * i + 1;
    if (c >= fn) break;
    let ck = unchecked(fkeys[c]);
    let cs = unchecked(fslots[c]);
    if (c + 1 < fn) {
      const k2 = unchecked(fkeys[c + 1]);
      const s2 = unchecked(fslots[c + 1]);
      if (k2 < ck || (k2 == ck && s2 < cs)) {
        c++;
        ck = k2;
        cs = s2;
      }
    }
    if (!(ck < k || (ck == k && cs < s))) break;
    unchecked((fkeys[i] = ck));
    unchecked((fslots[i] = cs));
    unchecked((fpos[cs] = i));
    i = c;
  }
  unchecked((fkeys[i] = k));
  unchecked((fslots[i] = s));
  unchecked((fpos[s] = i));
}
function frontUpdate(p: i32, s: i32, k: f64): void {
  const parent = (p - 1) >> 1;
  if (
    p > 0 &&
    (k < unchecked(fkeys[parent]) || (k == unchecked(fkeys[parent]) && s < unchecked(fslots[parent])))
  )
    up(p, s, k);
  else down(p, s, k);
}
function frontRemove(s: i32): void {
  const p = unchecked(fpos[s]);
  fn--;
  const last = fn;
  if (p != last) frontUpdate(p, unchecked(fslots[last]), unchecked(fkeys[last]));
}
function frontCrowded(): bool {
  frontOps++;
  return frontOps > FRONT_OPS_PER_ENTRY * queued + 64 && fn > FRONT_CROWDED;
}
function bucketOf(k: f64): f64 {
  return Math.floor((k - origin) * invW);
}
function place(s: i32, k: f64): void {
  unchecked((qkey[s] = k));
  const b = bucketOf(k);
  if (b <= cur) {
    unchecked((loc[s] = FRONT));
    up(fn, s, k);
    fn++;
    if (frontCrowded()) rebuild();
  } else if (b < ringEnd) {
    const r = <i32>(<i64>b) & mask;
    const h = unchecked(ring[r]);
    unchecked((qnext[s] = h));
    unchecked((qprev[s] = -1));
    if (h >= 0) unchecked((qprev[h] = s));
    unchecked((ring[r] = s));
    unchecked((loc[s] = r));
    ringCount++;
  } else {
    unchecked((qnext[s] = overHead));
    unchecked((qprev[s] = -1));
    if (overHead >= 0) unchecked((qprev[overHead] = s));
    overHead = s;
    unchecked((loc[s] = OVERFLOW));
    overCount++;
  }
}
function qunlink(s: i32, l: i32): void {
  const p = unchecked(qprev[s]);
  const q = unchecked(qnext[s]);
  if (p >= 0) unchecked((qnext[p] = q));
  else if (l == OVERFLOW) overHead = q;
  else unchecked((ring[l] = q));
  if (q >= 0) unchecked((qprev[q] = p));
  if (l == OVERFLOW) overCount--;
  else ringCount--;
}
function qremove(s: i32): void {
  const l = unchecked(loc[s]);
  if (l == ABSENT) return;
  if (l == FRONT) frontRemove(s);
  else qunlink(s, l);
  unchecked((loc[s] = ABSENT));
  queued--;
}
/** Queue item s at key k, moving it if already queued; k = +Infinity takes it out. */
export function setKey(s: i32, k: f64): void {
  if (k == INF) {
    qremove(s);
    return;
  }
  const l = unchecked(loc[s]);
  if (l == FRONT) {
    if (bucketOf(k) <= cur) {
      unchecked((qkey[s] = k));
      frontUpdate(unchecked(fpos[s]), s, k);
      if (frontCrowded()) rebuild();
      return;
    }
    frontRemove(s);
  } else if (l != ABSENT) qunlink(s, l);
  else queued++;
  place(s, k);
}
function refill(): bool {
  while (fn == 0) {
    if (ringCount == 0) {
      if (overCount == 0) return false;
      let m = INF;
      for (let s = overHead; s >= 0; s = unchecked(qnext[s])) {
        const b = bucketOf(unchecked(qkey[s]));
        if (b < m) m = b;
      }
      overScanned += overCount;
      if (!(m < MAX_BUCKET)) {
        rebuild();
        continue;
      }
      cur = m - 1;
      pullOverflow();
    }
    cur++;
    advances++;
    if (cur >= ringEnd - <f64>((mask + 1) >> 1)) {
      if (rebuildDue(advances, loaded, overScanned, queued)) {
        rebuild();
        continue;
      }
      pullOverflow();
    }
    const r = <i32>(<i64>cur) & mask;
    let s = unchecked(ring[r]);
    unchecked((ring[r] = -1));
    while (s >= 0) {
      const after = unchecked(qnext[s]);
      ringCount--;
      loaded++;
      unchecked((loc[s] = FRONT));
      up(fn, s, unchecked(qkey[s]));
      fn++;
      s = after;
    }
  }
  return true;
}
function pullOverflow(): void {
  ringEnd = cur + <f64>(mask + 1);
  overScanned += overCount;
  let s = overHead;
  while (s >= 0) {
    const after = unchecked(qnext[s]);
    if (bucketOf(unchecked(qkey[s])) < ringEnd) {
      qunlink(s, OVERFLOW);
      place(s, unchecked(qkey[s]));
    }
    s = after;
  }
}
function rebuild(): void {
  let m = 0;
  for (let i = 0; i < fn; i++) unchecked((allSlots[m++] = unchecked(fslots[i])));
  for (let r = 0; r <= mask; r++)
    for (let s = unchecked(ring[r]); s >= 0; s = unchecked(qnext[s])) unchecked((allSlots[m++] = s));
  for (let s = overHead; s >= 0; s = unchecked(qnext[s])) unchecked((allSlots[m++] = s));
  let lo: f64 = m > 0 ? INF : 0;
  for (let i = 0; i < m; i++) {
    const k = unchecked(qkey[unchecked(allSlots[i])]);
    unchecked((allKeys[i] = k));
    if (k < lo) lo = k;
  }
  const nw = widthFor(allKeys, m, lo);
  if (nw > 0 && 1 / nw < INF) {
    invW = 1 / nw;
  }
  let nb = 16;
  while (nb < 2 * m) nb *= 2;
  if (ring.length != nb) ring = new StaticArray<i32>(nb);
  for (let r = 0; r < nb; r++) unchecked((ring[r] = -1));
  mask = nb - 1;
  origin = lo;
  cur = 0;
  ringEnd = <f64>nb;
  fn = 0;
  overHead = -1;
  ringCount = 0;
  overCount = 0;
  advances = 0;
  loaded = 0;
  frontOps = 0;
  overScanned = 0;
  for (let i = 0; i < m; i++) place(unchecked(allSlots[i]), unchecked(qkey[unchecked(allSlots[i])]));
}
/** The item with the smallest (key, index), or -1 when nothing is queued. */
export function first(): i32 {
  if (fn == 0 && !refill()) return -1;
  return unchecked(fslots[0]);
}
/** The key of first() (call first() before). */
export function firstKey(): f64 {
  return unchecked(fkeys[0]);
}
