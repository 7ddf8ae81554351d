/**
 * Brings a table cell's open field back into its table's view when a key is typed into it. The row
 * of an open cell stays rendered, and its field keeps the focus, when the table is scrolled far
 * away (useHeldRows.ts): the keys then went to a field the author could not see, its refusal
 * hidden with it. Contract: `revealField(field)` scrolls the field's scroll box (`.table-scroll`,
 * whose table has a sticky thead) just enough for the field's row to be whole in view below the
 * thead (revealSpan), before the key lands; a row in view already, a field outside a table's box
 * (the Globals panel) or nothing laid out (jsdom, a hidden panel) moves nothing. Only the box
 * scrolls, as for a selected row (useRevealRow.ts): the page stays. Keys that type nothing alone
 * (Shift, Control, …: held for a shortcut or a capital) reveal nothing.
 */
import { revealSpan } from "./useRevealRow";

/** Keys that only modify the next one: pressed alone they change nothing in the field. */
const MODIFIER_KEYS = new Set(["Shift", "Control", "Alt", "AltGraph", "Meta", "CapsLock", "Fn", "OS"]);

/** Whether a keydown of `key` in an open field should bring it into view first. */
export function revealsField(key: string): boolean {
  return !MODIFIER_KEYS.has(key);
}

/** Scrolls the table box around `field` to show its row whole (see the header). */
export function revealField(field: HTMLElement): void {
  const box = field.closest<HTMLElement>(".table-scroll");
  if (!box) return;
  const b = box.getBoundingClientRect();
  if (!(b.height > 0)) return; // nothing laid out
  const row = (field.closest("tr") ?? field).getBoundingClientRect();
  const head = box.querySelector("thead")?.getBoundingClientRect().height ?? 0;
  const contentTop = b.top + box.clientTop - box.scrollTop;
  const to = revealSpan(row.top - contentTop, row.height, {
    head,
    view: box.clientHeight,
    scroll: box.scrollTop,
  });
  if (to !== null) box.scrollTop = to;
}
