/**
 * Whether an element's text is cut at its right edge (one line, `white-space: nowrap` and
 * `overflow: hidden` in the styles that apply): its content is wider than its box. Measured after
 * each render with `key` changed (the text shown) and whenever the element is resized (a window
 * made narrower or wider). False until measured, and where layout is not measured (jsdom: 0 = 0).
 */
import { type RefObject, useLayoutEffect, useState } from "react";

/** Pixels of width the content may exceed its box by before the text counts as cut (sub-pixel rounding). */
const CUT_SLACK_PX = 1;

export function useTextCut(ref: RefObject<HTMLElement | null>, key: unknown): boolean {
  const [cut, setCut] = useState(false);
  // biome-ignore lint/correctness/useExhaustiveDependencies: key is what to measure again after
  useLayoutEffect(() => {
    const el = ref.current;
    if (!el) {
      setCut(false);
      return;
    }
    const measure = () => setCut(el.scrollWidth > el.clientWidth + CUT_SLACK_PX);
    measure();
    const ro = typeof ResizeObserver === "undefined" ? null : new ResizeObserver(measure);
    ro?.observe(el);
    return () => ro?.disconnect();
  }, [ref, key]);
  return cut;
}
