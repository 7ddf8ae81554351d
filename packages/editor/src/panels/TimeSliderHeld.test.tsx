// @vitest-environment jsdom
/**
 * The Time slider while the time is held past the horizon (an edit in the past or an undo: the
 * history is computed again, the thumb at the recomputation's progress): a click on the slider past
 * the progress holds the time there, and the change event that follows (Chromium fires one on
 * letting go) does not move it back to the progress. jsdom keeps a range input's value as written;
 * Chromium keeps about 15 significant digits, which React took for a change by the user: the
 * input's value getter is made to do the same here.
 */
import { act, cleanup, fireEvent, render, screen } from "@testing-library/react";
import { afterAll, afterEach, beforeAll, describe, expect, it } from "vitest";
import { EditorContext } from "../EditorContext";
import type { TimelineClient } from "../remote/client";
import type { HostMessage } from "../remote/protocol";
import { cradleEditor } from "../testing/harness";
import { TimePanel } from "./TimePanel";

afterEach(cleanup);

const proto = HTMLInputElement.prototype;
const value = Object.getOwnPropertyDescriptor(proto, "value")!;
beforeAll(() => {
  Object.defineProperty(proto, "value", {
    ...value,
    get(this: HTMLInputElement) {
      const v = value.get!.call(this) as string;
      return this.type === "range" && v !== "" ? String(Number(Number(v).toPrecision(15))) : v;
    },
  });
});
afterAll(() => {
  Object.defineProperty(proto, "value", value);
});

/** The client told (as by its host) that the history is at `horizon`, recomputing it up to `target`. */
function hostSays(client: TimelineClient, horizon: number, target: number) {
  const info = {
    ...client.getSnapshot(),
    horizon,
    computing: { events: 0, targetEvents: null, targetTime: target, startHorizon: 0, restore: true },
  };
  const receive = (client as unknown as { receive(m: HostMessage): void }).receive.bind(client);
  act(() => receive({ type: "info", info }));
}

describe("Time slider with the time held past the horizon", () => {
  it("a click past the recomputation's progress holds the time there (it went back to the progress)", async () => {
    const h = await cradleEditor();
    render(
      <EditorContext.Provider value={h.editor}>
        <TimePanel />
      </EditorContext.Provider>,
    );
    act(() => h.editor.setTime(8));
    // a progress that takes 17 digits to write: Chromium reads it back with 15
    hostSays(h.client, 1.2345678901234567, 10);
    const slider = screen.getByRole("slider", { name: "Time" }) as HTMLInputElement;
    expect(Number(slider.value)).toBeCloseTo(1.2345678901234567, 12);
    // the click: Chromium moves the value under the pointer and fires input, then change on letting go
    act(() => {
      fireEvent.input(slider, { target: { value: "9" } });
    });
    expect(h.editor.ui.getState().t).toBe(9);
    // the recomputation goes on before the pointer is let go: the thumb follows it
    hostSays(h.client, 3.0000000000000004, 10);
    expect(Number(slider.value)).toBeCloseTo(3, 12);
    act(() => {
      fireEvent.change(slider);
    });
    expect(h.editor.ui.getState().t).toBe(9);
    // a click without the recomputation moving: the thumb goes back to the progress at once, the time held
    act(() => {
      fireEvent.input(slider, { target: { value: "7" } });
    });
    expect(h.editor.ui.getState().t).toBe(7);
    expect(Number(slider.value)).toBeCloseTo(3, 12);
    act(() => {
      fireEvent.change(slider);
    });
    expect(h.editor.ui.getState().t).toBe(7);
    // a move of the thumb by the user is a change of the time
    act(() => {
      fireEvent.input(slider, { target: { value: "2.5" } });
    });
    expect(h.editor.ui.getState().t).toBe(2.5);
  });
});
