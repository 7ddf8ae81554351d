// @vitest-environment jsdom
import { act, cleanup, fireEvent, render, screen, waitFor } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { EditorContext } from "../EditorContext";
import { cradleEditor, settled } from "../testing/harness";
import { loneDiscScene } from "../testing/scenes";
import { FileDrop } from "./FileDrop";

afterEach(cleanup);

const LONELY = JSON.stringify(loneDiscScene());

/** What a drag of these files carries (jsdom has no DataTransfer). */
const carrying = (files: File[], types = ["Files"]) => ({
  dataTransfer: { types, files, dropEffect: "none" },
});

async function setup() {
  const h = await cradleEditor();
  render(
    <EditorContext.Provider value={h.editor}>
      <FileDrop />
    </EditorContext.Provider>,
  );
  return h;
}

const indicator = () => screen.queryByRole("status", { name: "Drop indicator" });

describe("dropping a scene file", () => {
  it("shows the drop indicator while files are dragged over the page, and hides it when they leave", async () => {
    await setup();
    expect(indicator()).toBeNull();
    const files = [new File([LONELY], "lonely.json")];
    fireEvent.dragEnter(window, carrying(files));
    expect(indicator()?.textContent).toBe("Drop a scene file (.json) to open it");
    fireEvent.dragEnter(window, carrying(files)); // into a child element
    fireEvent.dragLeave(window, carrying(files)); // out of it
    expect(indicator()).not.toBeNull();
    fireEvent.dragLeave(window, carrying(files)); // out of the page
    expect(indicator()).toBeNull();
  });

  it("the indicator goes by itself when dragovers stop (a drag cancelled without a dragleave)", async () => {
    await setup();
    fireEvent.dragEnter(window, carrying([]));
    fireEvent.dragOver(window, carrying([]));
    expect(indicator()).not.toBeNull();
    await waitFor(() => expect(indicator()).toBeNull(), { timeout: 3000 });
  });

  it("a dropped scene file opens as one undo step, like Load file", async () => {
    const { editor, client } = await setup();
    fireEvent.dragEnter(window, carrying([]));
    const over = fireEvent.dragOver(window, carrying([]));
    expect(over).toBe(false); // default prevented: the browser does not open the file itself
    fireEvent.drop(window, carrying([new File([LONELY], "lonely.json")]));
    expect(indicator()).toBeNull();
    await waitFor(() =>
      expect(editor.doc.actions.map((a) => ("id" in a ? a.id : a.type))).toEqual(["lonely"]),
    );
    await settled(client);
    expect(editor.history.getState().past.length).toBe(1);
    expect(editor.ui.getState().message?.text).toBe(
      "Opened lonely.json. Undo returns to the scene you had before.",
    );
  });

  it("several files or a file of another kind are refused with a message; the scene is kept", async () => {
    const { editor } = await setup();
    const before = editor.doc;
    const scene = new File([LONELY], "lonely.json");
    act(() => void fireEvent.drop(window, carrying([scene, scene])));
    expect(editor.ui.getState().message).toEqual({
      text: "Drop one scene file at a time (2 files were dropped); nothing was opened.",
      tone: "error",
    });
    act(
      () => void fireEvent.drop(window, carrying([new File(["GIF89a"], "cat.gif", { type: "image/gif" })])),
    );
    expect(editor.ui.getState().message?.text).toMatch(/^cat\.gif: not a scene file/);
    await new Promise((r) => setTimeout(r, 20));
    expect(editor.doc).toBe(before);
  });

  it("text dragged over the page (into the Scene JSON box) is left to the browser", async () => {
    const { editor } = await setup();
    fireEvent.dragEnter(window, carrying([], ["text/plain"]));
    expect(indicator()).toBeNull();
    expect(fireEvent.dragOver(window, carrying([], ["text/plain"]))).toBe(true);
    expect(fireEvent.drop(window, carrying([], ["text/plain"]))).toBe(true);
    expect(editor.ui.getState().message).toBeNull();
  });
});
