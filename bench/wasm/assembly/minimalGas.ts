/**
 * AssemblyScript (WebAssembly) port of bench/engine/minimalGas.mjs: the same stripped algorithm,
 * the same arithmetic in the same order (so the same event sequence), compiled in memory by
 * bench/wasm/minimalGasWasm.mjs with its queue, calendar.ts.
 * It answers how much of the gap to the gas targets a WebAssembly core could close on this machine.
 * Array accesses are unchecked (no bounds checks), as a tuned core would be. A benchmark baseline,
 * not part of the engine. Record layout as in minimalGas.mjs.
 */
import { first, firstKey, reset, setKey } from "./calendar";

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
  for (let i = 0; i < n; i++) {
    unchecked((nxt[i] = -1));
    unchecked((prv[i] = -1));
  }
  reset(n);
  now = 0;
}
/** Queue disc s at its next event or crossing, whichever is earlier (never popped if infinite). */
function queue(s: i32): void {
  const i = s * REC;
  setKey(s, min(unchecked(rec[i + 6]), unchecked(rec[i + 7])));
}
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
    const s = first();
    if (s < 0) break;
    const t = firstKey();
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
