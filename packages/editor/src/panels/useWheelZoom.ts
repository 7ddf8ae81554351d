/**
 * Wheel zoom over the Time slider (the element `ref` points at: the slider and its ticks): wheel up
 * zooms in, down zooms out, 4× a mouse-wheel notch, smoothly on a touchpad (store/zoomRequest.ts
 * wheelZoomFactor), around the current time, which keeps its place (the thumb does not move), as
 * the Zoom buttons do. Not around the pointer: the window always holds the current time (the guard
 * turns the page to it), so a window around a pointer far from the thumb would be turned away at
 * once; click there first (that moves the time) and then zoom.
 * The listener is not passive: a vertical wheel over the slider zooms and does not scroll the page,
 * also at the smallest span and at the whole history (the page would jump under the pointer when a
 * zoom hits its limit). A mostly horizontal wheel (a touchpad's sideways swipe) is left to the page.
 * So is a wheel that scrolls the page and passes over the slider: the wheel events that follow
 * another outside the slider by less than WHEEL_LATCH_MS are one gesture, and stay the page's (the
 * way a browser keeps a scroll gesture on the scroller it started on).
 */
import { type RefObject, useEffect } from "react";
import type { Editor } from "../editor";
import { wheelZoomFactor, zoomBy } from "../store/zoomRequest";
import { applyZoom } from "./zoomActions";

/** Zooms the editor's time window on `e`; whether the event was taken (its default to be prevented). */
export function wheelZoom(editor: Pick<Editor, "ui" | "client">, e: WheelEvent): boolean {
  if (Math.abs(e.deltaY) <= Math.abs(e.deltaX)) return false;
  const factor = wheelZoomFactor(e.deltaY, e.deltaMode);
  applyZoom(editor, (s) => zoomBy(s.w, factor, s.t, s.horizon, s.end));
  return true;
}

/** A wheel event this soon (ms) after the previous one continues its gesture (a page scroll that
 *  reaches the slider keeps scrolling). Wheel events of one gesture come every 10–50 ms; a user who
 *  stops scrolling and then zooms pauses longer. */
export const WHEEL_LATCH_MS = 300;

/** Whether a wheel event at `now` (ms) belongs to a page scroll whose last event was at `pageAt`. */
export function continuesPageScroll(now: number, pageAt: number): boolean {
  return now - pageAt < WHEEL_LATCH_MS;
}

export function useWheelZoom(editor: Editor, ref: RefObject<HTMLElement | null>): void {
  useEffect(() => {
    const el = ref.current;
    if (!el) return;
    let pageAt = Number.NEGATIVE_INFINITY;
    const onAnyWheel = (e: WheelEvent) => {
      if (!(e.target instanceof Node && el.contains(e.target))) pageAt = performance.now();
    };
    const onWheel = (e: WheelEvent) => {
      const now = performance.now();
      if (continuesPageScroll(now, pageAt)) pageAt = now;
      else if (wheelZoom(editor, e)) e.preventDefault();
    };
    window.addEventListener("wheel", onAnyWheel, { capture: true, passive: true });
    el.addEventListener("wheel", onWheel, { passive: false });
    return () => {
      window.removeEventListener("wheel", onAnyWheel, { capture: true });
      el.removeEventListener("wheel", onWheel);
    };
  }, [editor, ref]);
}
