// @vitest-environment jsdom
/**
 * The Time slider's fast zooms: the wheel over the slider and a typed window width (from a history
 * of a billion seconds to a few seconds around the current time without 28 presses of Zoom in).
 */
import { act, cleanup, fireEvent, render, screen } from "@testing-library/react";
import { afterEach, describe, expect, it, vi } from "vitest";
import { EditorContext } from "../EditorContext";
import { cradleEditor } from "../testing/harness";
import { WHEEL_LATCH_MS } from "../wheelLatch";
import { TimePanel } from "./TimePanel";

afterEach(cleanup);

async function renderPanel() {
  const h = await cradleEditor();
  render(
    <EditorContext.Provider value={h.editor}>
      <TimePanel />
    </EditorContext.Provider>,
  );
  const slider = screen.getByRole("slider", { name: "Time" }) as HTMLInputElement;
  const width = screen.getByRole("textbox", { name: "Window width (s)" }) as HTMLInputElement;
  const time = screen.getByRole("textbox", { name: "Time (s)" }) as HTMLInputElement;
  const range = (): [number, number] => [Number(slider.min), Number(slider.max)];
  const typeWidth = (text: string) =>
    act(() => {
      width.focus();
      fireEvent.change(width, { target: { value: text } });
      fireEvent.keyDown(width, { key: "Enter" });
    });
  /** A wheel event on the slider; whether its default (scrolling the page) was left alone. */
  const wheel = (init: WheelEventInit) => {
    let notPrevented = true;
    act(() => {
      notPrevented = fireEvent.wheel(slider, init);
    });
    return notPrevented;
  };
  return { ...h, slider, width, time, range, typeWidth, wheel };
}

describe("Time slider: wheel zoom", () => {
  it("a notch up is 4x in around the time (the thumb keeps its place), down 4x out; the page does not scroll", async () => {
    const { editor, slider, range, wheel } = await renderPanel();
    act(() => editor.setTime(2.5));
    // a quarter of the way along [0, 10] -> a quarter of the way along [1.875, 4.375]
    expect(wheel({ deltaY: -100 })).toBe(false);
    expect(range()).toEqual([1.875, 4.375]);
    expect(slider.value).toBe("2.5");
    // a touchpad's small steps zoom by a little each
    wheel({ deltaY: 5 });
    const [lo, hi] = range();
    expect(hi - lo).toBeCloseTo(2.5 * 4 ** 0.05, 12);
    expect((2.5 - lo) / (hi - lo)).toBeCloseTo(0.25, 12);
    // lines (Firefox) count as a notch per 3 lines; out to the whole history, and no further
    wheel({ deltaY: 3, deltaMode: 1 });
    wheel({ deltaY: 300 });
    expect(editor.ui.getState().timeWindow).toBeNull();
    expect(wheel({ deltaY: 100 })).toBe(false);
    expect(range()).toEqual([0, 10]);
    // a sideways swipe is the page's
    expect(wheel({ deltaX: -100, deltaY: -10 })).toBe(true);
    expect(editor.ui.getState().timeWindow).toBeNull();
    // not an undo step
    expect(editor.history.getState().past).toHaveLength(0);
  });
});

describe("Time slider: a page scroll that passes over it", () => {
  it("keeps scrolling the page (no zoom) while its wheel events keep coming; a wheel after a pause zooms", async () => {
    const { editor, wheel } = await renderPanel();
    let now = 1000;
    const clock = vi.spyOn(performance, "now").mockImplementation(() => now);
    try {
      act(() => {
        fireEvent.wheel(document.body, { deltaY: 100 });
      });
      now += 40;
      expect(wheel({ deltaY: 100 })).toBe(true); // the page's: not prevented
      now += 40;
      expect(wheel({ deltaY: -100 })).toBe(true); // still the same gesture
      expect(editor.ui.getState().timeWindow).toBeNull();
      now += WHEEL_LATCH_MS;
      expect(wheel({ deltaY: -100 })).toBe(false); // a new gesture over the slider zooms
      expect(editor.ui.getState().timeWindow).not.toBeNull();
    } finally {
      clock.mockRestore();
    }
  });

  it("a wheel another zoom target took (the canvas) is not a page scroll: the slider zooms right after", async () => {
    const { editor, wheel } = await renderPanel();
    const canvas = document.body.appendChild(document.createElement("canvas"));
    const zoomCanvas = (e: WheelEvent) => e.preventDefault();
    canvas.addEventListener("wheel", zoomCanvas, { passive: false });
    let now = 1000;
    const clock = vi.spyOn(performance, "now").mockImplementation(() => now);
    try {
      act(() => {
        fireEvent.wheel(canvas, { deltaY: -100 });
      });
      now += 40;
      expect(wheel({ deltaY: -100 })).toBe(false);
      expect(editor.ui.getState().timeWindow).not.toBeNull();
    } finally {
      clock.mockRestore();
      canvas.remove();
    }
  });
});

describe("Time slider: typed window width", () => {
  it("shows the window's width and zooms in one step to a window that wide centred on the time", async () => {
    const { editor, width, time, range, typeWidth } = await renderPanel();
    expect(width.value).toBe("10");
    act(() => editor.setTime(2.5000001234));
    typeWidth("1e-6");
    const w = editor.ui.getState().timeWindow!;
    expect(w.hi - w.lo).toBeCloseTo(1e-6, 15);
    expect((w.lo + w.hi) / 2).toBeCloseTo(2.5000001234, 15);
    expect(range()).toEqual([w.lo, w.hi]);
    expect(width.value).toBe("0.000001");
    // the time to the window's precision (6 digits read 2.5)
    expect(time.value).toBe("2.5000001234");
    // near an end it is shifted inside the history
    act(() => editor.setTime(9.5));
    typeWidth("4");
    expect(range()).toEqual([6, 10]);
    expect(screen.getByRole("status", { name: "Time range shown" }).textContent).toBe("showing 6–10 s");
    // a width covering the history, or infinity, is the whole history
    typeWidth("12");
    expect(editor.ui.getState().timeWindow).toBeNull();
    typeWidth("2");
    typeWidth("∞");
    expect(editor.ui.getState().timeWindow).toBeNull();
    expect(width.value).toBe("10");
    expect(editor.history.getState().past).toHaveLength(0);
  });

  it("a slider value read just past the window's end (Chromium's 15 digits) does not turn the page", async () => {
    const { editor, slider, typeWidth } = await renderPanel();
    act(() => editor.setTime(2.5));
    typeWidth("0.001");
    const w = editor.ui.getState().timeWindow!;
    expect(w.hi).toBe(2.5004999999999997);
    // the thumb held at the end: every pointer move turned another page. (jsdom clamps a value to
    // max exactly where Chromium rounds it to 15 digits, past max: a looser max lets it through.)
    for (let i = 0; i < 3; i++) {
      slider.max = "3";
      fireEvent.change(slider, { target: { value: "2.5005" } });
    }
    expect(editor.ui.getState().timeWindow).toBe(w);
    expect(editor.ui.getState().t).toBe(w.hi);
  });

  it("refuses a width that is not a positive number, with a message, keeping the text; Escape drops it", async () => {
    const { editor, width, typeWidth } = await renderPanel();
    act(() => editor.setTime(5));
    typeWidth("2");
    const w = editor.ui.getState().timeWindow;
    expect(w).toEqual({ lo: 4, hi: 6 });
    for (const text of ["abc", "0", "-3"]) {
      typeWidth(text);
      expect(editor.ui.getState().timeWindow).toBe(w);
      expect(editor.ui.getState().message).toEqual({
        text: `Window width (s): must be a positive number of seconds (got ${text === "abc" ? '"abc"' : text})`,
        tone: "error",
      });
      // the text typed stays for correction, the refusal beside it (it was put back to the width)
      expect(width.value).toBe(text);
      expect(width.getAttribute("aria-invalid")).toBe("true");
      const beside = document.getElementById(width.getAttribute("aria-describedby") ?? "");
      expect(beside?.textContent).toBe(editor.ui.getState().message?.text);
    }
    act(() => {
      fireEvent.change(width, { target: { value: "0.5" } });
      fireEvent.keyDown(width, { key: "Escape" });
    });
    expect(width.value).toBe("2");
    act(() => fireEvent.blur(width));
    expect(editor.ui.getState().timeWindow).toBe(w);
  });

  it("a valid width clears the field's own error (it stayed after the zoom), not other messages", async () => {
    const { editor, typeWidth } = await renderPanel();
    act(() => editor.setTime(5));
    typeWidth("0");
    expect(editor.ui.getState().message?.tone).toBe("error");
    typeWidth("4");
    expect(editor.ui.getState().timeWindow).toEqual({ lo: 3, hi: 7 });
    expect(editor.ui.getState().message).toBeNull();
    // also a width that changes nothing (the same window)
    typeWidth("abc");
    typeWidth("4.0");
    expect(editor.ui.getState().message).toBeNull();
    // another field's or the editor's message is not this field's to clear
    const other = { text: "Autosave failed: the browser's storage is full", tone: "error" as const };
    act(() => editor.ui.setState({ message: other }));
    typeWidth("2");
    expect(editor.ui.getState().message).toBe(other);
  });

  it("a width below the smallest window is widened to it and says so, naming that width and why", async () => {
    const { editor, width, typeWidth } = await renderPanel();
    act(() => editor.setTime(3.3));
    typeWidth("1e-300");
    let w = editor.ui.getState().timeWindow!;
    expect(w.hi - w.lo).toBeCloseTo(1e-9, 15);
    expect(width.value).toBe("1e-9");
    expect(editor.ui.getState().message).toEqual({
      text: 'Window width (s): "1e-300" is narrower than the smallest window, 1e-9 s (a billionth of a second); the window is widened to that',
      tone: "info",
    });
    // a width the window can have: the note goes
    typeWidth("0.5");
    expect(editor.ui.getState().message).toBeNull();
    // far in the history the smallest window is 1e-12 of the time (the time's precision)
    await act(() => editor.goTo(1.23456789e8));
    typeWidth("1e-6");
    w = editor.ui.getState().timeWindow!;
    // (to the floating-point step of times near 1.2e8, 1.5e-8 s)
    expect(w.hi - w.lo).toBeCloseTo(1.23456789e-4, 8);
    expect(editor.ui.getState().message).toEqual({
      text:
        'Window width (s): "1e-6" is narrower than the smallest window at t = 1.23457e+8 s, 0.000123457 s' +
        " (the time's precision: a window spans at least 1e-12 of its time); the window is widened to that",
      tone: "info",
    });
    // the field is wide enough to show the width whole
    // (the window's ends are a floating-point step apart from its width: 0.000123456 here)
    expect(width.value).toMatch(/^0\.00012345\d$/);
    expect(width.size).toBeGreaterThan(width.value.length);
  });

  it("a history of a billion seconds: one typed width shows seconds around the time, to the digit", async () => {
    const { editor, client, time, range, typeWidth } = await renderPanel();
    await act(() => editor.goTo(1e9));
    expect(client.getSnapshot().horizon).toBe(1e9);
    act(() => editor.setTime(1e9 - 2.3456789));
    // six digits read 1e+9 for any time near the end
    expect(time.value).toBe("1e+9");
    typeWidth("4");
    const [lo, hi] = range();
    expect(lo).toBeCloseTo(1e9 - 4.3456789, 6);
    expect(hi).toBeCloseTo(1e9 - 0.3456789, 6);
    expect(time.value).toBe("999999997.6543");
    // at the end of the history the window ends there
    act(() => editor.setTime(1e9));
    expect(range()).toEqual([1e9 - 4, 1e9]);
    expect(time.value).toBe("1000000000");
  });
});
