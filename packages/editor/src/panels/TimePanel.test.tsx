// @vitest-environment jsdom
import { newtonsCradle } from "@chapgame/engine";
import { act, cleanup, fireEvent, render, screen, waitFor } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { EditorContext } from "../EditorContext";
import type { RequestMessage } from "../remote/protocol";
import { settled, testEditor } from "../testing/harness";
import { TimePanel } from "./TimePanel";

afterEach(cleanup);

async function renderPanel() {
  const h = testEditor();
  await h.editor.loadScene(newtonsCradle(), { undoable: false });
  await settled(h.client);
  render(
    <EditorContext.Provider value={h.editor}>
      <TimePanel />
    </EditorContext.Provider>,
  );
  const slider = screen.getByRole("slider", { name: "Time" }) as HTMLInputElement;
  const field = screen.getByRole("textbox", { name: "Time (s)" }) as HTMLInputElement;
  return { ...h, slider, field };
}

describe("TimePanel time field", () => {
  it("a time that is not a finite number leaves the time where it is and says why", async () => {
    const { editor, field } = await renderPanel();
    act(() => editor.setTime(1.25));
    for (const typed of ["abc", "1e400"]) {
      field.focus();
      fireEvent.change(field, { target: { value: typed } });
      fireEvent.keyDown(field, { key: "Enter" });
      expect(editor.ui.getState().t).toBe(1.25);
      expect(editor.ui.getState().message).toEqual({
        text: `Time (s): must be a finite number of seconds (got ${typed === "abc" ? '"abc"' : typed})`,
        tone: "error",
      });
    }
  });
});

describe("TimePanel time field, refused text", () => {
  it("keeps the text refused in the field, beside it the refusal, until corrected or dropped", async () => {
    const { editor, field } = await renderPanel();
    act(() => editor.setTime(1.25));
    field.focus();
    fireEvent.change(field, { target: { value: "2,5" } });
    fireEvent.keyDown(field, { key: "Enter" });
    const refusal = 'Time (s): must be a finite number of seconds (got "2,5")';
    // the text stays (it was replaced by the time, what the user typed lost)
    expect(field.value).toBe("2,5");
    expect(field.getAttribute("aria-invalid")).toBe("true");
    const beside = document.getElementById(field.getAttribute("aria-describedby") ?? "");
    expect(beside?.textContent).toBe(refusal);
    // the message bar shows it too, so the copy beside the field is no second alert
    expect(editor.ui.getState().message?.text).toBe(refusal);
    expect(beside?.getAttribute("role")).toBeNull();
    // the time moving (playback, the slider) leaves the text typed in place
    act(() => editor.setTime(0.5));
    expect(field.value).toBe("2,5");
    // corrected, it applies and the refusal goes, beside the field and in the message bar
    fireEvent.change(field, { target: { value: "2.5" } });
    await act(async () => {
      fireEvent.keyDown(field, { key: "Enter" });
    });
    expect(editor.ui.getState().t).toBe(2.5);
    expect(field.value).toBe("2.5");
    expect(field.getAttribute("aria-describedby")).toBeNull();
    expect(editor.ui.getState().message).toBeNull();
    // Escape drops a refused text and its refusal
    fireEvent.change(field, { target: { value: "-1" } });
    fireEvent.keyDown(field, { key: "Enter" });
    expect(editor.ui.getState().message?.text).toBe("Time (s): must be 0 or later (got -1)");
    fireEvent.keyDown(field, { key: "Escape" });
    expect(field.value).toBe("2.5");
    expect(field.getAttribute("aria-invalid")).toBe("false");
    expect(editor.ui.getState().message).toBeNull();
  });
});

describe("TimePanel time field, Escape", () => {
  it("Escape drops the typed text and shows the time again; leaving the field then changes nothing", async () => {
    const { editor, field } = await renderPanel();
    act(() => editor.setTime(1.25));
    field.focus();
    fireEvent.change(field, { target: { value: "garbage" } });
    fireEvent.keyDown(field, { key: "Escape" });
    expect(field.value).toBe("1.25");
    fireEvent.blur(field);
    expect(editor.ui.getState().message).toBeNull();
    expect(editor.ui.getState().t).toBe(1.25);
  });
});

describe("TimePanel time field, negative times", () => {
  it("a negative time is refused with a message naming the field (it went to 0 without a word)", async () => {
    const { editor, field } = await renderPanel();
    act(() => editor.setTime(1.25));
    field.focus();
    fireEvent.change(field, { target: { value: " -3 " } });
    await act(async () => {
      fireEvent.keyDown(field, { key: "Enter" });
    });
    expect(editor.ui.getState().t).toBe(1.25);
    expect(editor.ui.getState().message).toEqual({
      text: "Time (s): must be 0 or later (got -3)",
      tone: "error",
    });
    // -0 is 0.
    fireEvent.change(field, { target: { value: "-0" } });
    await act(async () => {
      fireEvent.keyDown(field, { key: "Enter" });
    });
    expect(editor.ui.getState().t).toBe(0);
  });

  it("a valid time clears the field's own error (it stayed), not another message", async () => {
    const { editor, field } = await renderPanel();
    const type = async (text: string) => {
      field.focus();
      fireEvent.change(field, { target: { value: text } });
      await act(async () => {
        fireEvent.keyDown(field, { key: "Enter" });
      });
    };
    await type("-3");
    expect(editor.ui.getState().message?.tone).toBe("error");
    await type("2");
    expect(editor.ui.getState().t).toBe(2);
    expect(editor.ui.getState().message).toBeNull();
    const other = {
      text: "Window width (s): must be a positive number of seconds (got 0)",
      tone: "error" as const,
    };
    act(() => editor.ui.setState({ message: other }));
    await type("3");
    expect(editor.ui.getState().message).toBe(other);
  });
});

describe("TimePanel", () => {
  it("paused, the slider and the time field show every time exactly and at once", async () => {
    const { editor, slider, field } = await renderPanel();
    const h = editor.client.getSnapshot().horizon;
    expect(h).toBeGreaterThan(2);
    expect(slider.max).toBe(String(h));
    for (const t of [1.25, 1.2500001, 0]) {
      act(() => editor.setTime(t));
      expect(slider.value).toBe(String(t));
      expect(field.value).toBe(String(Number(t.toPrecision(6))));
    }
  });

  it("playing, sub-pixel moves of the thumb are not written; pausing shows the exact time", async () => {
    const { editor, slider, field } = await renderPanel();
    // jsdom lays nothing out: the slider is taken as 1 px wide, so a move of less than the whole
    // horizon is sub-pixel.
    act(() => editor.ui.setState({ playing: true, t: 0.5 }));
    expect(slider.value).toBe("0");
    act(() => editor.ui.setState({ t: 0.75 }));
    expect(slider.value).toBe("0");
    await waitFor(() => expect(field.value).toBe("0.75")); // throttled, but it ends on the latest
    act(() => editor.ui.setState({ playing: false }));
    expect(slider.value).toBe("0.75");
    expect(field.value).toBe("0.75");
  });

  it("the event ticks follow a computation while progress reports keep arriving", async () => {
    const { editor, host } = await renderPanel();
    const ticks = () => [...document.querySelectorAll("svg.ticks line")].map((l) => l.getAttribute("x1"));
    await waitFor(() => expect(ticks()).toContain("100")); // the cradle's collisions at t = 1 of 10
    const handle = host.handle.bind(host);
    host.handle = (m: RequestMessage) => {
      if (m.op === "ticks") setTimeout(() => handle(m), 40);
      else handle(m);
    };
    const reports = setInterval(() => (host as unknown as { changed(d: boolean): void }).changed(false), 15);
    try {
      await act(async () => {
        await editor.loadScene(
          {
            format: "chapgame",
            version: 1,
            g: 9.81,
            gravity: [0, 0],
            actions: [
              { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, v: [1, 0] },
              { time: 0, type: "addBody", id: "b", x: 4, y: 0, r: 1, m: 1 },
            ],
          },
          { undoable: false },
        );
      });
      // a and b meet at t = 2 of a 10 s horizon
      await waitFor(() => expect(ticks()).toEqual(["0", "200"]), { timeout: 3000 });
    } finally {
      clearInterval(reports);
    }
  });

  it("an edit in the past moves the event ticks at once (they stayed stale for up to a second)", async () => {
    const { editor, slider } = await renderPanel();
    // The times the ticks stand for (their x over the slider's horizon, rounded to 1 ms).
    const ticks = () =>
      [...document.querySelectorAll("svg.ticks line")].map(
        (l) => Math.round(Number(l.getAttribute("x1")) * Number(slider.max)) / 1000,
      );
    await waitFor(() => expect(ticks()).toEqual([0, 1])); // the cradle's actions, its collisions at t = 1
    // Twice as fast, the striker meets c1 at t = 0.5; edited just after the first ticks were read.
    await act(async () => {
      expect(await editor.updateBody("striker", { v: [8, 0] })).toBeNull();
    });
    await waitFor(() => expect(ticks()).toEqual([0, 0.5]), { timeout: 400 });
  });

  it("a time typed past the horizon is computed and then shown (not cut to the horizon)", async () => {
    const { editor, field } = await renderPanel();
    expect(editor.client.getSnapshot().horizon).toBe(10);
    fireEvent.focus(field);
    fireEvent.change(field, { target: { value: "25" } });
    await act(async () => {
      fireEvent.keyDown(field, { key: "Enter" });
    });
    await waitFor(() => expect(editor.ui.getState().t).toBe(25), { timeout: 5000 });
    expect(editor.client.getSnapshot().horizon).toBeGreaterThanOrEqual(25);
  });

  it("clicking into the time field while playing and away again does not move the time back", async () => {
    const { editor, field } = await renderPanel();
    act(() => editor.ui.setState({ playing: true, t: 0.5 }));
    await waitFor(() => expect(field.value).toBe("0.5"));
    fireEvent.focus(field);
    act(() => editor.ui.setState({ t: 0.9 })); // playback goes on
    await act(async () => {
      fireEvent.blur(field);
    });
    expect(editor.ui.getState().t).toBe(0.9);
    await waitFor(() => expect(field.value).toBe("0.9"));
    fireEvent.focus(field);
    act(() => editor.ui.setState({ t: 1.3 }));
    await act(async () => {
      fireEvent.keyDown(field, { key: "Enter" });
    });
    expect(editor.ui.getState().t).toBe(1.3);
    // A typed time is gone to.
    fireEvent.change(field, { target: { value: "2" } });
    act(() => editor.ui.setState({ t: 1.6 }));
    expect(field.value).toBe("2");
    await act(async () => {
      fireEvent.blur(field);
    });
    await waitFor(() => expect(editor.ui.getState().t).toBe(2));
  });

  it("stepping past the last event says there is none instead of doing nothing", async () => {
    const { editor } = await renderPanel();
    act(() => editor.setTime(5)); // the cradle's last collisions are at t = 1
    await act(async () => {
      fireEvent.click(screen.getByRole("button", { name: "Next event" }));
    });
    await waitFor(() => expect(editor.ui.getState().message?.text).toMatch(/^No event after t = 5/));
    expect(editor.ui.getState().t).toBe(5);
  });
});

describe("TimePanel for screen readers", () => {
  it("the slider's aria-valuetext is the current time, also when playback does not move the thumb", async () => {
    const { editor, slider } = await renderPanel();
    act(() => editor.setTime(0.5));
    expect(slider.getAttribute("aria-valuetext")).toBe("t = 0.5 s");
    // while playing, a change of less than a pixel leaves the value alone (jsdom: a 1 px slider)
    act(() => editor.ui.setState({ playing: true }));
    const value = slider.value;
    act(() => editor.ui.setState({ t: 0.5001 }));
    expect(slider.value).toBe(value);
    expect(slider.getAttribute("aria-valuetext")).toBe("t = 0.5001 s");
  });

  it("the horizon is not in a live region (a computation changes it every 50 ms)", async () => {
    const { client } = await renderPanel();
    const horizon = String(client.getSnapshot().horizon);
    for (const live of document.querySelectorAll("output, [role=status], [role=log], [aria-live]")) {
      if (live.getAttribute("aria-live") === "off") continue;
      expect(live.textContent).not.toContain(horizon);
    }
  });
});
