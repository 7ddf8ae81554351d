// @vitest-environment jsdom
import { act, cleanup, fireEvent, render, screen, waitFor } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { EditorContext } from "../EditorContext";
import { cradleEditor } from "../testing/harness";
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
  const button = (name: string) => screen.getByRole("button", { name }) as HTMLButtonElement;
  const click = (name: string) => act(() => fireEvent.click(button(name)));
  const range = () => [slider.min, slider.max];
  const shown = () => screen.queryByRole("status", { name: "Time range shown" })?.textContent ?? null;
  /** Whether the button is shown as unavailable (aria-disabled; it stays focusable). */
  const off = (name: string) => button(name).getAttribute("aria-disabled") === "true";
  return { ...h, slider, button, click, range, shown, off };
}

describe("Time slider zoom", () => {
  it("Zoom in, Zoom out and Whole history set the slider's range; the time stays exact", async () => {
    const { editor, slider, click, range, shown, off } = await renderPanel();
    expect(editor.client.getSnapshot().horizon).toBe(10);
    expect(range()).toEqual(["0", "10"]);
    expect(shown()).toBeNull();
    expect(off("Zoom out")).toBe(true);
    expect(off("Whole history")).toBe(true);
    act(() => editor.setTime(2.5));
    // half the span, the time keeping its place (a quarter of the way along)
    click("Zoom in");
    expect(range()).toEqual(["1.25", "6.25"]);
    expect(slider.value).toBe("2.5");
    expect(shown()).toBe("showing 1.25–6.25 s");
    click("Zoom in");
    expect(range()).toEqual(["1.875", "4.375"]);
    // every time exactly, on the slider and from it
    act(() => editor.setTime(2.5000001));
    expect(slider.value).toBe("2.5000001");
    fireEvent.change(slider, { target: { value: "3.3000001" } });
    expect(editor.ui.getState().t).toBe(3.3000001);
    // a time past the window turns the page: same span, from where the window ended
    act(() => editor.setTime(5));
    expect(range()).toEqual(["4.375", "6.875"]);
    expect(slider.value).toBe("5");
    expect(shown()).toBe("showing 4.375–6.875 s");
    // twice the span around the time, up to the whole history
    click("Zoom out");
    expect(range()).toEqual(["3.75", "8.75"]);
    click("Zoom out");
    expect(range()).toEqual(["0", "10"]);
    expect(editor.ui.getState().timeWindow).toBeNull();
    expect(off("Zoom out")).toBe(true);
    // an unavailable button does nothing
    click("Zoom out");
    expect(editor.ui.getState().timeWindow).toBeNull();
    click("Zoom in");
    click("Zoom in");
    expect(off("Whole history")).toBe(false);
    click("Whole history");
    expect(range()).toEqual(["0", "10"]);
    expect(slider.value).toBe("5");
    expect(shown()).toBeNull();
    // not an undo step
    expect(editor.history.getState().past).toHaveLength(0);
  });

  it("a zoom button that becomes unavailable keeps the keyboard focus (it is aria-disabled, not disabled)", async () => {
    const { editor, button, off } = await renderPanel();
    act(() => editor.setTime(2.5));
    // Enter on the focused Zoom in until the smallest span (a billionth of a second of 10 s)
    const zoomInButton = button("Zoom in");
    zoomInButton.focus();
    let presses = 0;
    while (!off("Zoom in") && presses < 100) {
      act(() => fireEvent.click(document.activeElement!));
      presses++;
    }
    expect(presses).toBe(33);
    const smallest = editor.ui.getState().timeWindow!;
    expect(smallest.hi - smallest.lo).toBeLessThan(2e-9);
    // a disabled button loses the focus in a browser (jsdom does not do that, so: not disabled)
    expect(zoomInButton.disabled).toBe(false);
    expect(document.activeElement).toBe(zoomInButton);
    act(() => fireEvent.click(zoomInButton));
    expect(editor.ui.getState().timeWindow).toBe(smallest);
    // Whole history makes itself and Zoom out unavailable: the focus stays on it
    const whole = button("Whole history");
    whole.focus();
    act(() => fireEvent.click(whole));
    expect(editor.ui.getState().timeWindow).toBeNull();
    expect(off("Whole history")).toBe(true);
    expect(off("Zoom out")).toBe(true);
    expect(whole.disabled).toBe(false);
    expect(button("Zoom out").disabled).toBe(false);
    expect(document.activeElement).toBe(whole);
  });

  it("zoomed, the slider's arrow and page keys move the time on past the window's edges, turning the page", async () => {
    const { editor, slider, click, range } = await renderPanel();
    const key = (k: string) => {
      let handled = false;
      act(() => {
        handled = !fireEvent.keyDown(slider, { key: k });
      });
      return handled;
    };
    const t = () => editor.ui.getState().t;
    // the whole history: the input's own keys (its ends are the history's)
    expect(key("ArrowRight")).toBe(false);
    act(() => editor.setTime(5));
    click("Zoom in");
    click("Zoom in");
    expect(range()).toEqual(["3.75", "6.25"]);
    // a hundredth of the window's span
    expect(key("ArrowRight")).toBe(true);
    expect(t()).toBeCloseTo(5.025, 12);
    // on past the right edge: the next page, the time just past its start
    act(() => editor.setTime(6.25));
    expect(key("ArrowRight")).toBe(true);
    expect(range()).toEqual(["6.25", "8.75"]);
    expect(t()).toBeCloseTo(6.275, 12);
    expect(slider.value).toBe(String(t()));
    // back past the left edge, and a page key's tenth
    expect(key("ArrowLeft")).toBe(true);
    expect(key("ArrowLeft")).toBe(true);
    expect(t()).toBeCloseTo(6.225, 12);
    expect(range()).toEqual(["3.75", "6.25"]);
    act(() => editor.setTime(3.75));
    expect(key("PageDown")).toBe(true);
    expect(t()).toBe(3.5);
    expect(range()).toEqual(["1.25", "3.75"]);
    // Home and End stay the input's (the window's ends); the history's end holds the time
    expect(key("Home")).toBe(false);
    act(() => editor.setTime(10));
    expect(key("PageUp")).toBe(true);
    expect(t()).toBe(10);
    // not an undo step
    expect(editor.history.getState().past).toHaveLength(0);
  });

  it("the event ticks are those of the window, placed on it", async () => {
    const { editor, click } = await renderPanel();
    const ticks = () => [...document.querySelectorAll("svg.ticks line")].map((l) => l.getAttribute("x1"));
    // the cradle's actions at 0 and its collisions at t = 1 of a 10 s horizon
    await waitFor(() => expect(ticks()).toEqual(["0", "100"]));
    act(() => editor.setTime(1));
    click("Zoom in");
    click("Zoom in");
    click("Zoom in");
    expect(editor.ui.getState().timeWindow).toEqual({ lo: 0.875, hi: 2.125 });
    // t = 1 is a tenth of the way along [0.875, 2.125]; the actions at 0 are outside it
    await waitFor(() => expect(ticks()).toEqual(["100"]));
  });

  it("playing, the thumb turns to the next page at the window's end (the new range is always written)", async () => {
    const { editor, slider, click, range } = await renderPanel();
    act(() => editor.setTime(2));
    click("Zoom in"); // [1, 6]
    act(() => editor.ui.setState({ playing: true, t: 2.5 }));
    // jsdom lays nothing out: the slider is taken as 1 px wide, every move inside the window is sub-pixel
    expect(slider.value).toBe("2");
    act(() => editor.ui.setState({ t: 6.5 }));
    // playing into the computation (auto-extend): the whole next page, its end computed as time runs
    expect(range()).toEqual(["6", "11"]);
    expect(slider.value).toBe("6.5");
    // with auto-extend off the history ends at 10: [6, 11] is shifted back inside it
    act(() => editor.ui.setState({ t: 2.5, timeWindow: { lo: 1, hi: 6 } }));
    act(() => editor.ui.setState({ calc: { ...editor.ui.getState().calc, autoExtend: false } }));
    act(() => editor.ui.setState({ t: 6.5 }));
    expect(range()).toEqual(["5", "10"]);
    expect(slider.value).toBe("6.5");
  });
});
