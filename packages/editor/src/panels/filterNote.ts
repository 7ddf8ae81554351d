/**
 * What the Event log says when its filter keeps no entry: an empty table said nothing, whether the
 * id was mistyped or the object simply took part in nothing yet. Two different true statements:
 * - no body, line or point of the scene has the id (any of them, for a list "a, b"): "No body, line
 *   or point has the id "x"." and the scene's ids close to it ("Close: "b1", "b12"."), so a typo
 *   is seen at once;
 * - every id is the scene's, but none of its entries (or none the ids share) is in the computed
 *   history read: "“b3” takes part in no entry of the computed history (up to t = 1 s)." (an action
 *   after the horizon, a refused one, a disc that never meets anything it is filtered with).
 * The filter reads the ids as the log does (remote/eventFilter.ts). Pure.
 */
import { filterParts } from "../remote/eventFilter";
import { FILTER_SCAN_LIMIT } from "../remote/eventQueries";

/** At most this many close ids are named. */
const CLOSE_MAX = 3;
/** Ids at most this many single-character edits away, and fewer than the shorter has characters
 *  (or holding the text, any case), are close. */
const CLOSE_EDITS = 2;

/** The ids of a scene's bodies, lines and points: every `id` its actions name. */
export function sceneIds(actions: readonly object[]): Set<string> {
  const ids = new Set<string>();
  for (const a of actions) if ("id" in a && typeof a.id === "string") ids.add(a.id);
  return ids;
}

/** Single-character insertions, deletions and substitutions from `a` to `b`, up to `max + 1`. */
export function editDistance(a: string, b: string, max: number): number {
  if (Math.abs(a.length - b.length) > max) return max + 1;
  let prev = Array.from({ length: b.length + 1 }, (_, j) => j);
  for (let i = 1; i <= a.length; i++) {
    const row = [i];
    for (let j = 1; j <= b.length; j++)
      row[j] = Math.min(
        (prev[j] as number) + 1,
        (row[j - 1] as number) + 1,
        (prev[j - 1] as number) + (a[i - 1] === b[j - 1] ? 0 : 1),
      );
    prev = row;
  }
  return Math.min(prev[b.length] as number, max + 1);
}

/** The ids of `ids` close to `typed` (closest first, then in natural order), at most CLOSE_MAX. */
export function closeIds(typed: string, ids: Iterable<string>): string[] {
  const lower = typed.toLowerCase();
  const close: { id: string; d: number }[] = [];
  for (const id of ids) {
    if (id.toLowerCase().includes(lower)) {
      close.push({ id, d: 1 });
      continue;
    }
    // fewer edits than the shorter id has characters: "b4" is close to "b3", not to "a"
    const d = editDistance(lower, id.toLowerCase(), CLOSE_EDITS);
    if (d <= CLOSE_EDITS && d < Math.min(lower.length, id.length)) close.push({ id, d });
  }
  const order = new Intl.Collator(undefined, { numeric: true });
  close.sort((x, y) => x.d - y.d || order.compare(x.id, y.id));
  return close.slice(0, CLOSE_MAX).map((c) => c.id);
}

const quoted = (ids: readonly string[]): string => ids.map((id) => JSON.stringify(id)).join(", ");

/**
 * The note for a filter text `filter` whose page shows `shown` entries (null: none to say: no
 * filter, or entries shown); `ids`: the scene's ids (sceneIds), `total` the log's entries and
 * `horizon` the computed history's end.
 */
export function filterNote(
  filter: string,
  shown: number,
  ids: ReadonlySet<string>,
  total: number,
  horizon: number,
): string | null {
  const whole = filter.trim();
  if (whole === "" || shown > 0) return null;
  const parts = ids.has(whole) ? [whole] : filterParts(whole);
  const missing = parts.filter((p) => !ids.has(p));
  if (missing.length > 0) {
    const close = missing.length === 1 ? closeIds(missing[0] as string, ids) : [];
    const noun = missing.length === 1 ? "the id" : "the ids";
    return `No body, line or point has ${noun} ${quoted(missing)}.${close.length > 0 ? ` Close: ${quoted(close)}.` : ""}`;
  }
  const where =
    total > 2 * FILTER_SCAN_LIMIT
      ? `within ${FILTER_SCAN_LIMIT} entries either side of the current time`
      : `of the computed history (up to t = ${Number(horizon.toPrecision(6))} s)`;
  if (parts.length === 1) return `${quoted(parts)} takes part in no entry ${where}.`;
  return `${quoted(parts)} take part in no entry together ${where}.`;
}
