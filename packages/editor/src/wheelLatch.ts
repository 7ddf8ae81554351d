/**
 * Wheel zoom targets that leave a page scroll alone (the Time slider, useWheelZoom; the scene
 * canvas, SceneCanvas): a wheel event over a target zooms it (its default, scrolling the page, is
 * prevented), unless it continues a page scroll: wheel events less than WHEEL_LATCH_MS after one the
 * page scrolled with are one gesture and stay the page's, the way a browser keeps a scroll gesture on
 * the scroller it started on (at 390 px the canvas and the slider fill the screen: a scroll that
 * reached them stopped there). Only events the page scrolled with count (their default not prevented
 * by the time they reach the window): a wheel a zoom target took is not a page scroll, so a wheel over
 * the slider right after zooming the canvas zooms the slider.
 * The targets of one window share its record of page scrolls (one passive listener on the window,
 * removed with the last target).
 */

/** A wheel event this soon (ms) after the previous page scroll's continues that gesture. Wheel events
 *  of one gesture come every 10–50 ms; a user who stops scrolling and then zooms pauses longer. */
export const WHEEL_LATCH_MS = 300;

/** Whether a wheel event at `now` (ms) belongs to a page scroll whose last event was at `pageAt`. */
export function continuesPageScroll(now: number, pageAt: number): boolean {
  return now - pageAt < WHEEL_LATCH_MS;
}

/** A window's record of page scrolls: when the last wheel event the page scrolled with came. */
interface PageScrolls {
  at: number;
  targets: number;
  listener: (e: WheelEvent) => void;
}

const windows = new WeakMap<Window, PageScrolls>();

/**
 * Makes `el` a wheel zoom target: `zoom(e)` gets each wheel event over it that does not continue a
 * page scroll and says whether it took it (its default is then prevented: the page does not scroll).
 * Returns the removal.
 */
export function addWheelZoom(el: HTMLElement, zoom: (e: WheelEvent) => boolean): () => void {
  const win = el.ownerDocument.defaultView ?? window;
  let page = windows.get(win);
  if (page === undefined) {
    const p: PageScrolls = {
      at: Number.NEGATIVE_INFINITY,
      targets: 0,
      // at the bubbling end, after the targets: their preventDefault says the page did not scroll
      listener: (e) => {
        if (!e.defaultPrevented) p.at = performance.now();
      },
    };
    win.addEventListener("wheel", p.listener, { passive: true });
    windows.set(win, p);
    page = p;
  }
  const shared = page;
  shared.targets++;
  const onWheel = (e: WheelEvent) => {
    if (continuesPageScroll(performance.now(), shared.at)) return; // the page's (recorded at the window)
    if (zoom(e)) e.preventDefault();
  };
  el.addEventListener("wheel", onWheel, { passive: false });
  let removed = false;
  return () => {
    if (removed) return;
    removed = true;
    el.removeEventListener("wheel", onWheel);
    if (--shared.targets > 0) return;
    win.removeEventListener("wheel", shared.listener);
    windows.delete(win);
  };
}
