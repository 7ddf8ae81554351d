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
 * The queue is a calendar queue (minimalCalendar.mjs) of one entry per disc, keyed by the earlier
 * of its next event and its next cell crossing, popped in (key, disc index) order, so the
 * WebAssembly twin (bench/wasm/assembly/minimalGas.ts) runs the same event sequence bit for bit.
 *
 * Record layout per disc (REC doubles): 0 t0, 1 x0, 2 y0, 3 vx, 4 vy, 5 motion version,
 * 6 event time, 7 crossing time, 8 event kind (0 none, 1 disc, 2 wall), 9 partner or wall,
 * 10 partner version at prediction, 11 crossing direction (0 -x, 1 +x, 2 -y, 3 +y).
 */
import { createCalendar } from "./minimalCalendar.mjs";

const REC = 16;
const INF = Number.POSITIVE_INFINITY;

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

  const { set: setKey, first, firstKey, keys: queueKeys, stats: queueStats } = createCalendar(n);

  /** Queue disc s at its next event or crossing, whichever is earlier (never popped if infinite). */
  function queue(s) {
    const i = s * REC;
    setKey(s, Math.min(rec[i + 6], rec[i + 7]));
  }

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
      const s = first();
      if (s < 0) break;
      const t = firstKey();
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

  return { advance, time: () => now, state, queueKeys, queueStats };
}
