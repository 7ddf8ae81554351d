/**
 * Reading the history: the state at any time (last keyframe at or before t + the records up to t +
 * closed-form evaluation) and the event log (each record expanded into a LogEvent; the contact point,
 * normal and impulse are recomputed from the motions just before the event with the World's own
 * formulas, so they match what the World reported; the walk over the records is logCursor.ts). Without history (headlessStateAt) only the
 * span since the last event or action can be read, from the World itself.
 */

import { discDiscResponse, impulseMagnitude, reflectResponse } from "../physics/response.js";
import type { Action } from "../scene/types.js";
import { lineParameter, makeLine, parameterOnLine } from "../sim/obstacles.js";
import type { TimelineCore } from "./core.js";
import { earliestReadable } from "./kept.js";
import type { Keyframe } from "./keyframe.js";
import type { MotionCursor } from "./motionCursor.js";
import type { MotionTable } from "./motionTable.js";
import { K_ACTION, K_BODY_BODY, K_BODY_LINE, K_BODY_POINT, KIND_NAMES, type Records } from "./records.js";
import type { LogEvent, SceneState } from "./types.js";

const INF = Number.POSITIVE_INFINITY;
const vel = new Float64Array(4);

/** Apply record i (an event) to the motions in `table`. */
export function applyRecord(records: Records, i: number, table: MotionTable, kf: Keyframe): void {
  const t = records.time[i] as number;
  const o = 4 * i;
  const gx = kf.gravity[0];
  const gy = kf.gravity[1];
  const v = records.vel;
  table.rebase(records.a[i] as number, t, v[o] as number, v[o + 1] as number, kf.g, gx, gy);
  if (records.kind[i] === K_BODY_BODY)
    table.rebase(records.b[i] as number, t, v[o + 2] as number, v[o + 3] as number, kf.g, gx, gy);
}

/** The exact state at time t (0 <= t <= horizon), the motions found by `cursor` (motionCursor.ts). */
export function stateAt(core: TimelineCore, t: number, cursor: MotionCursor): SceneState {
  const kf = cursor.seek(core, t);
  const scratch = cursor.table;
  const ids = core.bodyIds;
  const bodies = Array.from(core.chains.orderOf(kf, ids), (n) => scratch.state(n, ids[n] as string, t));
  // copies: the keyframe's own lists rebuild Worlds (an edit in the past), so they must not be handed out
  return {
    time: t,
    g: kf.g,
    gravity: [kf.gravity[0], kf.gravity[1]],
    bodies,
    lines: kf.lines.map((l) => ({ id: l.id, p1: [l.p1[0], l.p1[1]], p2: [l.p2[0], l.p2[1]], kind: l.kind })),
    points: kf.points.map((p) => ({ id: p.id, p: [p.p[0], p.p[1]] })),
  };
}

/** The state at t of a timeline without history: only from its last event or action on (no event or
 *  action lies in (lastLogged, horizon], so every current motion holds over that span). */
export function headlessStateAt(core: TimelineCore, t: number): SceneState {
  requireHeadlessTime(core, t, "stateAt");
  const w = core.world;
  return { time: t, g: w.g, gravity: w.gravity, bodies: w.bodies(t), lines: w.lines(), points: w.points() };
}

/** Throws `method`'s RangeError for a t before the last logged entry of a timeline without history
 *  (the readers check it first, through stateTime: this guards the reads themselves). */
export function requireHeadlessTime(core: TimelineCore, t: number, method: string): void {
  if (t < core.lastLogged)
    throw new RangeError(
      `${method}(t): must be a number in [${core.lastLogged}, ${core.horizon}] (got ${t}): ${earliestReadable(core)}`,
    );
}

/** Log event of record i, given the motions just before it in `table`. */
export function describe(core: TimelineCore, i: number, table: MotionTable, kf: Keyframe): LogEvent {
  const rec = core.records;
  const t = rec.time[i] as number;
  const kind = rec.kind[i] as number;
  const a = rec.a[i] as number;
  const b = rec.b[i] as number;
  if (kind === K_ACTION) {
    const act = core.acts[a] as Action;
    return {
      time: t,
      type: "action",
      ids: "id" in act ? [act.id] : [],
      point: null,
      normal: null,
      impulse: null,
      action: act.type,
    };
  }
  const ida = core.bodyIds[a] as string;
  const x = table.x(a, t);
  const y = table.y(a, t);
  const vx = table.vx(a, t);
  const vy = table.vy(a, t);
  const m = table.m(a);
  if (kind === K_BODY_BODY) {
    const xb = table.x(b, t);
    const yb = table.y(b, t);
    const approach = discDiscResponse(
      x,
      y,
      vx,
      vy,
      m,
      xb,
      yb,
      table.vx(b, t),
      table.vy(b, t),
      table.m(b),
      vel,
    );
    const dx = xb - x;
    const dy = yb - y;
    const d = Math.sqrt(dx * dx + dy * dy);
    const nx = dx / d;
    const ny = dy / d;
    const r = table.r(a);
    return {
      time: t,
      type: "bodyBody",
      ids: [ida, core.bodyIds[b] as string],
      point: [x + r * nx, y + r * ny],
      normal: [nx, ny],
      impulse: impulseMagnitude(m, table.m(b), approach),
    };
  }
  if (kind !== K_BODY_LINE && kind !== K_BODY_POINT)
    return { time: t, type: "stop", ids: [ida], point: [x, y], normal: null, impulse: 0 };
  let other: string;
  let nx = 0;
  let ny = 0;
  let cx = 0;
  let cy = 0;
  let px: number | null = null;
  let py = 0;
  if (kind === K_BODY_LINE) {
    other = core.lineIds[b] as string;
    const ls = kf.lines.find((l) => l.id === other);
    if (!ls) throw new Error(`timeline: line ${other} missing from its keyframe`);
    const line = makeLine(other, ls.p1, ls.p2, ls.kind);
    const lambda = lineParameter(line, x, y);
    if (parameterOnLine(line.kind, lambda)) {
      const side = line.nx * (x - line.x1) + line.ny * (y - line.y1);
      nx = side > 0 ? line.ey : -line.ey;
      ny = side > 0 ? -line.ex : line.ex;
      const len = Math.sqrt(line.ee);
      const r = table.r(a);
      cx = x + (r * nx) / len;
      cy = y + (r * ny) / len;
    } else {
      px = lambda < 0 ? line.x1 : line.x2;
      py = lambda < 0 ? line.y1 : line.y2;
    }
  } else {
    other = core.pointIds[b] as string;
    const ps = kf.points.find((p) => p.id === other);
    if (!ps) throw new Error(`timeline: point ${other} missing from its keyframe`);
    px = ps.p[0];
    py = ps.p[1];
  }
  if (px !== null) {
    nx = px - x;
    ny = py - y;
    cx = px;
    cy = py;
  }
  const approach = reflectResponse(vx, vy, nx, ny, vel);
  const nn = Math.sqrt(nx * nx + ny * ny);
  return {
    time: t,
    type: KIND_NAMES[kind] as "bodyLine" | "bodyPoint",
    ids: [ida, other],
    point: [cx, cy],
    normal: [nx / nn, ny / nn],
    impulse: m === INF ? (approach > 0 ? INF : 0) : 2 * m * approach,
  };
}
