// @vitest-environment jsdom
// Buttons that cannot act (the toolbar's Delete with nothing selected, Undo and Redo with nothing to
// take back) are greyed out with aria-disabled, not disabled: they keep the keyboard focus (a
// disabled button drops it to the page; Chromium's own check is the e2e test editor-keyboard.test.ts).
import { newtonsCradle } from "@chapgame/engine";
import { act, cleanup, fireEvent, render, screen, waitFor } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { EditorContext } from "../EditorContext";
import { settled, testEditor } from "../testing/harness";
import { SceneActions } from "./SceneActions";
import { Toolbar } from "./Toolbar";

afterEach(cleanup);

const greyed = (b: HTMLElement) =>
  b.getAttribute("aria-disabled") === "true" && !(b as HTMLButtonElement).disabled;

describe("buttons that cannot act keep the focus", () => {
  it("the toolbar's Delete: greyed out once it deleted the selection, still focused, and a press does nothing", async () => {
    const h = testEditor();
    await h.editor.loadScene(newtonsCradle(), { undoable: false });
    await settled(h.client);
    render(
      <EditorContext.Provider value={h.editor}>
        <SceneActions />
        <Toolbar />
      </EditorContext.Provider>,
    );
    const undo = screen.getByRole("button", { name: "Undo" });
    expect(greyed(undo)).toBe(true);
    expect(greyed(screen.getByRole("button", { name: "Redo" }))).toBe(true);
    act(() => h.editor.ui.setState({ selection: { kind: "body", id: "c1" } }));
    const del = screen.getByRole("button", { name: "Delete: body c1" });
    expect(greyed(del)).toBe(false);
    del.focus();
    await act(async () => fireEvent.click(del));
    await waitFor(() => expect(h.editor.ui.getState().selection).toBeNull());
    expect(greyed(del)).toBe(true);
    expect(document.activeElement).toBe(del);
    await waitFor(() => expect(greyed(undo)).toBe(false));
    const actions = h.editor.doc.actions.length;
    await act(async () => fireEvent.click(del));
    expect(h.editor.doc.actions.length).toBe(actions);
  });
});
