// @vitest-environment jsdom
import { dilutedGas } from "@chapgame/engine";
import { act, cleanup, render } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { EditorContext } from "../EditorContext";
import { settled, testEditor } from "../testing/harness";
import { TimePanel } from "./TimePanel";

afterEach(cleanup);

describe("TimePanel with the time past the computed history (an undo recomputing it)", () => {
  it("says that the view shows the end of the history, and whether it is being computed", async () => {
    const h = testEditor();
    await h.editor.loadScene(dilutedGas({ n: 1500, packing: 0.1, seed: 3 }), { undoable: false });
    await settled(h.client);
    const { container } = render(
      <EditorContext.Provider value={h.editor}>
        <TimePanel />
      </EditorContext.Provider>,
    );
    const note = () => container.querySelector(".behind")?.textContent ?? null;
    expect(note()).toBeNull();
    const end = h.client.getSnapshot().horizon;
    // what a reload at a late time leaves; far enough past the end (1,000 s of a 1,500-disc gas, millions
    // of events) that the computation below cannot reach it before the note is read, however the
    // host's slices fall (at end + 5 s it sometimes had, under load, and the note was gone)
    act(() => h.editor.ui.setState({ t: end + 1000 }));
    expect(note()).toBe(` past the computed history: the view shows t = ${end} s`);
    await act(async () => {
      await h.client.compute({ time: 1e4 }); // a gas of 1,500 discs: many slices
    });
    expect(note()).toMatch(/^ computing up to t: the view shows t = .* s until then$/);
    await act(async () => {
      await h.client.cancel();
    });
  });
});
