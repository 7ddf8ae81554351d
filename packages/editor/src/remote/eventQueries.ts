/**
 * Read-only queries over a timeline's event log for the UI. Built on nextEventTime / prevEventTime
 * (O(log n)) and one eventsBetween per query: reading single events by index is costly in the
 * engine (each read reconstructs its contact data), reading a time window is not. A page's action
 * entries carry the action's index in the timeline's `actions` (actionIndices.ts), found before the
 * page is cut, while every entry at each time is at hand.
 */
import type { LogEvent } from "../engineTypes";
import { withActionIndices } from "./actionIndices";
import { eventFilter } from "./eventFilter";
import type { EventPage, PageEvent } from "./protocol";
import type { TimelineLike } from "./timelineLike";

type Log = Pick<
  TimelineLike,
  "actions" | "eventCount" | "nextEventTime" | "prevEventTime" | "eventsBetween" | "horizon"
>;

/** Largest number of events one filtered query may read on each side of t. */
export const FILTER_SCAN_LIMIT = 200_000;

/** The time `steps` distinct event times after t (null when there is none). */
function walkForward(tl: Log, t: number, steps: number): number | null {
  let last: number | null = null;
  for (let k = 0; k < steps; k++) {
    const n = tl.nextEventTime(last ?? t);
    if (n === null) break;
    last = n;
  }
  return last;
}

/** The earliest of the `steps` distinct event times before t (t itself when there is none). */
function walkBack(tl: Log, t: number, steps: number): number {
  let at = t;
  for (let k = 0; k < steps; k++) {
    const p = tl.prevEventTime(at);
    if (p === null) break;
    at = p;
  }
  return at;
}

/**
 * Up to `before` events at or before t and `after` events after t, in time order (events sharing a
 * time count once per time when walking). With a filter text `body` (eventFilter.ts: one id, or ids
 * separated by commas that must all take part), only the entries it keeps, found by scanning
 * windows outward from t (at most FILTER_SCAN_LIMIT events per side). Action entries carry their
 * action's index (PageEvent.actionIndex).
 */
export function eventPage(tl: Log, t: number, before: number, after: number, body: string | null): EventPage {
  const total = tl.eventCount;
  // Every eventsBetween window holds all the entries at each time in it: action indices are found
  // there, before a page or a filter keeps part of them.
  const actions = () => tl.actions;
  if (total === 0) return { first: -1, total, events: [] };
  const test = body === null ? null : eventFilter(body);
  if (test === null) {
    const t0 = walkBack(tl, t, before);
    const t1 = walkForward(tl, t, after) ?? t;
    const all = tl.eventsBetween(t0, t1);
    const split = all.findIndex((e) => e.time > t);
    const mid = split < 0 ? all.length : split;
    const from = Math.max(0, mid - before);
    const events = withActionIndices(all, actions, (_e, i) => i >= from && i < mid + after);
    return { first: -1, total, events };
  }
  const mine = (e: LogEvent) => test(e.ids);
  const density = Math.max(tl.horizon / total, 1e-12);
  const back: PageEvent[] = [];
  const ahead: PageEvent[] = [];
  // backwards from t
  let hi = t;
  let span = density * 1000;
  let scanned = 0;
  // At t = 0 the one window [0, 0] is still read (the actions at time 0).
  while (back.length < before && (hi > 0 || hi === t) && scanned < FILTER_SCAN_LIMIT) {
    const lo = Math.max(0, hi - span);
    const win = tl.eventsBetween(lo, hi);
    scanned += win.length;
    const found = withActionIndices(win, actions, (e) => mine(e) && e.time <= t && (e.time < hi || hi === t));
    back.unshift(...found);
    if (lo === 0) break;
    hi = lo;
    span *= 2;
  }
  // forwards from t
  let lo = t;
  span = density * 1000;
  scanned = 0;
  while (ahead.length < after && lo < tl.horizon && scanned < FILTER_SCAN_LIMIT) {
    const top = Math.min(tl.horizon, lo + span);
    const win = tl.eventsBetween(lo, top);
    scanned += win.length;
    ahead.push(...withActionIndices(win, actions, (e) => mine(e) && e.time > lo));
    lo = top;
    span *= 2;
  }
  // Windows share their edges; each window keeps only events strictly inside its far edge.
  const events = [...back.slice(-before), ...ahead.slice(0, after)];
  return { first: -1, total, events };
}

/** Time of the last logged event (at most the horizon), or null when the log is empty. */
export function lastEventTime(tl: Log): number | null {
  if (tl.eventCount === 0) return null;
  const before = tl.prevEventTime(tl.horizon);
  if (before === null) return tl.nextEventTime(Number.NEGATIVE_INFINITY);
  return tl.nextEventTime(before) ?? before;
}

/** The time of the first logged event at or after t, or null when there is none. */
function firstEventFrom(tl: Log, t: number): number | null {
  return tl.nextEventTime(tl.prevEventTime(t) ?? Number.NEGATIVE_INFINITY);
}

/**
 * Event times for the scrubber: for each of n equal bins of [lo, hi] (by default the whole history
 * [0, horizon]; the Time slider's zoom asks for its window), the first event in it.
 */
export function eventTicks(tl: Log, n: number, lo = 0, hi = tl.horizon): number[] {
  const out: number[] = [];
  const span = hi - lo;
  if (tl.eventCount === 0 || !(span > 0)) return out;
  let next = firstEventFrom(tl, lo);
  while (next !== null && next <= hi) {
    out.push(next);
    // jump to the bin after the one holding `next`
    const k = Math.floor(((next - lo) / span) * n) + 1;
    if (k >= n) break;
    // (an event on the bin's edge is the bin's first)
    const edge = lo + (k * span) / n;
    next = edge > next ? firstEventFrom(tl, edge) : tl.nextEventTime(next);
  }
  return out;
}
