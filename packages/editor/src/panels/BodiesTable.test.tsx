// @vitest-environment jsdom
// Editing a Bodies cell while playing: opening the cell pauses playback, so the edit applies at the
// time whose values the table shows, and a vx edit keeps the vy of that time (it once kept playing:
// the action was stamped later than the values it was built from, up to a table refresh late).
import { act, cleanup, fireEvent, render, screen, waitFor, within } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { EditorContext } from "../EditorContext";
import { settled, testEditor } from "../testing/harness";
import { discsInRow, sceneOf } from "../testing/scenes";
import { BodiesTable } from "./BodiesTable";

afterEach(cleanup);

/** The Bodies table of `editor`, rendered. */
function renderTable(editor: ReturnType<typeof testEditor>["editor"]): HTMLElement {
  render(
    <EditorContext.Provider value={editor}>
      <BodiesTable />
    </EditorContext.Provider>,
  );
  return screen.getByRole("table", { name: "Bodies" });
}

/** A ball thrown sideways under gravity (vy = -10 t), its table rendered. */
async function fallingBall() {
  const h = testEditor();
  await h.editor.loadScene(
    {
      format: "chapgame",
      version: 1,
      g: 0,
      gravity: [0, -10],
      actions: [{ time: 0, type: "addBody", id: "ball", x: 0, y: 100, r: 1, m: 1, v: [1, 0] }],
    },
    { undoable: false },
  );
  await settled(h.client);
  return { h, table: renderTable(h.editor) };
}

describe("BodiesTable", () => {
  it("opening a cell while playing pauses; the velocity edit keeps vy of the paused time", async () => {
    const { h, table } = await fallingBall();
    const cell = (name: string) => within(table).getByLabelText(name);
    await waitFor(() => expect(cell("ball vy").textContent).toBe("0"));
    act(() => h.editor.ui.setState({ playing: true, t: 0.5 }));
    fireEvent.click(cell("ball vx"));
    expect(h.editor.ui.getState().playing).toBe(false);
    await waitFor(() => expect(cell("ball vy").textContent).toBe("-5"));
    const input = within(table).getByRole("textbox", { name: "ball vx" });
    fireEvent.change(input, { target: { value: "2" } });
    await act(async () => {
      fireEvent.keyDown(input, { key: "Enter" });
    });
    await waitFor(() => expect(h.editor.doc.actions.length).toBe(2));
    expect(h.editor.doc.actions[1]).toMatchObject({ time: 0.5, type: "updateBody", id: "ball", v: [2, -5] });
  });

  it("a vx typed at once, before the row shows the paused time, keeps the vy of that time (audit: an old vy was committed)", async () => {
    const { h, table } = await fallingBall();
    const cell = (name: string) => within(table).getByLabelText(name);
    await waitFor(() => expect(cell("ball vy").textContent).toBe("0"));
    act(() => h.editor.ui.setState({ playing: true, t: 0.75 }));
    fireEvent.click(cell("ball vx"));
    const input = within(table).getByRole("textbox", { name: "ball vx" });
    fireEvent.change(input, { target: { value: "2" } });
    await act(async () => {
      fireEvent.keyDown(input, { key: "Enter" });
    });
    await waitFor(() => expect(h.editor.doc.actions.length).toBe(2));
    expect(h.editor.doc.actions[1]).toMatchObject({
      time: 0.75,
      type: "updateBody",
      id: "ball",
      v: [2, -7.5],
    });
  });
});

describe("BodiesTable messages", () => {
  it("opening a cell clears the message an earlier refusal left in the bar (two different errors showed at once)", async () => {
    const h = testEditor();
    await h.editor.loadScene(sceneOf([{ time: 0, type: "addBody", id: "ball", x: 0, y: 0, r: 1, m: 1 }], 0), {
      undoable: false,
    });
    await settled(h.client);
    const table = renderTable(h.editor);
    await waitFor(() => expect(within(table).getByLabelText("ball r").textContent).toBe("1"));
    fireEvent.click(within(table).getByLabelText("ball r"));
    const r = within(table).getByRole("textbox", { name: "ball r" });
    fireEvent.change(r, { target: { value: "-1" } });
    await act(async () => {
      fireEvent.keyDown(r, { key: "Enter" });
    });
    await waitFor(() => expect(h.editor.ui.getState().message).not.toBeNull());
    fireEvent.keyDown(r, { key: "Escape" });
    fireEvent.click(within(table).getByLabelText("ball m"));
    expect(h.editor.ui.getState().message).toBeNull();
  });

  it("text that is not a number, or a negative |v|, is refused naming the body and the column", async () => {
    const h = testEditor();
    await h.editor.loadScene(sceneOf([{ time: 0, type: "addBody", id: "ball", x: 0, y: 0, r: 1, m: 1 }], 0), {
      undoable: false,
    });
    await settled(h.client);
    const table = renderTable(h.editor);
    const refusal = async (name: string, text: string) => {
      await waitFor(() => expect(within(table).getByLabelText(name)).toBeTruthy());
      fireEvent.click(within(table).getByLabelText(name));
      const input = within(table).getByRole("textbox", { name });
      fireEvent.change(input, { target: { value: text } });
      await act(async () => {
        fireEvent.keyDown(input, { key: "Enter" });
      });
      // a refusal of the engine shows in the message bar too (the cell's copy is then no alert)
      const shown = await waitFor(() => {
        const text = table.querySelector(".cell-error")?.textContent;
        expect(text).toBeTruthy();
        return text;
      });
      fireEvent.keyDown(input, { key: "Escape" });
      return shown;
    };
    expect(await refusal("ball vx", "abc")).toBe('ball vx: must be a number (got "abc")');
    expect(await refusal("ball speed", "-2")).toBe("ball |v|: must be zero or positive (got -2)");
    // regression (audit of session 20): "ball v: must be an array of two finite numbers"
    expect(await refusal("ball speed", "1e999")).toBe("ball |v|: must be a finite number (got 1e999)");
    // the friction column is μ in the engine's refusals too (it said "ball mu")
    expect(await refusal("ball mu", "-1")).toBe("ball μ: must be a non-negative finite number (got -1)");
    expect(await refusal("ball m", "1e999")).toBe(
      "ball m: is too large for a number (got 1e999): type ∞ or Infinity for an immovable body",
    );
    expect(h.editor.doc.actions.length).toBe(1);
  });
});

describe("BodiesTable order", () => {
  it("lists ids with numbers in natural order (ball2 before ball10)", async () => {
    const h = testEditor();
    const ids = ["ball10", "ball2", "ball1", "cue", "ball11", "ball9"];
    await h.editor.loadScene(
      {
        format: "chapgame",
        version: 1,
        g: 0,
        gravity: [0, 0],
        actions: ids.map((id, i) => ({ time: 0, type: "addBody" as const, id, x: 10 * i, y: 0, r: 1, m: 1 })),
      },
      { undoable: false },
    );
    await settled(h.client);
    const table = renderTable(h.editor);
    await waitFor(() => expect(within(table).getAllByRole("row").length).toBe(7));
    const shown = within(table)
      .getAllByRole("button", { name: / id$/ })
      .map((b) => b.textContent);
    expect(shown).toEqual(["ball1", "ball2", "ball9", "ball10", "ball11", "cue"]);
  });
});

describe("BodiesTable selection", () => {
  it("opening a cell of a row selects its body (the row's click was lost: the edited disc was not lit)", async () => {
    const h = testEditor();
    await h.editor.loadScene(
      sceneOf([
        { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 },
        { time: 0, type: "addBody", id: "b", x: 5, y: 0, r: 1, m: 1 },
      ]),
      { undoable: false },
    );
    await settled(h.client);
    const table = renderTable(h.editor);
    await waitFor(() => expect(within(table).getByLabelText("b x").textContent).toBe("5"));
    // A pointer press focuses the cell, which opens it at once; the click that follows lands on the
    // input that replaced the button, not on the row: focus alone must select.
    act(() => within(table).getByRole("button", { name: "b x" }).focus());
    expect(within(table).getByRole("textbox", { name: "b x" })).toBeTruthy();
    expect(h.editor.ui.getState().selection).toEqual({ kind: "body", id: "b" });
    fireEvent.keyDown(within(table).getByRole("textbox", { name: "b x" }), { key: "Escape" });
    act(() => within(table).getByRole("button", { name: "a id" }).focus());
    expect(h.editor.ui.getState().selection).toEqual({ kind: "body", id: "a" });
  });
});

describe("BodiesTable with more bodies than rows", () => {
  async function manyBodies(n: number) {
    const h = testEditor();
    const ids = Array.from({ length: n }, (_, i) => `ball${i + 1}`);
    await h.editor.loadScene(sceneOf(discsInRow(ids), 0), { undoable: false });
    await settled(h.client);
    render(
      <EditorContext.Provider value={h.editor}>
        <BodiesTable />
        <button type="button">after</button>
      </EditorContext.Provider>,
    );
    const table = screen.getByRole("table", { name: "Bodies" });
    await waitFor(() => expect(screen.getByText(/^Showing 60 of 70 bodies/)).toBeTruthy());
    return { ...h, table };
  }

  it("the filter finds a body past the first rows, whose cells can then be edited", async () => {
    const { editor, table } = await manyBodies(70);
    expect(within(table).queryByRole("button", { name: "ball70 x" })).toBeNull();
    fireEvent.change(screen.getByRole("searchbox", { name: "Filter bodies by id" }), {
      target: { value: "ALL70" },
    });
    const cell = await within(table).findByRole("button", { name: "ball70 x" });
    expect(
      within(table)
        .getAllByRole("button", { name: / id$/ })
        .map((b) => b.textContent),
    ).toEqual(["ball70"]);
    fireEvent.click(cell);
    const input = within(table).getByRole("textbox", { name: "ball70 x" });
    fireEvent.change(input, { target: { value: "1000" } });
    await act(async () => {
      fireEvent.keyDown(input, { key: "Enter" });
    });
    await waitFor(() =>
      expect(within(table).getByRole("button", { name: "ball70 x" }).textContent).toBe("1000"),
    );
    // ball70 was the last body added at t = 0: the edit there changed its addBody (doc/mergeEdit.ts)
    expect(editor.doc.actions.at(-1)).toMatchObject({ type: "addBody", id: "ball70", x: 1000 });
    expect(editor.doc.actions).toHaveLength(70);
  });

  it("typing a filter scrolls the list back to its top (the first matches were hidden above)", async () => {
    const { table } = await manyBodies(70);
    const box = table.closest(".table-scroll") as HTMLElement;
    box.scrollTop = 400;
    fireEvent.change(screen.getByRole("searchbox", { name: "Filter bodies by id" }), {
      target: { value: "ball7" },
    });
    expect(box.scrollTop).toBe(0);
  });

  it("Skip the Bodies table moves the focus to the first control after the table", async () => {
    await manyBodies(70);
    fireEvent.click(screen.getByRole("button", { name: "Skip the Bodies table" }));
    expect(document.activeElement).toBe(screen.getByRole("button", { name: "after" }));
  });
});
