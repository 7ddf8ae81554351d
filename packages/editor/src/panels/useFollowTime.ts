/**
 * Keeps a time-ordered table scrolled to the current time: the first row at or after t is brought
 * near the top of the view (FOLLOW_LEAD rows of the past above it), so the events just before and
 * after the current time are what a reader sees while playing and scrubbing. A reader who scrolls
 * the table by hand takes over: following pauses for HANDS_OFF_MS after that (a click on a row
 * jumps to its time, and the view follows it).
 */
import { type RefObject, useEffect, useLayoutEffect, useRef } from "react";
import type { BoxGeometry } from "./useRowWindow";

/** Rows of the past kept in view above the first row at or after the current time. */
export const FOLLOW_LEAD = 3;
/** Milliseconds after the reader last scrolled or clicked in the table during which it is left alone. */
export const HANDS_OFF_MS = 4000;

const SCROLL_KEYS = new Set(["ArrowUp", "ArrowDown", "PageUp", "PageDown", "Home", "End"]);

/** Index of the row to scroll to the top: FOLLOW_LEAD rows before the first time >= t. */
export function followRow(times: readonly number[], t: number, lead = FOLLOW_LEAD): number {
  let k = times.findIndex((x) => x >= t);
  if (k < 0) k = times.length;
  return Math.max(0, k - lead);
}

/** Scrolls `ref` (a scroll box around a table with a sticky thead and rows of equal height). */
export function useFollowTime(
  ref: RefObject<HTMLElement | null>,
  times: readonly number[],
  t: number,
  key: unknown,
  box: BoxGeometry,
): void {
  const touched = useRef(Number.NEGATIVE_INFINITY);

  useEffect(() => {
    const el = ref.current;
    if (!el) return;
    // Scrolling by hand: the wheel, a touch, the scroll bar (a press on the box itself, not on a
    // row: a click on a row jumps to its time, which the view then follows), the scroll keys.
    const mark = (e: Event) => {
      if (e.type === "pointerdown" && e.target !== el) return;
      if (e instanceof KeyboardEvent && !SCROLL_KEYS.has(e.key)) return;
      touched.current = Date.now();
    };
    const events = ["wheel", "pointerdown", "keydown", "touchstart"] as const;
    for (const e of events) el.addEventListener(e, mark, { passive: true });
    return () => {
      for (const e of events) el.removeEventListener(e, mark);
    };
  }, [ref]);

  // biome-ignore lint/correctness/useExhaustiveDependencies: runs when the rows (key, with the time they were read around) change
  useLayoutEffect(() => {
    const el = ref.current;
    if (!el || Date.now() - touched.current < HANDS_OFF_MS) return;
    // The box as last measured by the row window (reading the DOM here would force a layout on
    // every refresh).
    const { row, head, view, scroll } = box;
    if (!(row > 0) || !(view > 0)) return; // nothing laid out (a hidden panel, jsdom)
    // Scroll only when the current row (with a row of the past above it and two of the future
    // below) has left the view: a refresh while playing then seldom scrolls, and each scroll costs
    // a second render of the windowed rows.
    const first = followRow(times, t, 0);
    const from = scroll / row;
    if (first - 1 >= from && first + 2 <= from + (view - head) / row) return;
    el.scrollTop = followRow(times, t) * row;
  }, [key]);
}
