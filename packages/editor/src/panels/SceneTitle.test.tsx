// @vitest-environment jsdom
// The header's Title field: shows meta.title, applies typed text on Enter or leaving it, Escape
// drops it; its tooltip says the file name Save file suggests.
import { newtonsCradle } from "@chapgame/engine";
import { act, cleanup, fireEvent, render, screen, waitFor } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { EditorContext } from "../EditorContext";
import { settled, testEditor } from "../testing/harness";
import { SceneTitle } from "./SceneTitle";

afterEach(cleanup);

async function renderTitle() {
  const h = testEditor();
  await h.editor.loadScene(
    { ...newtonsCradle(), meta: { title: "Cradle" } },
    { undoable: false, name: "newtons-cradle.chapgame.json", preset: true },
  );
  await settled(h.client);
  render(
    <EditorContext.Provider value={h.editor}>
      <SceneTitle />
    </EditorContext.Provider>,
  );
  return { ...h, field: screen.getByRole("textbox", { name: "Scene title" }) as HTMLInputElement };
}

describe("SceneTitle", () => {
  it("shows the scene's title and applies a typed one on Enter; the tooltip follows the name", async () => {
    const { editor, field } = await renderTitle();
    expect(field.value).toBe("Cradle");
    expect(field.title).toBe("Save file suggests newtons-cradle.chapgame.json");
    fireEvent.change(field, { target: { value: "Five balls" } });
    await act(async () => {
      fireEvent.keyDown(field, { key: "Enter" });
    });
    await waitFor(() => expect(editor.doc.meta).toEqual({ title: "Five balls" }));
    await waitFor(() => expect(field.title).toBe("Save file suggests five-balls.chapgame.json"));
    expect(field.value).toBe("Five balls");
    // Undo brings the title back into the field
    await act(() => editor.undo());
    await waitFor(() => expect(field.value).toBe("Cradle"));
  });

  it("a title that is not text is not shown, and the field says one is there", async () => {
    const h = testEditor();
    await h.editor.loadScene({ ...newtonsCradle(), meta: { title: 7 } }, { undoable: false });
    await settled(h.client);
    render(
      <EditorContext.Provider value={h.editor}>
        <SceneTitle />
      </EditorContext.Provider>,
    );
    const field = screen.getByRole("textbox", { name: "Scene title" }) as HTMLInputElement;
    expect(field.value).toBe("");
    expect(field.placeholder).toBe("the file's title is not text");
  });

  it("Escape drops the text typed; leaving the field then changes nothing", async () => {
    const { editor, field } = await renderTitle();
    fireEvent.change(field, { target: { value: "Other" } });
    fireEvent.keyDown(field, { key: "Escape" });
    expect(field.value).toBe("Cradle");
    await act(async () => {
      fireEvent.blur(field);
    });
    expect(editor.history.getState().past.length).toBe(0);
    expect(editor.doc.meta).toEqual({ title: "Cradle" });
  });
});
