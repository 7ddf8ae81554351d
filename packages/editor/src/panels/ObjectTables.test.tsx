// @vitest-environment jsdom
// The Lines and Points tables (ObjectRow, CoordinateCell): a coordinate typed into a cell moves that
// one coordinate; text that is not a number is refused in place; a row click selects the object.
import { act, cleanup, fireEvent, render, screen, waitFor, within } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { EditorContext } from "../EditorContext";
import { settled, testEditor } from "../testing/harness";
import { LinesTable } from "./LinesTable";
import { PointsTable } from "./PointsTable";

afterEach(cleanup);

async function setup() {
  const h = testEditor();
  await h.editor.addPoint([1, 2]);
  await h.editor.addLine([0, 0], [10, 0], "segment");
  await settled(h.client);
  render(
    <EditorContext.Provider value={h.editor}>
      <PointsTable />
      <LinesTable />
    </EditorContext.Provider>,
  );
  const idIn = async (table: string) => {
    const cell = await within(screen.getByRole("table", { name: table })).findByRole("button", {
      name: / id$/,
    });
    return (cell.getAttribute("aria-label") ?? "").replace(/ id$/, "");
  };
  return { ...h, pointId: await idIn("Points"), lineId: await idIn("Lines") };
}

const shown = (label: string) => screen.getByRole("button", { name: label }).textContent;

async function commit(label: string, text: string) {
  fireEvent.click(screen.getByRole("button", { name: label }));
  const input = screen.getByRole("textbox", { name: label });
  fireEvent.change(input, { target: { value: text } });
  await act(async () => {
    fireEvent.keyDown(input, { key: "Enter" });
  });
}

describe("Lines and Points tables", () => {
  it("list their rows in natural id order (p2 before p10), as the Bodies table does", async () => {
    const h = testEditor();
    for (let i = 0; i < 11; i++) await h.editor.addPoint([3 * i, 1]);
    await settled(h.client);
    render(
      <EditorContext.Provider value={h.editor}>
        <PointsTable />
      </EditorContext.Provider>,
    );
    const table = await screen.findByRole("table", { name: "Points" });
    await waitFor(() => expect(within(table).getAllByRole("button", { name: / id$/ })).toHaveLength(11));
    const ids = within(table)
      .getAllByRole("button", { name: / id$/ })
      .map((c) => (c.getAttribute("aria-label") ?? "").replace(/ id$/, ""));
    const numbers = ids.map((id) => Number(/\d+$/.exec(id)?.[0]));
    expect(numbers).toEqual([...numbers].sort((a, b) => a - b)); // the frame lists p10 before p2
    expect(new Set(numbers.map((n) => String(n).length)).size).toBe(2); // ids of one and two digits
  });

  it("a typed coordinate moves only that coordinate of the point or line end", async () => {
    const { client, pointId, lineId } = await setup();
    await commit(`${pointId} x`, "7");
    await commit(`${lineId} y2`, "3");
    await settled(client);
    await waitFor(() => {
      expect([shown(`${pointId} x`), shown(`${pointId} y`)]).toEqual(["7", "2"]);
      expect([shown(`${lineId} x1`), shown(`${lineId} y1`)]).toEqual(["0", "0"]);
      expect([shown(`${lineId} x2`), shown(`${lineId} y2`)]).toEqual(["10", "3"]);
    });
  });

  it("text that is not a number is refused in place, naming the object and the field; nothing changes", async () => {
    const { editor, lineId } = await setup();
    const before = editor.doc.actions.length;
    await commit(`${lineId} x1`, "abc");
    expect(screen.getByRole("alert").textContent).toBe(`${lineId} x1: must be a number (got "abc")`);
    expect(editor.doc.actions.length).toBe(before);
  });

  it("clicking a row selects its object and marks the row", async () => {
    const { editor, pointId } = await setup();
    const row = screen.getByRole("button", { name: `${pointId} y` }).closest("tr") as HTMLTableRowElement;
    fireEvent.click(row);
    expect(editor.ui.getState().selection).toEqual({ kind: "point", id: pointId });
    await waitFor(() => expect(row.getAttribute("aria-selected")).toBe("true"));
  });

  it("opening a cell of a row selects its object (the row's click was lost to the opened input)", async () => {
    const { editor, pointId, lineId } = await setup();
    act(() => screen.getByRole("button", { name: `${lineId} x2` }).focus());
    expect(screen.getByRole("textbox", { name: `${lineId} x2` })).toBeTruthy();
    expect(editor.ui.getState().selection).toEqual({ kind: "line", id: lineId });
    act(() => screen.getByRole("button", { name: `${pointId} x` }).focus());
    expect(editor.ui.getState().selection).toEqual({ kind: "point", id: pointId });
  });
});
