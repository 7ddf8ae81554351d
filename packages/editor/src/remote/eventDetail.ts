/**
 * The worker's side of the Event details panel: finds the log entry an EventRef names (protocol.ts)
 * and reads its detail from the engine (Timeline.eventDetail: each participant's exact state just
 * before and just after). Contract: `findEventDetail(tl, ref)` returns the detail of the first entry
 * logged at exactly `ref.time` whose kind, participants and action type equal the ref's, or null when
 * there is none (the history was recomputed without it, or not computed that far). The search starts
 * at eventIndexAt(time) (a binary search) and walks only the entries at that time, in log order (a
 * forward walk: the engine replays each record once). A ref's `nth` skips that many entries alike.
 * `stepEventDetail(tl, ref, ±1)` gives the entry logged just before or after the one `ref` names, with
 * its detail and a ref that names it even among entries alike (its `nth`): stepping this way walks
 * through the entries of one instant one by one (a Newton's cradle's chain), which stepping by time
 * cannot.
 */
import type { EventDetail, LogEvent } from "../engineTypes";
import type { EntryDetail, EventRef, EventStep } from "./protocol";
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

/** A key that changes with the entry an EventRef names ("" for none; nth 0 and no nth are alike). */
export function refKey(ref: EventRef | null): string {
  if (ref === null) return "";
  const key: unknown[] = [ref.time, ref.type, ref.ids, ref.action ?? null];
  if (ref.nth) key.push(ref.nth);
  return JSON.stringify(key);
}

/** Whether a ref's time can name an entry at all (a ref comes from the page, through the worker). */
const usable = (ref: EventRef): boolean => typeof ref.time === "number" && Number.isFinite(ref.time);

/** Entry i's detail `d` with whether it is the log's first or last entry (Event details greys out
 *  Previous / Next entry there). */
function atEnds(tl: Log, i: number, d: EventDetail): EntryDetail {
  return { ...d, first: i === 0, last: i === tl.eventCount - 1 };
}

/** The detail of the entry `ref` names, or null (see the header). */
export function findEventDetail(tl: Log, ref: EventRef): EntryDetail | null {
  if (!usable(ref)) return null;
  const n = tl.eventCount;
  let skip = ref.nth ?? 0;
  // A collision or a stop is read with its detail at once (the walk goes on forwards; reading the
  // entry, then its detail, would replay from a keyframe twice); an action's detail loads a keyframe,
  // so the actions of a group are only read until the one named.
  const action = ref.type === "action";
  for (let i = tl.eventIndexAt(ref.time); i < n; i++) {
    const e = action ? tl.event(i) : tl.eventDetail(i);
    if (e.time !== ref.time) return null;
    if (matches(e, ref) && skip-- === 0)
      return atEnds(tl, i, action ? tl.eventDetail(i) : (e as EventDetail));
  }
  return null;
}

/** The log index of the entry `ref` names, or −1. */
function indexOf(tl: Log, ref: EventRef): number {
  if (!usable(ref)) return -1;
  let skip = ref.nth ?? 0;
  for (let i = tl.eventIndexAt(ref.time); i < tl.eventCount; i++) {
    const e = tl.event(i);
    if (e.time !== ref.time) return -1;
    if (matches(e, ref) && skip-- === 0) return i;
  }
  return -1;
}

/** The entry logged just before (−1) or after (+1) the one `ref` names (see the header), or null. */
export function stepEventDetail(tl: Log, ref: EventRef, step: 1 | -1): EventStep | null {
  const i = indexOf(tl, ref);
  const j = i + step;
  if (i < 0 || j < 0 || j >= tl.eventCount) return null;
  const detail = atEnds(tl, j, tl.eventDetail(j));
  const to = refOf(detail);
  let nth = 0;
  for (let k = tl.eventIndexAt(detail.time); k < j; k++) if (matches(tl.event(k), to)) nth++;
  if (nth > 0) to.nth = nth;
  return { ref: to, detail };
}
