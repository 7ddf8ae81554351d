/**
 * AssemblyScript (WebAssembly) port of bench/engine/minimalGas.mjs: the same stripped algorithm,
 * the same arithmetic in the same order (so the same event sequence), compiled by bench/wasm/build.mjs.
 * It answers how much of the gap to the gas targets a WebAssembly core could close on this machine.
 * Array accesses are unchecked (no bounds checks), as a tuned core would be. A benchmark baseline,
 * not part of the engine. Record layout and calendar queue (pops in (key, disc index) order, the
 * same width estimates and rebuilds) as in minimalGas.mjs.
 */
const REC: i32 = 16;
let n: i32 = 0;
let R: f64 = 1;
let D: f64 = 2;
let bx0: f64 = 0;
let by0: f64 = 0;
let bx1: f64 = 0;
let by1: f64 = 0;
let nx: i32 = 1;
let ny: i32 = 1;
let w: f64 = 1;
let rec: StaticArray<f64> = new StaticArray<f64>(0);
let head: StaticArray<i32> = new StaticArray<i32>(0);
let nxt: StaticArray<i32> = new StaticArray<i32>(0);
let prv: StaticArray<i32> = new StaticArray<i32>(0);
let cellOf: StaticArray<i32> = new StaticArray<i32>(0);
let now: f64 = 0;
const INF: f64 = Infinity;
const CALENDAR_BUCKET_TARGET: f64 = 2;
const CALENDAR_REBUILD_FACTOR: f64 = 4;
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

export function setup(count: i32, r: f64, x0: f64, y0: f64, x1: f64, y1: f64): void {
  n = count;
  R = r;
  D = 2 * r;
  bx0 = x0;
  by0 = y0;
  bx1 = x1;
  by1 = y1;
  const side = x1 - x0;
  nx = max(1, <i32>Math.floor(side / max(D * (1 + 1e-6), Math.sqrt((side * side) / (3 * <f64>n)))));
  ny = nx;
  w = side / <f64>nx;
  rec = new StaticArray<f64>(n * REC);
  head = new StaticArray<i32>(nx * ny);
  for (let i = 0; i < nx * ny; i++) unchecked((head[i] = -1));
  nxt = new StaticArray<i32>(n);
  prv = new StaticArray<i32>(n);
  cellOf = new StaticArray<i32>(n);
  qkey = new StaticArray<f64>(n);
  loc = new StaticArray<i32>(n);
  qnext = new StaticArray<i32>(n);
  qprev = new StaticArray<i32>(n);
  fpos = new StaticArray<i32>(n);
  fslots = new StaticArray<i32>(n);
  fkeys = new StaticArray<f64>(n);
  allSlots = new StaticArray<i32>(n);
  allKeys = new StaticArray<f64>(n);
  for (let i = 0; i < n; i++) {
    unchecked((nxt[i] = -1));
    unchecked((prv[i] = -1));
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
  now = 0;
}
// ---- calendar queue (as in minimalGas.mjs) ---------------------------------------------------
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
function queue(s: i32): void {
  const i = s * REC;
  const k = min(unchecked(rec[i + 6]), unchecked(rec[i + 7]));
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
      if (adaptDue()) {
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
function adaptDue(): bool {
  if (advances < 64) return false;
  const perBucket = <f64>loaded / <f64>advances;
  return (
    perBucket > CALENDAR_BUCKET_TARGET * CALENDAR_REBUILD_FACTOR ||
    perBucket < CALENDAR_BUCKET_TARGET / CALENDAR_REBUILD_FACTOR ||
    overScanned > 8 * queued + 1024
  );
}
function select(m: i32, k: i32): f64 {
  const a = allKeys;
  let lo = 0;
  let hi = m - 1;
  while (lo < hi) {
    const p = unchecked(a[(lo + hi) >> 1]);
    let i = lo;
    let j = hi;
    while (i <= j) {
      while (unchecked(a[i]) < p) i++;
      while (unchecked(a[j]) > p) j--;
      if (i <= j) {
        const t = unchecked(a[i]);
        unchecked((a[i] = unchecked(a[j])));
        unchecked((a[j] = t));
        i++;
        j--;
      }
    }
    if (k <= j) hi = j;
    else if (k >= i) lo = i;
    else break;
  }
  return unchecked(a[k]);
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
  const spread: f64 = m > 0 ? select(m, m >> 1) - lo : 0;
  const nw = (CALENDAR_BUCKET_TARGET * spread) / (0.69 * <f64>max(1, m));
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
// ---- grid and physics ------------------------------------------------------------------------
function link(s: i32, c: i32): void {
  const h = unchecked(head[c]);
  unchecked((nxt[s] = h));
  unchecked((prv[s] = -1));
  if (h >= 0) unchecked((prv[h] = s));
  unchecked((head[c] = s));
  unchecked((cellOf[s] = c));
}
function unlink(s: i32): void {
  const p = unchecked(prv[s]);
  const q = unchecked(nxt[s]);
  if (p >= 0) unchecked((nxt[p] = q));
  else unchecked((head[unchecked(cellOf[s])] = q));
  if (q >= 0) unchecked((prv[q] = p));
}
function pairTime(s: i32, o: i32): f64 {
  const i = s * REC;
  const j = o * REC;
  const ts = unchecked(rec[i]);
  const to = unchecked(rec[j]);
  const tb = max(ts, to);
  const dx =
    unchecked(rec[j + 1]) +
    unchecked(rec[j + 3]) * (tb - to) -
    (unchecked(rec[i + 1]) + unchecked(rec[i + 3]) * (tb - ts));
  const dy =
    unchecked(rec[j + 2]) +
    unchecked(rec[j + 4]) * (tb - to) -
    (unchecked(rec[i + 2]) + unchecked(rec[i + 4]) * (tb - ts));
  const ux = unchecked(rec[j + 3]) - unchecked(rec[i + 3]);
  const uy = unchecked(rec[j + 4]) - unchecked(rec[i + 4]);
  const b = dx * ux + dy * uy;
  if (b >= 0) return INF;
  const c = dx * dx + dy * dy - D * D;
  const disc = b * b - (ux * ux + uy * uy) * c;
  if (disc < 0) return INF;
  return max(tb + c / (-b + Math.sqrt(disc)), now);
}
function offer(s: i32, t: f64, kind: f64, other: i32): void {
  const i = s * REC;
  if (t >= unchecked(rec[i + 6])) return;
  unchecked((rec[i + 6] = t));
  unchecked((rec[i + 8] = kind));
  unchecked((rec[i + 9] = <f64>other));
  unchecked((rec[i + 10] = kind == 1 ? unchecked(rec[other * REC + 5]) : 0));
}
function scan(s: i32, c: i32): void {
  for (let o = unchecked(head[c]); o >= 0; o = unchecked(nxt[o])) {
    if (o == s) continue;
    const t = pairTime(s, o);
    if (t < INF) offer(s, t, 1, o);
  }
}
function wallTime(s: i32): void {
  const i = s * REC;
  const vx = unchecked(rec[i + 3]);
  const vy = unchecked(rec[i + 4]);
  let t = INF;
  let wall = -1;
  if (vx > 0) {
    t = unchecked(rec[i]) + (bx1 - R - unchecked(rec[i + 1])) / vx;
    wall = 1;
  } else if (vx < 0) {
    t = unchecked(rec[i]) + (bx0 + R - unchecked(rec[i + 1])) / vx;
    wall = 0;
  }
  if (vy > 0) {
    const ty = unchecked(rec[i]) + (by1 - R - unchecked(rec[i + 2])) / vy;
    if (ty < t) {
      t = ty;
      wall = 3;
    }
  } else if (vy < 0) {
    const ty = unchecked(rec[i]) + (by0 + R - unchecked(rec[i + 2])) / vy;
    if (ty < t) {
      t = ty;
      wall = 2;
    }
  }
  if (wall >= 0) offer(s, max(t, now), 2, wall);
}
function crossing(s: i32): void {
  const i = s * REC;
  const c = unchecked(cellOf[s]);
  const cx = c % nx;
  const cy = c / nx;
  const vx = unchecked(rec[i + 3]);
  const vy = unchecked(rec[i + 4]);
  let t = INF;
  let dir = -1;
  if (vx > 0 && cx < nx - 1) {
    t = unchecked(rec[i]) + (bx0 + <f64>(cx + 1) * w - unchecked(rec[i + 1])) / vx;
    dir = 1;
  } else if (vx < 0 && cx > 0) {
    t = unchecked(rec[i]) + (bx0 + <f64>cx * w - unchecked(rec[i + 1])) / vx;
    dir = 0;
  }
  if (vy > 0 && cy < ny - 1) {
    const ty = unchecked(rec[i]) + (by0 + <f64>(cy + 1) * w - unchecked(rec[i + 2])) / vy;
    if (ty < t) {
      t = ty;
      dir = 3;
    }
  } else if (vy < 0 && cy > 0) {
    const ty = unchecked(rec[i]) + (by0 + <f64>cy * w - unchecked(rec[i + 2])) / vy;
    if (ty < t) {
      t = ty;
      dir = 2;
    }
  }
  unchecked((rec[i + 11] = <f64>dir));
  unchecked((rec[i + 7] = max(t, now)));
}
function predict(s: i32): void {
  const i = s * REC;
  unchecked((rec[i + 6] = INF));
  unchecked((rec[i + 8] = 0));
  const c = unchecked(cellOf[s]);
  const cx = c % nx;
  const cy = c / nx;
  for (let y = cy - 1; y <= cy + 1; y++) {
    if (y < 0 || y >= ny) continue;
    for (let x = cx - 1; x <= cx + 1; x++) if (x >= 0 && x < nx) scan(s, y * nx + x);
  }
  wallTime(s);
  crossing(s);
  queue(s);
}
function setMotion(s: i32, t: f64, vx: f64, vy: f64): void {
  const i = s * REC;
  const dt = t - unchecked(rec[i]);
  unchecked((rec[i + 1] = unchecked(rec[i + 1]) + unchecked(rec[i + 3]) * dt));
  unchecked((rec[i + 2] = unchecked(rec[i + 2]) + unchecked(rec[i + 4]) * dt));
  unchecked((rec[i] = t));
  unchecked((rec[i + 3] = vx));
  unchecked((rec[i + 4] = vy));
  unchecked((rec[i + 5] = unchecked(rec[i + 5]) + 1));
}
function cross(s: i32): void {
  const i = s * REC;
  const c = unchecked(cellOf[s]);
  let cx = c % nx;
  let cy = c / nx;
  const dir = <i32>unchecked(rec[i + 11]);
  if (dir == 0) cx--;
  else if (dir == 1) cx++;
  else if (dir == 2) cy--;
  else cy++;
  unlink(s);
  link(s, cy * nx + cx);
  if (dir <= 1) {
    const x = dir == 0 ? cx - 1 : cx + 1;
    if (x >= 0 && x < nx) for (let y = cy - 1; y <= cy + 1; y++) if (y >= 0 && y < ny) scan(s, y * nx + x);
  } else {
    const y = dir == 2 ? cy - 1 : cy + 1;
    if (y >= 0 && y < ny) for (let x = cx - 1; x <= cx + 1; x++) if (x >= 0 && x < nx) scan(s, y * nx + x);
  }
  crossing(s);
  queue(s);
}
function collide(s: i32, o: i32, t: f64): void {
  const i = s * REC;
  const j = o * REC;
  const xs = unchecked(rec[i + 1]) + unchecked(rec[i + 3]) * (t - unchecked(rec[i]));
  const ys = unchecked(rec[i + 2]) + unchecked(rec[i + 4]) * (t - unchecked(rec[i]));
  const dx = unchecked(rec[j + 1]) + unchecked(rec[j + 3]) * (t - unchecked(rec[j])) - xs;
  const dy = unchecked(rec[j + 2]) + unchecked(rec[j + 4]) * (t - unchecked(rec[j])) - ys;
  const q =
    ((unchecked(rec[j + 3]) - unchecked(rec[i + 3])) * dx +
      (unchecked(rec[j + 4]) - unchecked(rec[i + 4])) * dy) /
    (dx * dx + dy * dy);
  const vxs = unchecked(rec[i + 3]) + q * dx;
  const vys = unchecked(rec[i + 4]) + q * dy;
  setMotion(o, t, unchecked(rec[j + 3]) - q * dx, unchecked(rec[j + 4]) - q * dy);
  setMotion(s, t, vxs, vys);
  predict(s);
  predict(o);
}
export function setBody(s: i32, x: f64, y: f64, vx: f64, vy: f64): void {
  const i = s * REC;
  unchecked((rec[i + 1] = x));
  unchecked((rec[i + 2] = y));
  unchecked((rec[i + 3] = vx));
  unchecked((rec[i + 4] = vy));
  const col = min(nx - 1, max(0, <i32>Math.floor((x - bx0) / w)));
  const row = min(ny - 1, max(0, <i32>Math.floor((y - by0) / w)));
  link(s, row * nx + col);
}
export function start(): void {
  for (let s = 0; s < n; s++) predict(s);
}
export function time(): f64 {
  return now;
}
export function advance(count: i32): i32 {
  let events = 0;
  while (events < count) {
    if (fn == 0 && !refill()) break;
    const s = unchecked(fslots[0]);
    const t = unchecked(fkeys[0]);
    now = t;
    const i = s * REC;
    if (unchecked(rec[i + 7]) <= unchecked(rec[i + 6])) {
      cross(s);
      continue;
    }
    if (unchecked(rec[i + 8]) == 1) {
      const o = <i32>unchecked(rec[i + 9]);
      if (unchecked(rec[o * REC + 5]) != unchecked(rec[i + 10])) {
        predict(s);
        continue;
      }
      collide(s, o, t);
    } else {
      const wall = unchecked(rec[i + 9]);
      if (wall <= 1) setMotion(s, t, -unchecked(rec[i + 3]), unchecked(rec[i + 4]));
      else setMotion(s, t, unchecked(rec[i + 3]), -unchecked(rec[i + 4]));
      predict(s);
    }
    events++;
  }
  return events;
}
