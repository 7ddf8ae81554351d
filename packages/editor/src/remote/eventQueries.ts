/**
 * Read-only queries over a timeline's event log for the UI: the page of events around a time
 * (optionally only those of one body), downsampled event times for the scrubber's ticks.
 * All are O(log n) in the log size except building a body filter (done once per revision by the host).
 */
import type { LogEvent } from "../engineTypes";
import type { EventPage } from "./protocol";
import type { TimelineLike } from "./timelineLike";

/** Number of logged events with time <= t (the index of the first event after t). */
export function firstEventAfter(tl: Pick<TimelineLike, "eventCount" | "event">, t: number): number {
  let lo = 0;
  let hi = tl.eventCount;
  while (lo < hi) {
    const mid = (lo + hi) >>> 1;
    if (tl.event(mid).time <= t) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}

function copy(e: LogEvent): LogEvent {
  return {
    time: e.time,
    type: e.type,
    ids: [...e.ids],
    point: e.point,
    normal: e.normal,
    impulse: e.impulse,
  };
}

/**
 * Up to `before` events at or before t and `after` events after t, in time order. With `indices`
 * (the log indices of one body's events, ascending) only those events count.
 */
export function eventPage(
  tl: Pick<TimelineLike, "eventCount" | "event">,
  t: number,
  before: number,
  after: number,
  indices: number[] | null,
): EventPage {
  const total = indices ? indices.length : tl.eventCount;
  const at = (k: number) => tl.event(indices ? indices[k]! : k);
  let lo = 0;
  let hi = total;
  while (lo < hi) {
    const mid = (lo + hi) >>> 1;
    if (at(mid).time <= t) lo = mid + 1;
    else hi = mid;
  }
  const first = Math.max(0, lo - before);
  const end = Math.min(total, lo + after);
  const events: LogEvent[] = [];
  for (let k = first; k < end; k++) events.push(copy(at(k)));
  return { first, total, events };
}

/** At most n event times spread evenly over the log (all of them when there are few). */
export function eventTicks(tl: Pick<TimelineLike, "eventCount" | "event">, n: number): number[] {
  const count = tl.eventCount;
  const out: number[] = [];
  if (count <= n) {
    for (let i = 0; i < count; i++) out.push(tl.event(i).time);
    return out;
  }
  for (let k = 0; k < n; k++) out.push(tl.event(Math.floor((k * (count - 1)) / (n - 1))).time);
  return out;
}
