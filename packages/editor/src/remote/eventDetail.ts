/**
 * The worker's side of the Event details panel: finds the log entry an EventRef names (protocol.ts)
 * and reads its detail from the engine (Timeline.eventDetail: each participant's exact state just
 * before and just after). Contract: `findEventDetail(tl, ref)` returns the detail of the first entry
 * logged at exactly `ref.time` whose kind, participants and action type equal the ref's, or null when
 * there is none (the history was recomputed without it, or not computed that far). The search starts
 * at eventIndexAt(time) (a binary search) and walks only the entries at that time, in log order (a
 * forward walk: the engine replays each record once).
 */
import type { EventDetail, LogEvent } from "../engineTypes";
import type { EventRef } from "./protocol";
import type { TimelineLike } from "./timelineLike";

type Log = Pick<TimelineLike, "eventCount" | "event" | "eventDetail" | "eventIndexAt">;

/** Whether log entry `e` is the one `ref` names. */
export function matches(e: LogEvent, ref: EventRef): boolean {
  return (
    e.time === ref.time &&
    e.type === ref.type &&
    e.action === ref.action &&
    e.ids.length === ref.ids.length &&
    e.ids.every((id, k) => id === ref.ids[k])
  );
}

/** The EventRef of a log entry (what the Event log stores as the selected event). */
export function refOf(e: LogEvent): EventRef {
  const ref: EventRef = { time: e.time, type: e.type, ids: [...e.ids] };
  if (e.action !== undefined) ref.action = e.action;
  return ref;
}

/** A key that changes with the entry an EventRef names ("" for none). */
export function refKey(ref: EventRef | null): string {
  return ref === null ? "" : JSON.stringify([ref.time, ref.type, ref.ids, ref.action ?? null]);
}

/** The detail of the entry `ref` names, or null (see the header). */
export function findEventDetail(tl: Log, ref: EventRef): EventDetail | null {
  if (!(typeof ref.time === "number" && Number.isFinite(ref.time))) return null;
  const n = tl.eventCount;
  // A collision or a stop is read with its detail at once (the walk goes on forwards; reading the
  // entry, then its detail, would replay from a keyframe twice); an action's detail loads a keyframe,
  // so the actions of a group are only read until the one named.
  const action = ref.type === "action";
  for (let i = tl.eventIndexAt(ref.time); i < n; i++) {
    const e = action ? tl.event(i) : tl.eventDetail(i);
    if (e.time !== ref.time) return null;
    if (matches(e, ref)) return action ? tl.eventDetail(i) : (e as EventDetail);
  }
  return null;
}
