/** Fresh ids for new bodies, lines and points: `prefix` + the smallest number not yet used. */
import type { Action } from "../engineTypes";

export function nextFreeId(prefix: string, live: readonly string[], actions: readonly Action[]): string {
  const used = new Set(live);
  for (const a of actions) if ("id" in a) used.add(a.id);
  for (let n = 1; ; n++) {
    const id = `${prefix}${n}`;
    if (!used.has(id)) return id;
  }
}
