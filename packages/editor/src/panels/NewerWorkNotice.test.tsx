// @vitest-environment jsdom
import { act, cleanup, fireEvent, render, screen, waitFor } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { writeSlot } from "../doc/autosaveSlots";
import { sceneText } from "../doc/sceneIo";
import { EditorContext } from "../EditorContext";
import { cradleEditor, settled } from "../testing/harness";
import { loneDiscScene } from "../testing/scenes";
import { NewerWorkNotice } from "./NewerWorkNotice";

afterEach(() => {
  cleanup();
  localStorage.clear();
});

const LONELY = loneDiscScene();

async function setup() {
  const h = await cradleEditor();
  render(
    <EditorContext.Provider value={h.editor}>
      <NewerWorkNotice />
    </EditorContext.Provider>,
  );
  return h;
}

const notice = () => screen.queryByRole("status", { name: "Newer work in another tab" });

describe("newer work notice", () => {
  it("is shown only while another tab's newer work is known; Dismiss hides it", async () => {
    const { editor } = await setup();
    expect(notice()).toBeNull();
    act(() => editor.ui.setState({ newerWork: { tab: "other", savedAt: Date.UTC(2026, 0, 1, 12) } }));
    expect(notice()?.textContent).toMatch(/^Another editor tab saved a newer scene at /);
    fireEvent.click(screen.getByRole("button", { name: "Dismiss" }));
    expect(notice()).toBeNull();
    expect(editor.ui.getState().newerWork).toBeNull();
  });

  it("Open it loads that tab's scene as one undo step", async () => {
    const { editor, client } = await setup();
    writeSlot(localStorage, "other", sceneText(LONELY), 5);
    act(() => editor.ui.setState({ newerWork: { tab: "other", savedAt: 5 } }));
    fireEvent.click(screen.getByRole("button", { name: "Open it" }));
    await waitFor(() => expect(editor.doc.actions.length).toBe(1));
    await settled(client);
    expect(notice()).toBeNull();
    expect(editor.history.getState().past.length).toBe(1);
  });
});
