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
    // the slow test host computes one event per round of slices, whatever the machine's load, so
    // the computation below is still far from the view's time when the note is read
    const h = testEditor({ slow: true });
    await h.editor.loadScene(dilutedGas({ n: 40, packing: 0.1, seed: 3 }), { undoable: false });
    await settled(h.client);
    const { container } = render(
      <EditorContext.Provider value={h.editor}>
        <TimePanel />
      </EditorContext.Provider>,
    );
    const note = () => container.querySelector(".behind")?.textContent ?? null;
    expect(note()).toBeNull();
    const end = h.client.getSnapshot().horizon;
    act(() => h.editor.ui.setState({ t: end + 5 })); // what a reload at a late time leaves
    expect(note()).toBe(` past the computed history: the view shows t = ${end} s`);
    await act(async () => {
      await h.client.compute({ time: 1e4 });
    });
    expect(note()).toMatch(/^ computing up to t: the view shows t = .* s until then$/);
    await act(async () => {
      await h.client.cancel();
    });
  });
});
