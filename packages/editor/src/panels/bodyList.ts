/**
 * Which bodies the Bodies table lists: in natural id order (naturalOrder.ts), those whose id contains
 * the filter (case-insensitive; an empty filter matches all), at most `max` of them, and the selected
 * body and the `kept` ones (rows holding an open cell: useHeldRows.ts) always. `matched` counts every match, so the table can say how many it leaves out: with more
 * bodies than rows, the filter is how any body is found from the keyboard.
 */
import { naturalOrder } from "./naturalOrder";

export interface BodyList {
  /** Indices into `ids` of the rows to list, in natural id order. */
  listed: number[];
  /** Bodies whose id matches the filter. */
  matched: number;
  /** Matches listed (at most `max`; the selected or kept bodies listed without matching are not). */
  shown: number;
}

export function listBodies(
  ids: readonly string[],
  filter: string,
  selectedId: string | null,
  max: number,
  kept: ReadonlySet<string> = new Set(),
): BodyList {
  const needle = filter.trim().toLowerCase();
  const listed: number[] = [];
  let matched = 0;
  for (const i of naturalOrder(ids)) {
    const id = ids[i]!;
    const match = needle === "" || id.toLowerCase().includes(needle);
    if (match) matched++;
    if ((match && listed.length < max) || id === selectedId || kept.has(id)) listed.push(i);
  }
  return { listed, matched, shown: Math.min(matched, max) };
}

/** The note under the table; null when every match is listed. */
export function listNote(list: BodyList, total: number, filter: string): string | null {
  const shownMatches = list.shown;
  if (filter.trim() === "")
    return list.matched > shownMatches
      ? `Showing ${shownMatches} of ${total} bodies: filter by id to find the others.`
      : null;
  if (list.matched === 0) return `No body id contains "${filter.trim()}".`;
  return list.matched > shownMatches
    ? `Showing ${shownMatches} of ${list.matched} bodies matching "${filter.trim()}".`
    : null;
}
