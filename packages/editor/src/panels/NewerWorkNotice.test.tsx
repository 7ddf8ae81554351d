// @vitest-environment jsdom
import { newtonsCradle } from "@chapgame/engine";
import { act, cleanup, fireEvent, render, screen, waitFor } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { writeSlot } from "../doc/autosaveSlots";
import { sceneText } from "../doc/sceneIo";
import { EditorContext } from "../EditorContext";
import { settled, testEditor } from "../testing/harness";
import { NewerWorkNotice } from "./NewerWorkNotice";

afterEach(() => {
  cleanup();
  localStorage.clear();
});

const LONELY = {
  format: "chapgame" as const,
  version: 1 as const,
  g: 9.81,
  gravity: [0, 0] as [number, number],
  actions: [
    {
      time: 0,
      type: "addBody" as const,
      id: "lonely",
      x: 0,
      y: 0,
      r: 1,
      m: 1,
      mu: 0,
      v: [0, 0] as [number, number],
    },
  ],
};

async function setup() {
  const h = testEditor();
  await h.editor.loadScene(newtonsCradle(), { undoable: false });
  await settled(h.client);
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
