// @vitest-environment jsdom
// A cell edited while an undo recomputes the history, the time not reached yet: the edit is refused
// ("still being computed", Editor.edit: it would be built from the state shown, the end of the
// history, not the state at the current time). That refusal holds only until the history gets
// there: it stayed in the cell (and the message bar) until the user pressed Enter again, after the
// computation had passed the time. It lapses now: the cell's error goes, its draft stays for Enter.
import { dilutedGas } from "@chapgame/engine";
import { act, cleanup, fireEvent, render, screen, waitFor, within } from "@testing-library/react";
import { afterEach, describe, expect, it, vi } from "vitest";
import { EditorContext } from "../EditorContext";
import { settled, testEditor } from "../testing/harness";
import { BodiesTable } from "./BodiesTable";
import { EditableCell } from "./EditableCell";
import { MessageBar } from "./MessageBar";

afterEach(cleanup);

/** The gas edited at t = 0, its history computed to t = 10, then the time set to `t` and the edit undone. */
async function undoneAt(t: number) {
  // the slow host computes one event per round: the recomputation lasts many rounds
  const h = testEditor({ slow: true });
  await h.editor.loadScene(dilutedGas({ n: 40, packing: 0.1, seed: 3 }), { undoable: false });
  await settled(h.client, 60_000);
  expect(await h.editor.giveVelocity("d0", [1, 0])).toBeNull();
  await settled(h.client, 60_000);
  render(
    <EditorContext.Provider value={h.editor}>
      <MessageBar />
      <BodiesTable />
    </EditorContext.Provider>,
  );
  const table = screen.getByRole("table", { name: "Bodies" });
  await waitFor(() => within(table).getByLabelText("d1 m"));
  act(() => h.editor.ui.setState({ t }));
  await act(async () => {
    await h.editor.undo();
  });
  return { h, table };
}

/** Opens the cell `label`, types `text` and presses Enter; the input. */
async function typeInto(table: HTMLElement, label: string, text: string): Promise<HTMLInputElement> {
  fireEvent.click(within(table).getByRole("button", { name: label }));
  const input = within(table).getByRole("textbox", { name: label }) as HTMLInputElement;
  fireEvent.change(input, { target: { value: text } });
  await act(async () => {
    fireEvent.keyDown(input, { key: "Enter" });
  });
  return input;
}

const cellError = (input: HTMLInputElement) => {
  const id = input.getAttribute("aria-describedby");
  return id === null ? null : (document.getElementById(id)?.textContent ?? null);
};

describe("a cell refused while the history is recomputed", () => {
  it("drops the 'still being computed' refusal once the history reaches the time; Enter then applies the draft", async () => {
    const { h, table } = await undoneAt(8);
    expect(h.client.getSnapshot().horizon).toBeLessThan(8);
    const input = await typeInto(table, "d1 m", "2");
    await waitFor(() =>
      expect(cellError(input)).toMatch(/^The history is still being computed up to t = 8 s/),
    );
    expect(input.getAttribute("aria-invalid")).toBe("true");
    expect(h.editor.ui.getState().message?.text).toBe(cellError(input));
    await act(async () => {
      await settled(h.client, 60_000);
    });
    expect(h.client.getSnapshot().horizon).toBeGreaterThanOrEqual(8);
    // the refusal no longer holds: gone from the cell and from the bar, which says why
    await waitFor(() => expect(cellError(input)).toBeNull());
    expect(input.getAttribute("aria-invalid")).toBe("false");
    expect(input.value).toBe("2"); // the draft is kept
    expect(h.editor.ui.getState().message).toEqual({
      text: "The history has reached t = 8 s: edits there are accepted now.",
      tone: "info",
    });
    expect(screen.queryAllByRole("alert")).toEqual([]);
    const actions = h.editor.doc.actions.length;
    await act(async () => {
      fireEvent.keyDown(input, { key: "Enter" });
    });
    await waitFor(() => expect(h.editor.doc.actions.length).toBe(actions + 1));
    expect(h.editor.doc.actions.at(-1)).toMatchObject({ time: 8, type: "updateBody", id: "d1", m: 2 });
    await waitFor(() => expect(within(table).queryByRole("textbox", { name: "d1 m" })).toBeNull());
  });
});

describe("EditableCell and a refusal that changes", () => {
  it("shows the refusal that holds instead (the computation cancelled short), then none once it lapses; other refusals stay", async () => {
    const { editor } = testEditor();
    const waits = new Map<string, (next: string | null) => void>();
    editor.refusalChanged = (text) =>
      text.startsWith("behind") ? new Promise((resolve) => waits.set(text, resolve)) : null;
    const onCommit = vi.fn(async (text: string) => (text === "2" ? "behind 1" : "A m: must be a number"));
    render(
      <EditorContext.Provider value={editor}>
        <EditableCell label="A m" value="1" onCommit={onCommit} />
      </EditorContext.Provider>,
    );
    fireEvent.click(screen.getByRole("button", { name: "A m" }));
    const input = screen.getByRole("textbox", { name: "A m" }) as HTMLInputElement;
    fireEvent.change(input, { target: { value: "2" } });
    await act(async () => {
      fireEvent.keyDown(input, { key: "Enter" });
    });
    expect(cellError(input)).toBe("behind 1");
    await act(async () => waits.get("behind 1")!("behind 2"));
    expect(cellError(input)).toBe("behind 2");
    await act(async () => waits.get("behind 2")!(null));
    expect(cellError(input)).toBeNull();
    expect(input.value).toBe("2");
    // a refusal that does not lapse stays; a lapse of an earlier one no longer shown changes nothing
    fireEvent.change(input, { target: { value: "2" } });
    await act(async () => {
      fireEvent.keyDown(input, { key: "Enter" });
    });
    expect(cellError(input)).toBe("behind 1");
    fireEvent.change(input, { target: { value: "x" } });
    await act(async () => {
      fireEvent.keyDown(input, { key: "Enter" });
    });
    expect(cellError(input)).toBe("A m: must be a number");
    await act(async () => waits.get("behind 1")!(null));
    expect(cellError(input)).toBe("A m: must be a number");
  });
});
