/**
 * Where the keyboard focus goes after an Event-log entry's ✕ removed its action (the button it was
 * on may be gone, and focus would fall to the page): to the ✕ of the next action entry the log shows,
 * else of the previous one, else to the log itself. Pure: given the index the removed action had in
 * the scene's action list (sorted by time, as the log lists its action entries) and the action indices
 * of the entries the log now shows (after the removal: the action that followed the removed one now
 * has its index), the index whose ✕ takes the focus, or null for the log.
 */
export function focusAfterRemoval(removed: number, shown: readonly number[]): number | null {
  let next: number | null = null;
  let previous: number | null = null;
  for (const i of shown) {
    if (i >= removed && (next === null || i < next)) next = i;
    if (i < removed && (previous === null || i > previous)) previous = i;
  }
  return next ?? previous;
}
