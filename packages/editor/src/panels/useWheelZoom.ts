/**
 * Wheel zoom over the Time slider (the element `ref` points at: the slider and its ticks): wheel up
 * zooms in, down zooms out, 4× a mouse-wheel notch, smoothly on a touchpad (store/zoomRequest.ts
 * wheelZoomFactor), around the current time, which keeps its place (the thumb does not move), as
 * the Zoom buttons do, and from the history's end (zoomActions.ts: during an undo's restore, the
 * history being restored, not the restore's progress). Not around the pointer: the window always
 * holds the current time (the guard turns the page to it), so a window around a pointer far from
 * the thumb would be turned away at once; click there first (that moves the time) and then zoom.
 * The listener is not passive: a vertical wheel over the slider zooms and does not scroll the page,
 * also at the smallest span and at the whole history (the page would jump under the pointer when a
 * zoom hits its limit). A mostly horizontal wheel (a touchpad's sideways swipe) is left to the page.
 * So is a wheel that continues a page scroll passing over the slider (wheelLatch.ts, shared with the
 * scene canvas's zoom).
 */
import { type RefObject, useEffect } from "react";
import type { Editor } from "../editor";
import { wheelZoomFactor, zoomBy } from "../store/zoomRequest";
import { addWheelZoom } from "../wheelLatch";
import { applyZoom } from "./zoomActions";

/** Zooms the editor's time window on `e`; whether the event was taken (its default to be prevented). */
export function wheelZoom(editor: Pick<Editor, "ui" | "client">, e: WheelEvent): boolean {
  if (Math.abs(e.deltaY) <= Math.abs(e.deltaX)) return false;
  const factor = wheelZoomFactor(e.deltaY, e.deltaMode);
  applyZoom(editor, (s) => zoomBy(s.w, factor, s.t, s.end));
  return true;
}

export function useWheelZoom(editor: Editor, ref: RefObject<HTMLElement | null>): void {
  useEffect(() => {
    const el = ref.current;
    if (!el) return;
    return addWheelZoom(el, (e) => wheelZoom(editor, e));
  }, [editor, ref]);
}
