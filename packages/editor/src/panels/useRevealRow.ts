/**
 * Brings a table's row into view when it becomes the one to show (the selected body, selected from
 * the canvas or the Event log): the scroll box around the table (a sticky thead, rows of equal
 * height, windowed by useRowWindow) scrolls just enough for the whole row to be in view, and only
 * when `key` (the selection) changes, not on every refresh of the rows: a reader scrolling the table
 * afterwards is left alone. A key whose row is not listed yet is revealed once it is. Only the box
 * scrolls: the page does not move and the focus stays where it is.
 */
import { type RefObject, useLayoutEffect, useRef } from "react";
import type { BoxGeometry } from "./useRowWindow";

/** The scrollTop that shows row `index` whole in the box, or null when it is in view already. */
export function revealScroll(index: number, box: BoxGeometry): number | null {
  const { row, view } = box;
  if (!(row > 0) || !(view > 0) || index < 0) return null; // nothing laid out (a hidden panel, jsdom)
  return revealSpan(box.head + index * row, row, box);
}

/**
 * The scrollTop that shows whole the `height` px starting `top` px from the top of the box's content
 * (its thead included), or null when they are in view already: scrolled just enough, below the
 * sticky thead, which covers the top `head` px of the box.
 */
export function revealSpan(
  top: number,
  height: number,
  { head, view, scroll }: Pick<BoxGeometry, "head" | "view" | "scroll">,
): number | null {
  if (top < scroll + head) return Math.max(0, top - head);
  if (top + height > scroll + view) return Math.max(0, top + height - view);
  return null;
}

/** Scrolls `ref` to show row `index` (-1: not listed) when `key` changes (null: nothing to show). */
export function useRevealRow(
  ref: RefObject<HTMLElement | null>,
  key: string | null,
  index: number,
  box: BoxGeometry,
): void {
  const pending = useRef<string | null>(null);
  const last = useRef<string | null>(null);
  // no dependencies: checked on every render while a key waits for its row
  useLayoutEffect(() => {
    if (key !== last.current) {
      last.current = key;
      pending.current = key;
    }
    const el = ref.current;
    if (pending.current === null || !el || index < 0 || !(box.view > 0)) return;
    pending.current = null;
    // read now (once per selection): the focus may have just scrolled the box (a cell tabbed to)
    const to = revealScroll(index, { ...box, scroll: el.scrollTop, view: el.clientHeight });
    if (to !== null) el.scrollTop = to;
  });
}
