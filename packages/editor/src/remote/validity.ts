/**
 * Motion-law intervals of a frame's bodies (protocol.ts, F_FROM / F_UNTIL): between two events that
 * involve a body, its position is one polynomial of time (p + v·dt + a·dt²/2, docs/architecture.md),
 * so the law a frame gives at its time t holds from the body's last event at or before t to its first
 * event after t. Actions (edits, gravity changes) end every body's interval; intervals never reach
 * beyond `window` seconds around t, before 0 or past the horizon.
 */
import type { LogEvent } from "../engineTypes";
import { F_FROM, F_UNTIL, FRAME_STRIDE } from "./protocol";

/**
 * Sets F_FROM / F_UNTIL of every body in `data` (FRAME_STRIDE numbers per body, body i has id
 * ids[i], `index` maps ids to i) from `events`: the logged events with t − window <= time <= t + window.
 */
export function markValidity(
  data: Float64Array,
  index: ReadonlyMap<string, number>,
  events: readonly LogEvent[],
  t: number,
  window: number,
  horizon: number,
): void {
  const n = data.length / FRAME_STRIDE;
  const lo = Math.min(t, Math.max(0, t - window));
  const hi = Math.max(t, Math.min(horizon, t + window));
  // Actions end every body's interval: only the last one at or before t and the first one after t
  // count, applied once to all bodies (a scene adds its bodies by actions at t = 0: marking every
  // body for each of 20,000 adds took 0.4 s per frame while playing the first quarter second).
  let from = lo;
  let until = hi;
  for (const e of events) {
    if (e.type !== "action" || e.time < lo || e.time > hi) continue;
    if (e.time <= t) from = Math.max(from, e.time);
    else until = Math.min(until, e.time);
  }
  for (let i = 0; i < n; i++) {
    data[i * FRAME_STRIDE + F_FROM] = from;
    data[i * FRAME_STRIDE + F_UNTIL] = until;
  }
  for (const e of events) {
    if (e.type === "action" || e.time < lo || e.time > hi) continue;
    const before = e.time <= t;
    for (const id of e.ids) {
      const i = index.get(id);
      if (i === undefined) continue;
      const o = i * FRAME_STRIDE + (before ? F_FROM : F_UNTIL);
      if (before ? e.time > data[o]! : e.time < data[o]!) data[o] = e.time;
    }
  }
}
