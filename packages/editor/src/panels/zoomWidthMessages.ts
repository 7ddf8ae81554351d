/**
 * The messages of the Time panel's window width field (ZoomWidthField), each starting with the
 * field's label: a refused width (not a positive number of seconds), and a note when a typed width
 * is narrower than the smallest window at the current time and is widened to it (it was changed
 * without a word: 1e-6 at t ≈ 1.2e8 gave 0.000123 s). `messageAfterWidth` is the message once a
 * width is applied: that note, or none in place of the field's own earlier message (fieldMessages.ts:
 * an error left after a valid width was still shown next to the zoom it made); another message
 * stays. Pure.
 */

import type { Message } from "../store/uiStore";
import { smallestSpanAt } from "../store/zoomRequest";
import { formatNumber } from "./EditableCell";
import { afterFieldApplied, isFieldMessage } from "./fieldMessages";
import { refusedTyped } from "./typedRefusal";

export const WIDTH_LABEL = "Window width (s)";

/** Whether `m` is one of this field's messages. */
export function isWidthMessage(m: Message | null): boolean {
  return isFieldMessage(m, WIDTH_LABEL);
}

/** The refusal of typed text that is not a positive number of seconds. */
export function refusedWidth(typed: string): string {
  return refusedTyped(WIDTH_LABEL, "must be a positive number of seconds", typed);
}

/**
 * The note for a typed width `span` (typed as `typed`) at time t in a history ending at `end`: null
 * when the window can be that narrow there; otherwise it names the smallest width and why: a
 * billionth of a second, or the time's precision (a window spans at least 1e-12 of its time).
 */
export function narrowedWidth(typed: string, span: number, t: number, end: number): Message | null {
  const least = smallestSpanAt(span, t, end);
  if (!(span < least)) return null;
  const w = formatNumber(least);
  const text =
    least > 1e-9
      ? `${WIDTH_LABEL}: "${typed}" is narrower than the smallest window at t = ${formatNumber(t)} s, ${w} s` +
        ` (the time's precision: a window spans at least 1e-12 of its time); the window is widened to that`
      : `${WIDTH_LABEL}: "${typed}" is narrower than the smallest window, ${w} s (a billionth of a second); the window is widened to that`;
  return { text, tone: "info" };
}

/** The message once a typed width is applied, `current` being the message shown before. */
export function messageAfterWidth(
  current: Message | null,
  typed: string,
  span: number,
  t: number,
  end: number,
): Message | null {
  return narrowedWidth(typed, span, t, end) ?? afterFieldApplied(current, WIDTH_LABEL);
}
