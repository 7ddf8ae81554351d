// @vitest-environment jsdom
import { afterEach, describe, expect, it, vi } from "vitest";
import { addWheelZoom, continuesPageScroll, WHEEL_LATCH_MS } from "./wheelLatch";

let now = 1000;
const removals: (() => void)[] = [];
afterEach(() => {
  for (const remove of removals.splice(0)) remove();
  document.body.replaceChildren();
  vi.restoreAllMocks();
});

/** Two zoom targets (the slider, the canvas) on a page; each counts the wheel events it took. */
function page() {
  vi.spyOn(performance, "now").mockImplementation(() => now);
  const target = () => {
    const el = document.body.appendChild(document.createElement("div"));
    const taken: number[] = [];
    removals.push(
      addWheelZoom(el, (e) => {
        if (Math.abs(e.deltaY) <= Math.abs(e.deltaX)) return false;
        taken.push(e.deltaY);
        return true;
      }),
    );
    return { el, taken };
  };
  const text = document.body.appendChild(document.createElement("p"));
  /** A wheel event on `el` `after` ms; whether the page scrolls with it (its default left alone). */
  const wheel = (el: Element, after: number, init: WheelEventInit = { deltaY: 40 }) => {
    now += after;
    return el.dispatchEvent(new WheelEvent("wheel", { bubbles: true, cancelable: true, ...init }));
  };
  return { slider: target(), canvas: target(), text, wheel };
}

describe("wheel zoom targets and page scrolls", () => {
  it("a page scroll passing over a target goes on scrolling; a wheel after a pause zooms", () => {
    const { slider, canvas, text, wheel } = page();
    expect(wheel(text, 0)).toBe(true);
    expect(wheel(canvas.el, 30)).toBe(true);
    expect(wheel(slider.el, 30)).toBe(true);
    expect(wheel(canvas.el, WHEEL_LATCH_MS - 1)).toBe(true); // each one keeps the gesture going
    expect([slider.taken, canvas.taken]).toEqual([[], []]);
    expect(wheel(canvas.el, WHEEL_LATCH_MS)).toBe(false);
    expect(canvas.taken).toEqual([40]);
  });

  it("a wheel a target took is not a page scroll: another target zooms right after it", () => {
    const { slider, canvas, wheel } = page();
    expect(wheel(canvas.el, 0)).toBe(false);
    expect(wheel(slider.el, 30)).toBe(false);
    expect(wheel(canvas.el, 30)).toBe(false);
    expect([slider.taken, canvas.taken]).toEqual([[40], [40, 40]]);
  });

  it("an event the target leaves to the page (a sideways swipe) counts as a page scroll", () => {
    const { slider, wheel } = page();
    expect(wheel(slider.el, 0, { deltaX: 50, deltaY: 5 })).toBe(true);
    expect(wheel(slider.el, 30)).toBe(true);
    expect(slider.taken).toEqual([]);
  });

  it("the last target removed takes the window's listener with it", () => {
    const { slider, canvas, text, wheel } = page();
    const removeListener = vi.spyOn(window, "removeEventListener");
    removals.shift()!();
    expect(removeListener).not.toHaveBeenCalled();
    expect(wheel(text, 0)).toBe(true);
    expect(wheel(canvas.el, 30)).toBe(true); // still latched: the record is shared
    expect(wheel(slider.el, 30)).toBe(true); // removed: not a target
    removals.shift()!();
    expect(removeListener).toHaveBeenCalledTimes(1);
    expect(canvas.taken).toEqual([]);
  });

  it("continuesPageScroll: less than WHEEL_LATCH_MS after the page's last wheel", () => {
    expect(continuesPageScroll(1000 + WHEEL_LATCH_MS - 1, 1000)).toBe(true);
    expect(continuesPageScroll(1000 + WHEEL_LATCH_MS, 1000)).toBe(false);
    expect(continuesPageScroll(0, Number.NEGATIVE_INFINITY)).toBe(false);
  });
});
