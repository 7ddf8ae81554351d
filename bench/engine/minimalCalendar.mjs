/**
 * The calendar event queue of the benchmark's ceiling loop (minimalGas.mjs): items 0..n-1 (the
 * discs), each queued at most once under a double key, popped in (key, item index) order: exact
 * ties go to the smaller index, whatever the bucket width or history, so the WebAssembly twin
 * (bench/wasm/assembly/calendar.ts) pops the same sequence bit for bit. Keys must be >= the key of
 * the last item returned by first() (an event queue: nothing is scheduled in the past).
 *
 * The engine's design (packages/engine/src/sim/calendarQueue.ts), written again without its API:
 * buckets of adaptive width; entries of the current bucket or earlier in a small binary "front"
 * heap; the next ring-length buckets in a ring of doubly linked lists; later ones in an overflow
 * list; rebuilt with a width estimated from the queued keys when the entries loaded per bucket
 * drift from their target (when, and with what width: minimalCalendarWidth.mjs, as the engine's
 * calendarWidth.ts).
 *
 * A factory over typed arrays rather than a class, so that the loop holds its functions in
 * constants and V8 inlines the small ones (set, first, firstKey) into the hot path.
 */
import { rebuildDue, widthFor } from "./minimalCalendarWidth.mjs";

const INF = Number.POSITIVE_INFINITY;
/** Queue location of an item: not queued, in the front heap, in the overflow list (>= 0: ring bucket). */
const ABSENT = -1;
const FRONT = -2;
const OVERFLOW = -3;
/** Bucket numbers stay below this so that they are exact integers. */
const MAX_BUCKET = 2 ** 52;
/** A front this large after this many front operations per entry means the width is too large. */
const FRONT_CROWDED = 64;
const FRONT_OPS_PER_ENTRY = 4;

/**
 * An empty queue for items 0..n-1. set(s, k) queues or moves item s (k = +Infinity removes it);
 * first() is the item with the smallest (key, index), -1 when the queue is empty, and firstKey()
 * its key (valid after first() returned an item; first() does not remove it: the caller sets a
 * new key). keys() (each item's key, +Infinity if not queued) and stats() are for the tests.
 */
export function createCalendar(n) {
  const qkey = new Float64Array(n);
  const loc = new Int32Array(n).fill(ABSENT);
  const qnext = new Int32Array(n).fill(-1);
  const qprev = new Int32Array(n).fill(-1);
  const fpos = new Int32Array(n);
  const fslots = new Int32Array(n);
  const fkeys = new Float64Array(n);
  const allSlots = new Int32Array(n);
  const allKeys = new Float64Array(n);
  let fn = 0;
  let ring = new Int32Array(16).fill(-1);
  let mask = 15;
  let overHead = -1;
  let queued = 0;
  let ringCount = 0;
  let overCount = 0;
  let origin = 0;
  let bw = 1;
  let invW = 1;
  let cur = 0;
  let ringEnd = 16;
  let advances = 0;
  let loaded = 0;
  let frontOps = 0;
  let overScanned = 0;
  let rebuilds = 0;

  function up(i, s, k) {
    while (i > 0) {
      const p = (i - 1) >> 1;
      const pk = fkeys[p];
      const ps = fslots[p];
      if (!(k < pk || (k === pk && s < ps))) break;
      fkeys[i] = pk;
      fslots[i] = ps;
      fpos[ps] = i;
      i = p;
    }
    fkeys[i] = k;
    fslots[i] = s;
    fpos[s] = i;
  }

  function down(i, s, k) {
    for (;;) {
      let c = 2 * i + 1;
      if (c >= fn) break;
      let ck = fkeys[c];
      let cs = fslots[c];
      if (c + 1 < fn) {
        const k2 = fkeys[c + 1];
        const s2 = fslots[c + 1];
        if (k2 < ck || (k2 === ck && s2 < cs)) {
          c++;
          ck = k2;
          cs = s2;
        }
      }
      if (!(ck < k || (ck === k && cs < s))) break;
      fkeys[i] = ck;
      fslots[i] = cs;
      fpos[cs] = i;
      i = c;
    }
    fkeys[i] = k;
    fslots[i] = s;
    fpos[s] = i;
  }

  function frontUpdate(p, s, k) {
    const parent = (p - 1) >> 1;
    if (p > 0 && (k < fkeys[parent] || (k === fkeys[parent] && s < fslots[parent]))) up(p, s, k);
    else down(p, s, k);
  }

  function frontRemove(s) {
    const p = fpos[s];
    const last = --fn;
    if (p !== last) frontUpdate(p, fslots[last], fkeys[last]);
  }

  function frontCrowded() {
    return ++frontOps > FRONT_OPS_PER_ENTRY * queued + 64 && fn > FRONT_CROWDED;
  }

  /** Put a disc that is in no structure where its key belongs. */
  function place(s, k) {
    qkey[s] = k;
    const b = Math.floor((k - origin) * invW);
    if (b <= cur) {
      loc[s] = FRONT;
      up(fn++, s, k);
      if (frontCrowded()) rebuild();
    } else if (b < ringEnd) {
      const r = (b | 0) & mask;
      const h = ring[r];
      qnext[s] = h;
      qprev[s] = -1;
      if (h >= 0) qprev[h] = s;
      ring[r] = s;
      loc[s] = r;
      ringCount++;
    } else {
      qnext[s] = overHead;
      qprev[s] = -1;
      if (overHead >= 0) qprev[overHead] = s;
      overHead = s;
      loc[s] = OVERFLOW;
      overCount++;
    }
  }

  /** Take a disc out of its ring bucket (l >= 0) or the overflow list. */
  function qunlink(s, l) {
    const p = qprev[s];
    const q = qnext[s];
    if (p >= 0) qnext[p] = q;
    else if (l === OVERFLOW) overHead = q;
    else ring[l] = q;
    if (q >= 0) qprev[q] = p;
    if (l === OVERFLOW) overCount--;
    else ringCount--;
  }

  function qremove(s) {
    const l = loc[s];
    if (l === ABSENT) return;
    if (l === FRONT) frontRemove(s);
    else qunlink(s, l);
    loc[s] = ABSENT;
    queued--;
  }

  /** Queue item s at key k, moving it if already queued; k = +Infinity takes it out. */
  function set(s, k) {
    if (k === INF) {
      qremove(s);
      return;
    }
    const l = loc[s];
    if (l === FRONT) {
      if (Math.floor((k - origin) * invW) <= cur) {
        qkey[s] = k;
        frontUpdate(fpos[s], s, k);
        if (frontCrowded()) rebuild();
        return;
      }
      frontRemove(s);
    } else if (l !== ABSENT) qunlink(s, l);
    else queued++;
    place(s, k);
  }

  /** Move the window until the front holds something; false when the queue is empty. */
  function refill() {
    while (fn === 0) {
      if (ringCount === 0) {
        if (overCount === 0) return false;
        let m = INF;
        for (let s = overHead; s >= 0; s = qnext[s]) {
          const b = Math.floor((qkey[s] - origin) * invW);
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
      if (cur >= ringEnd - ((mask + 1) >> 1)) {
        if (rebuildDue(advances, loaded, overScanned, queued)) {
          rebuild();
          continue;
        }
        pullOverflow();
      }
      const r = (cur | 0) & mask;
      let s = ring[r];
      ring[r] = -1;
      while (s >= 0) {
        const after = qnext[s];
        ringCount--;
        loaded++;
        loc[s] = FRONT;
        up(fn++, s, qkey[s]);
        s = after;
      }
    }
    return true;
  }

  /** Extend the window to cur + ring length and move the overflow entries it covers into the ring. */
  function pullOverflow() {
    ringEnd = cur + mask + 1;
    overScanned += overCount;
    let s = overHead;
    while (s >= 0) {
      const after = qnext[s];
      if (Math.floor((qkey[s] - origin) * invW) < ringEnd) {
        qunlink(s, OVERFLOW);
        place(s, qkey[s]);
      }
      s = after;
    }
  }

  /** Re-place every entry with a width from the queued keys (widthFor) and a ring of about two buckets per entry. */
  function rebuild() {
    rebuilds++;
    let m = 0;
    for (let i = 0; i < fn; i++) allSlots[m++] = fslots[i];
    for (let r = 0; r <= mask; r++) for (let s = ring[r]; s >= 0; s = qnext[s]) allSlots[m++] = s;
    for (let s = overHead; s >= 0; s = qnext[s]) allSlots[m++] = s;
    let lo = m > 0 ? INF : 0;
    for (let i = 0; i < m; i++) {
      const k = qkey[allSlots[i]];
      allKeys[i] = k;
      if (k < lo) lo = k;
    }
    const nw = widthFor(allKeys, m, lo);
    if (nw > 0 && Number.isFinite(1 / nw)) {
      bw = nw;
      invW = 1 / nw;
    }
    let nb = 16;
    while (nb < 2 * m) nb *= 2;
    if (ring.length !== nb) ring = new Int32Array(nb);
    ring.fill(-1);
    mask = nb - 1;
    origin = lo;
    cur = 0;
    ringEnd = nb;
    fn = 0;
    overHead = -1;
    ringCount = 0;
    overCount = 0;
    advances = 0;
    loaded = 0;
    frontOps = 0;
    overScanned = 0;
    for (let i = 0; i < m; i++) place(allSlots[i], qkey[allSlots[i]]);
  }

  /** The item with the smallest (key, index), or -1 when nothing is queued. */
  function first() {
    if (fn === 0 && !refill()) return -1;
    return fslots[0];
  }

  /** The key of first() (call first() before). */
  function firstKey() {
    return fkeys[0];
  }

  function keys() {
    const out = new Float64Array(n);
    for (let s = 0; s < n; s++) out[s] = loc[s] === ABSENT ? INF : qkey[s];
    return out;
  }

  const stats = () => ({ width: bw, buckets: mask + 1, rebuilds });

  return { set, first, firstKey, keys, stats };
}
