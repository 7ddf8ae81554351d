// @vitest-environment jsdom
// Deleting from the keyboard (audit of session 20): a row's ✕ passes the focus to the next row's ✕
// (it fell to the page, and the next Tab started at the top), and the toolbar's Delete names what it
// removes (reached by Shift+Tab through the table, whose rows select their object on focus, it
// removed another body than the one chosen).
import { act, cleanup, fireEvent, render, screen, waitFor, within } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { EditorContext } from "../EditorContext";
import { settled, testEditor } from "../testing/harness";
import { discsInRow, sceneOf } from "../testing/scenes";
import { BodiesTable } from "./BodiesTable";
import { Toolbar } from "./Toolbar";

afterEach(cleanup);

async function threeBodies() {
  const h = testEditor();
  await h.editor.loadScene(sceneOf(discsInRow(["b1", "b2", "b3"])), { undoable: false });
  await settled(h.client);
  render(
    <EditorContext.Provider value={h.editor}>
      <Toolbar />
      <BodiesTable />
    </EditorContext.Provider>,
  );
  const table = screen.getByRole("table", { name: "Bodies" });
  await within(table).findByRole("button", { name: "Delete b3" });
  return { h, table };
}

describe("deleting from the keyboard", () => {
  it("a row's ✕ hands the focus to the next row's ✕, and the last one's to the row before", async () => {
    const { h, table } = await threeBodies();
    const del = (id: string) => within(table).getByRole("button", { name: `Delete ${id}` });
    act(() => del("b2").focus());
    fireEvent.click(del("b2"));
    await waitFor(() => expect(within(table).queryByRole("button", { name: "Delete b2" })).toBeNull());
    await waitFor(() => expect(document.activeElement).toBe(del("b3")));
    fireEvent.click(del("b3"));
    await waitFor(() => expect(document.activeElement).toBe(del("b1")));
    expect(h.editor.history.getState().past).toHaveLength(2);
  });

  it("the toolbar's Delete names the selected object", async () => {
    const { h } = await threeBodies();
    const tools = screen.getByRole("toolbar", { name: "Tools" });
    // greyed out with aria-disabled (it keeps the keyboard focus: FocusKeptButton)
    expect(within(tools).getByRole("button", { name: "Delete" }).getAttribute("aria-disabled")).toBe("true");
    act(() => h.editor.ui.setState({ selection: { kind: "body", id: "b2" } }));
    expect(
      within(tools).getByRole("button", { name: "Delete: body b2" }).getAttribute("aria-disabled"),
    ).toBeNull();
  });
});
