/**
 * A ceiling for the dilute-gas rows: the same event-driven algorithm as the engine (uniform grid
 * with cell-crossing events, a calendar queue of one next event per disc, stale partners
 * re-predicted when popped, exact closed-form collision times) stripped of everything the product
 * needs: no API, no ids, no friction or gravity, no lines other than the four box walls, no
 * obstacles, no event reports, no validation, equal masses and radii only. It answers one
 * question: how many events per second plain JavaScript reaches on this machine with this
 * algorithm. It is a benchmark baseline, not part of the engine, and nothing depends on its results
 * beyond the report.
 *
 * The queue is the engine's design (packages/engine/src/sim/calendarQueue.ts), written again here
 * without its API: buckets of adaptive width; entries of the current bucket or earlier in a small
 * binary "front" heap; the next ring-length buckets in a ring of doubly linked lists; later ones in
 * an overflow list; rebuilt with a width estimated from the queued keys when the entries loaded per
 * bucket drift from CALENDAR_BUCKET_TARGET by more than CALENDAR_REBUILD_FACTOR (values copied from
 * the engine's tolerances). Pops come in (key, disc index) order: exact ties go to the smaller
 * index, whatever the width or history, so the WebAssembly twin (bench/wasm/assembly/minimalGas.ts)
 * pops the same sequence bit for bit.
 *
 * Record layout per disc (REC doubles): 0 t0, 1 x0, 2 y0, 3 vx, 4 vy, 5 motion version,
 * 6 event time, 7 crossing time, 8 event kind (0 none, 1 disc, 2 wall), 9 partner or wall,
 * 10 partner version at prediction, 11 crossing direction (0 -x, 1 +x, 2 -y, 3 +y).
 */
const REC = 16;
const INF = Number.POSITIVE_INFINITY;
/** Copies of packages/engine/src/tolerances.ts (the bench does not import engine internals). */
const CALENDAR_BUCKET_TARGET = 2;
const CALENDAR_REBUILD_FACTOR = 4;
/** Queue location of a disc: not queued, in the front heap, in the overflow list (>= 0: ring bucket). */
const ABSENT = -1;
const FRONT = -2;
const OVERFLOW = -3;
/** Bucket numbers stay below this so that they are exact integers. */
const MAX_BUCKET = 2 ** 52;
/** A front this large after this many front operations per entry means the width is too large. */
const FRONT_CROWDED = 64;
const FRONT_OPS_PER_ENTRY = 4;

/**
 * Builds the gas of `scene` (from bench/scenes/gas.mjs). Returns advance(count) (count collisions,
 * disc or wall, counted like the engine's events), time(), state(), and for the tests queueKeys()
 * (each disc's queued key, +Infinity if not queued) and queueStats(). `onPop(disc, key)`, if given,
 * is called for every item popped, before it is processed (tests only).
 */
export function createMinimalGas(scene, onPop = null) {
  const n = scene.bodies.length;
  const R = scene.bodies[0].r;
  const D = 2 * R;
  const { x0: bx0, y0: by0, x1: bx1, y1: by1 } = scene.box;
  const side = bx1 - bx0;
  const nx = Math.max(1, Math.floor(side / Math.max(D * (1 + 1e-6), Math.sqrt((side * side) / (3 * n)))));
  const w = side / nx;
  const ny = nx;
  const rec = new Float64Array(n * REC);
  const head = new Int32Array(nx * ny).fill(-1);
  const next = new Int32Array(n).fill(-1);
  const prev = new Int32Array(n).fill(-1);
  const cellOf = new Int32Array(n);
  let now = 0;

  // ---- calendar queue: one entry per disc, keyed by min(event time, crossing time) ----------
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

  /** Queue disc s at its next event or crossing, whichever is earlier (never popped if infinite). */
  function queue(s) {
    const i = s * REC;
    const k = Math.min(rec[i + 6], rec[i + 7]);
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
        if (adaptDue()) {
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

  function adaptDue() {
    if (advances < 64) return false;
    const perBucket = loaded / advances;
    return (
      perBucket > CALENDAR_BUCKET_TARGET * CALENDAR_REBUILD_FACTOR ||
      perBucket < CALENDAR_BUCKET_TARGET / CALENDAR_REBUILD_FACTOR ||
      overScanned > 8 * queued + 1024
    );
  }

  /** The k-th smallest (from 0) of a[0..m), reordering a (Hoare selection). */
  function select(a, m, k) {
    let lo = 0;
    let hi = m - 1;
    while (lo < hi) {
      const p = a[(lo + hi) >> 1];
      let i = lo;
      let j = hi;
      while (i <= j) {
        while (a[i] < p) i++;
        while (a[j] > p) j--;
        if (i <= j) {
          const t = a[i];
          a[i] = a[j];
          a[j] = t;
          i++;
          j--;
        }
      }
      if (k <= j) hi = j;
      else if (k >= i) lo = i;
      else break;
    }
    return a[k];
  }

  /**
   * Re-place every entry with a width from the queued keys (CALENDAR_BUCKET_TARGET entries per
   * bucket if the keys are spread like an exponential: median spread 0.69 tau) and a ring of
   * about two buckets per entry.
   */
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
    const spread = m > 0 ? select(allKeys, m, m >> 1) - lo : 0;
    const nw = (CALENDAR_BUCKET_TARGET * spread) / (0.69 * Math.max(1, m));
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

  // ---- grid and physics ---------------------------------------------------------------------

  function link(s, c) {
    const h = head[c];
    next[s] = h;
    prev[s] = -1;
    if (h >= 0) prev[h] = s;
    head[c] = s;
    cellOf[s] = c;
  }

  function unlink(s) {
    const p = prev[s];
    const q = next[s];
    if (p >= 0) next[p] = q;
    else head[cellOf[s]] = q;
    if (q >= 0) prev[q] = p;
  }

  /** Contact time of discs s and o (uniform motions, from the later start), or +Infinity. */
  function pairTime(s, o) {
    const i = s * REC;
    const j = o * REC;
    const ts = rec[i];
    const to = rec[j];
    const tb = Math.max(ts, to);
    const dx = rec[j + 1] + rec[j + 3] * (tb - to) - (rec[i + 1] + rec[i + 3] * (tb - ts));
    const dy = rec[j + 2] + rec[j + 4] * (tb - to) - (rec[i + 2] + rec[i + 4] * (tb - ts));
    const ux = rec[j + 3] - rec[i + 3];
    const uy = rec[j + 4] - rec[i + 4];
    const b = dx * ux + dy * uy;
    if (b >= 0) return INF;
    const c = dx * dx + dy * dy - D * D;
    const disc = b * b - (ux * ux + uy * uy) * c;
    if (disc < 0) return INF;
    const t = tb + c / (-b + Math.sqrt(disc));
    return Math.max(t, now);
  }

  function offer(s, t, kind, other) {
    const i = s * REC;
    if (t >= rec[i + 6]) return;
    rec[i + 6] = t;
    rec[i + 8] = kind;
    rec[i + 9] = other;
    rec[i + 10] = kind === 1 ? rec[other * REC + 5] : 0;
  }

  function scan(s, c) {
    for (let o = head[c]; o >= 0; o = next[o]) {
      if (o === s) continue;
      const t = pairTime(s, o);
      if (t < INF) offer(s, t, 1, o);
    }
  }

  function wallTime(s) {
    const i = s * REC;
    const vx = rec[i + 3];
    const vy = rec[i + 4];
    let t = INF;
    let wall = -1;
    if (vx > 0) {
      t = rec[i] + (bx1 - R - rec[i + 1]) / vx;
      wall = 1;
    } else if (vx < 0) {
      t = rec[i] + (bx0 + R - rec[i + 1]) / vx;
      wall = 0;
    }
    if (vy > 0) {
      const ty = rec[i] + (by1 - R - rec[i + 2]) / vy;
      if (ty < t) {
        t = ty;
        wall = 3;
      }
    } else if (vy < 0) {
      const ty = rec[i] + (by0 + R - rec[i + 2]) / vy;
      if (ty < t) {
        t = ty;
        wall = 2;
      }
    }
    if (wall >= 0) offer(s, Math.max(t, now), 2, wall);
  }

  function crossing(s) {
    const i = s * REC;
    const c = cellOf[s];
    const cx = c % nx;
    const cy = (c - cx) / nx;
    const vx = rec[i + 3];
    const vy = rec[i + 4];
    let t = INF;
    let dir = -1;
    if (vx > 0 && cx < nx - 1) {
      t = rec[i] + (bx0 + (cx + 1) * w - rec[i + 1]) / vx;
      dir = 1;
    } else if (vx < 0 && cx > 0) {
      t = rec[i] + (bx0 + cx * w - rec[i + 1]) / vx;
      dir = 0;
    }
    if (vy > 0 && cy < ny - 1) {
      const ty = rec[i] + (by0 + (cy + 1) * w - rec[i + 2]) / vy;
      if (ty < t) {
        t = ty;
        dir = 3;
      }
    } else if (vy < 0 && cy > 0) {
      const ty = rec[i] + (by0 + cy * w - rec[i + 2]) / vy;
      if (ty < t) {
        t = ty;
        dir = 2;
      }
    }
    rec[i + 11] = dir;
    rec[i + 7] = Math.max(t, now);
  }

  function predict(s) {
    const i = s * REC;
    rec[i + 6] = INF;
    rec[i + 8] = 0;
    const c = cellOf[s];
    const cx = c % nx;
    const cy = (c - cx) / nx;
    for (let y = cy - 1; y <= cy + 1; y++) {
      if (y < 0 || y >= ny) continue;
      for (let x = cx - 1; x <= cx + 1; x++) if (x >= 0 && x < nx) scan(s, y * nx + x);
    }
    wallTime(s);
    crossing(s);
    queue(s);
  }

  function setMotion(s, t, vx, vy) {
    const i = s * REC;
    const dt = t - rec[i];
    rec[i + 1] += rec[i + 3] * dt;
    rec[i + 2] += rec[i + 4] * dt;
    rec[i] = t;
    rec[i + 3] = vx;
    rec[i + 4] = vy;
    rec[i + 5] += 1;
  }

  function cross(s) {
    const i = s * REC;
    const c = cellOf[s];
    let cx = c % nx;
    let cy = (c - cx) / nx;
    const dir = rec[i + 11];
    if (dir === 0) cx--;
    else if (dir === 1) cx++;
    else if (dir === 2) cy--;
    else cy++;
    unlink(s);
    link(s, cy * nx + cx);
    if (dir <= 1) {
      const x = dir === 0 ? cx - 1 : cx + 1;
      if (x >= 0 && x < nx) for (let y = cy - 1; y <= cy + 1; y++) if (y >= 0 && y < ny) scan(s, y * nx + x);
    } else {
      const y = dir === 2 ? cy - 1 : cy + 1;
      if (y >= 0 && y < ny) for (let x = cx - 1; x <= cx + 1; x++) if (x >= 0 && x < nx) scan(s, y * nx + x);
    }
    crossing(s);
    queue(s);
  }

  function collide(s, o, t) {
    const i = s * REC;
    const j = o * REC;
    const xs = rec[i + 1] + rec[i + 3] * (t - rec[i]);
    const ys = rec[i + 2] + rec[i + 4] * (t - rec[i]);
    const dx = rec[j + 1] + rec[j + 3] * (t - rec[j]) - xs;
    const dy = rec[j + 2] + rec[j + 4] * (t - rec[j]) - ys;
    // Equal masses: the normal components of the velocities are exchanged.
    const q = ((rec[j + 3] - rec[i + 3]) * dx + (rec[j + 4] - rec[i + 4]) * dy) / (dx * dx + dy * dy);
    const vxs = rec[i + 3] + q * dx;
    const vys = rec[i + 4] + q * dy;
    setMotion(o, t, rec[j + 3] - q * dx, rec[j + 4] - q * dy);
    setMotion(s, t, vxs, vys);
    predict(s);
    predict(o);
  }

  for (let s = 0; s < n; s++) {
    const b = scene.bodies[s];
    const i = s * REC;
    rec[i + 1] = b.x;
    rec[i + 2] = b.y;
    rec[i + 3] = b.vx;
    rec[i + 4] = b.vy;
    const col = Math.min(nx - 1, Math.max(0, Math.floor((b.x - bx0) / w)));
    const row = Math.min(ny - 1, Math.max(0, Math.floor((b.y - by0) / w)));
    link(s, row * nx + col);
  }
  for (let s = 0; s < n; s++) predict(s);

  /** Process queue items until `count` collisions (disc or wall) have happened; returns count. */
  function advance(count) {
    let events = 0;
    while (events < count) {
      if (fn === 0 && !refill()) break;
      const s = fslots[0];
      const t = fkeys[0];
      if (onPop !== null) onPop(s, t);
      now = t;
      const i = s * REC;
      if (rec[i + 7] <= rec[i + 6]) {
        cross(s);
        continue;
      }
      if (rec[i + 8] === 1) {
        const o = rec[i + 9];
        if (rec[o * REC + 5] !== rec[i + 10]) {
          predict(s);
          continue;
        }
        collide(s, o, t);
      } else {
        const wall = rec[i + 9];
        if (wall <= 1) setMotion(s, t, -rec[i + 3], rec[i + 4]);
        else setMotion(s, t, rec[i + 3], -rec[i + 4]);
        predict(s);
      }
      events++;
    }
    return events;
  }

  /** Positions and velocities of every disc at the current time (for the tests). */
  function state() {
    const out = [];
    for (let s = 0; s < n; s++) {
      const i = s * REC;
      const dt = now - rec[i];
      out.push({
        x: rec[i + 1] + rec[i + 3] * dt,
        y: rec[i + 2] + rec[i + 4] * dt,
        vx: rec[i + 3],
        vy: rec[i + 4],
      });
    }
    return out;
  }

  function queueKeys() {
    const out = new Float64Array(n);
    for (let s = 0; s < n; s++) out[s] = loc[s] === ABSENT ? INF : qkey[s];
    return out;
  }

  const queueStats = () => ({ width: bw, buckets: mask + 1, rebuilds });

  return { advance, time: () => now, state, queueKeys, queueStats };
}
