// @vitest-environment jsdom
/**
 * The Time slider's zoom while an undo's restore runs (the history the user had is computed again
 * from an earlier time, in slices, the time held where it was): the whole history, the zoom steps
 * and the window's width are those of the history being restored (timeWindowGuard's historyEnd),
 * not of the restore's progress (the horizon).
 */
import { act, cleanup, fireEvent, render, screen } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { EditorContext } from "../EditorContext";
import type { TimelineClient } from "../remote/client";
import type { HostMessage } from "../remote/protocol";
import { cradleEditor } from "../testing/harness";
import { TimePanel } from "./TimePanel";

afterEach(cleanup);

/** The client told (as by its host) that the history is at `horizon`, restoring up to `target` (null: done). */
function hostSays(client: TimelineClient, horizon: number, target: number | null) {
  const info = {
    ...client.getSnapshot(),
    horizon,
    computing:
      target === null
        ? null
        : { events: 0, targetEvents: null, targetTime: target, startHorizon: 0, restore: true },
  };
  const receive = (client as unknown as { receive(m: HostMessage): void }).receive.bind(client);
  act(() => receive({ type: "info", info }));
}

async function restoring() {
  const h = await cradleEditor();
  render(
    <EditorContext.Provider value={h.editor}>
      <TimePanel />
    </EditorContext.Provider>,
  );
  expect(h.client.getSnapshot().horizon).toBe(10);
  act(() => h.editor.setTime(8));
  // an undo: the history is computed again from 0 up to 10, the time held at 8; the restore is at 2 s
  hostSays(h.client, 2, 10);
  act(() => h.editor.ui.setState({ t: 8 }));
  const slider = screen.getByRole("slider", { name: "Time" }) as HTMLInputElement;
  const width = screen.getByRole("textbox", { name: "Window width (s)" }) as HTMLInputElement;
  const button = (name: string) => screen.getByRole("button", { name }) as HTMLButtonElement;
  return { ...h, slider, width, button };
}

describe("Time slider zoom during an undo's restore", () => {
  it("the whole history is the history being restored, not the restore's progress", async () => {
    const { client, slider, width } = await restoring();
    expect([slider.min, slider.max]).toEqual(["0", "10"]);
    expect(width.value).toBe("10");
    hostSays(client, 10, null);
    expect([slider.min, slider.max]).toEqual(["0", "10"]);
  });

  it("Zoom in halves the history being restored, around the time", async () => {
    const { editor, button, width } = await restoring();
    act(() => fireEvent.click(button("Zoom in")));
    // 8 is 4/5 of the way along [0, 10]: 4/5 of the way along a 5 s window (not along [0, 2])
    expect(editor.ui.getState().timeWindow).toEqual({ lo: 4, hi: 9 });
    expect(width.value).toBe("5");
  });

  it("a wheel notch zooms 4x in from the history being restored", async () => {
    const { editor, slider } = await restoring();
    act(() => {
      fireEvent.wheel(slider, { deltaY: -100 });
    });
    expect(editor.ui.getState().timeWindow).toEqual({ lo: 6, hi: 8.5 });
  });
});
