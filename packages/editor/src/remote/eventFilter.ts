/**
 * The Event log's filter text as a test on an entry's participants. Pure.
 *
 * - One id: the entries it takes part in (a body, or a line or point: every participant counts).
 * - Ids separated by commas ("a, b", as the log's participants column writes a pair): the entries
 *   all of them take part in, e.g. every collision of one pair of discs.
 *
 * Ids may hold commas and spaces themselves, so a text that is one participant's whole id is
 * always that id, whatever it holds; only otherwise is it read as a list.
 */

/** Whether an entry with participants `ids` passes the filter text `text` (trimmed, non-empty). */
export type EventFilter = (ids: readonly string[]) => boolean;

/** The filter's parts: the comma-separated ids, trimmed, empty ones left out. */
export function filterParts(text: string): string[] {
  return text
    .split(",")
    .map((p) => p.trim())
    .filter((p) => p !== "");
}

/** The test for a filter text; null for a blank one (no filter). */
export function eventFilter(text: string): EventFilter | null {
  const whole = text.trim();
  if (whole === "") return null;
  const parts = filterParts(whole);
  if (parts.length <= 1) {
    const id = parts[0] ?? whole;
    return (ids) => ids.includes(whole) || ids.includes(id);
  }
  return (ids) => ids.includes(whole) || parts.every((p) => ids.includes(p));
}
