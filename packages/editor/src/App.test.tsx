// @vitest-environment jsdom
import { newtonsCradle } from "@chapgame/engine";
import { act, cleanup, fireEvent, render, screen, waitFor, within } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { App } from "./App";
import { EditorContext } from "./EditorContext";
import { settled, testEditor } from "./testing/harness";

afterEach(cleanup);

async function renderApp() {
  const h = testEditor();
  await h.editor.loadScene(newtonsCradle(), { undoable: false });
  await settled(h.client);
  render(
    <EditorContext.Provider value={h.editor}>
      <App />
    </EditorContext.Provider>,
  );
  const bodies = screen.getByRole("table", { name: "Bodies" });
  await waitFor(() => expect(within(bodies).getAllByRole("row").length).toBe(7));
  return { ...h, bodies };
}

describe("App", () => {
  it("Undo, Redo, Save file and Load file are in the header's Scene toolbar, before every panel", async () => {
    await renderApp();
    const bar = screen.getByRole("toolbar", { name: "Scene" });
    expect(bar.closest("header")).not.toBeNull();
    for (const name of ["Undo", "Redo", "Save file", "Load file"]) {
      const button = screen.getByRole("button", { name });
      expect(bar.contains(button)).toBe(true);
      // first in the tab order: before the Bodies table's first cell
      const cell = within(screen.getByRole("table", { name: "Bodies" })).getAllByRole("button")[0]!;
      expect(button.compareDocumentPosition(cell) & Node.DOCUMENT_POSITION_FOLLOWING).toBeTruthy();
    }
  });

  it("every control the end-to-end tests rely on has its accessible name", async () => {
    await renderApp();
    for (const name of [
      "Play",
      "−1×: play backwards",
      "Next event",
      "Previous event",
      "Undo",
      "Redo",
      "Paste",
      "Copy",
    ])
      expect(screen.getByRole("button", { name })).toBeTruthy();
    expect(screen.getByRole("slider", { name: "Time" })).toBeTruthy();
    for (const name of ["Bodies", "Lines", "Points", "Event log"])
      expect(screen.getByRole("table", { name })).toBeTruthy();
  });

  it("the Bodies table shows the state at the current time", async () => {
    const { editor, bodies } = await renderApp();
    const x = () => within(bodies).getByRole("button", { name: "striker x" }).textContent;
    expect(x()).toBe("-6");
    act(() => editor.setTime(0.25));
    await waitFor(() => expect(x()).toBe("-5"), { timeout: 4000 });
  });

  it("Play toggles to Pause, and the Time slider moves the store's time", async () => {
    const { editor } = await renderApp();
    fireEvent.click(screen.getByRole("button", { name: "Play" }));
    expect(editor.ui.getState().playing).toBe(true);
    fireEvent.click(screen.getByRole("button", { name: "Pause" }));
    expect(editor.ui.getState().playing).toBe(false);
    fireEvent.change(screen.getByRole("slider", { name: "Time" }), { target: { value: "2.5" } });
    expect(editor.ui.getState().t).toBe(2.5);
  });

  it("a broken paste shows the validation message and keeps the scene", async () => {
    const { editor, client } = await renderApp();
    const before = client.getSnapshot().doc;
    fireEvent.change(screen.getByRole("textbox", { name: "Scene JSON" }), {
      target: {
        value:
          '{"format":"chapgame","version":1,"actions":[{"time":0,"type":"addBody","id":"x","x":0,"y":0,"r":0,"m":1}]}',
      },
    });
    fireEvent.click(screen.getByRole("button", { name: "Paste" }));
    await waitFor(() => expect(screen.getByRole("alert").textContent).toContain("actions[0].r"));
    expect(client.getSnapshot().doc).toBe(before);
    expect(editor.history.getState().past.length).toBe(0);
  });
});
