/**
 * The canonical order of simultaneous events: the event queue's tie-break for two bodies whose next
 * events fall at exactly the same time. By rank first (a cell crossing before a stop, a line, a
 * point, then a body: bodyStore.ts's EV_* values), then by the two ids that name the event (for two
 * bodies, the smaller id first), then by the event's aux number (evAux: which part of a line is
 * met, 0 its length, 1 and 2 its ends). Slots and the order bodies were added in play no part, so
 * the same edits give the same events bit for bit (docs/architecture.md, Determinism). Pure reads
 * of the store and the lists.
 */
import { type BodyStore, EV_BODY, EV_CROSS, EV_LINE, EV_POINT } from "./bodyStore.js";
import type { Line, Point } from "./obstacles.js";

/** Whether slot a's next event comes before slot c's when both are at exactly the same time. */
export function eventTieLess(
  store: BodyStore,
  lines: readonly Line[],
  points: readonly Point[],
  a: number,
  c: number,
): boolean {
  const ra = rankOf(store, a);
  const rc = rankOf(store, c);
  if (ra !== rc) return ra < rc;
  const [a1, a2] = eventIds(store, lines, points, a, ra);
  const [c1, c2] = eventIds(store, lines, points, c, rc);
  if (a1 !== c1) return a1 < c1;
  if (a2 !== c2) return a2 < c2;
  return (store.evAux[a] as number) < (store.evAux[c] as number);
}

/** The rank of slot s's next event: a cell crossing when it comes no later, else its kind. */
function rankOf(b: BodyStore, s: number): number {
  return (b.crossTime[s] as number) <= (b.evTime[s] as number) ? EV_CROSS : (b.evKind[s] as number);
}

/** The two ids that name slot s's next event canonically: [first, second]. */
function eventIds(
  b: BodyStore,
  lines: readonly Line[],
  points: readonly Point[],
  s: number,
  rank: number,
): [string, string] {
  const id = b.ids[s] as string;
  if (rank === EV_BODY) {
    const other = b.ids[b.evOther[s] as number] as string;
    return id < other ? [id, other] : [other, id];
  }
  if (rank === EV_LINE) return [id, (lines[b.evOther[s] as number] as Line).id];
  if (rank === EV_POINT) return [id, (points[b.evOther[s] as number] as Point).id];
  return [id, ""];
}
