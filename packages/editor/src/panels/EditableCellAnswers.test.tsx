// @vitest-environment jsdom
/**
 * EditableCell and the answer to its commit: a refusal keeps the draft in the cell, marked invalid,
 * announced once (by the message bar when the bar shows it, else by the cell), and noted with its
 * time when the time moves on; an answer later than SLOW_COMMIT_MS says it is being checked; a
 * commit an Undo took back during its check closes the cell on the scene's value. How the cell
 * opens, commits and closes: EditableCell.test.tsx.
 */
import { act, cleanup, fireEvent, render, screen } from "@testing-library/react";
import { afterEach, describe, expect, it, vi } from "vitest";
import { EditorContext } from "../EditorContext";
import { UNDONE_DURING_CHECK } from "../remote/protocol";
import { openCell } from "../testing/editableCell";
import { testEditor } from "../testing/harness";
import { EditableCell, SLOW_COMMIT_MS } from "./EditableCell";
import { MessageBar } from "./MessageBar";

afterEach(cleanup);

describe("EditableCell: the answer to a commit", () => {
  it("a commit not answered within SLOW_COMMIT_MS says it is being checked, until it is answered", async () => {
    vi.useFakeTimers();
    try {
      let resolve: (v: string | null) => void = () => {};
      const onCommit = vi.fn(() => new Promise<string | null>((r) => (resolve = r)));
      render(<EditableCell label="a r" value="1" onCommit={onCommit} />);
      const input = openCell("a r");
      fireEvent.change(input, { target: { value: "2" } });
      fireEvent.keyDown(input, { key: "Enter" });
      expect(screen.queryByRole("status")).toBeNull(); // a quick answer shows nothing
      act(() => {
        vi.advanceTimersByTime(SLOW_COMMIT_MS);
      });
      expect(screen.getByRole("status").textContent).toBe("checking the later actions…");
      await act(async () => {
        resolve(null);
      });
      expect(screen.queryByRole("status")).toBeNull();
    } finally {
      vi.useRealTimers();
    }
  });

  it("a refused value stays in the cell with the message, marked invalid", async () => {
    const onCommit = vi.fn(async () => "actions[4].r: must be a positive finite number");
    render(<EditableCell label="a r" value="1" onCommit={onCommit} />);
    const input = openCell("a r");
    fireEvent.change(input, { target: { value: "-1" } });
    await act(async () => {
      fireEvent.keyDown(input, { key: "Enter" });
    });
    expect(screen.getByRole("alert").textContent).toBe("actions[4].r: must be a positive finite number");
    expect(input.getAttribute("aria-invalid")).toBe("true");
    expect(input.value).toBe("-1");
  });

  it("a commit an Undo took back during its check closes the cell on the scene's value (it stayed open, the undone draft shown as an error)", async () => {
    const onCommit = vi.fn(async () => UNDONE_DURING_CHECK);
    render(<EditableCell label="a vx" value="1" onCommit={onCommit} />);
    const input = openCell("a vx");
    fireEvent.change(input, { target: { value: "3" } });
    await act(async () => {
      fireEvent.keyDown(input, { key: "Enter" });
    });
    expect(screen.queryByRole("alert")).toBeNull();
    expect(screen.queryByRole("textbox", { name: "a vx" })).toBeNull();
    expect(screen.getByRole("button", { name: "a vx" }).textContent).toBe("1");
    expect(onCommit).toHaveBeenCalledTimes(1);
  });

  it("a refusal shown in the message bar too is announced once: the bar's alert, the cell's text describing the input", async () => {
    const { editor } = testEditor();
    const text = "A r: must be a positive finite number";
    const onCommit = vi.fn(async () => {
      editor.ui.setState({ message: { text, tone: "error" } }); // as Editor.edit does
      return text;
    });
    render(
      <EditorContext.Provider value={editor}>
        <MessageBar />
        <EditableCell label="A r" value="1" onCommit={onCommit} />
      </EditorContext.Provider>,
    );
    const input = openCell("A r");
    fireEvent.change(input, { target: { value: "-5" } });
    await act(async () => {
      fireEvent.keyDown(input, { key: "Enter" });
    });
    expect(screen.getAllByRole("alert").map((a) => a.textContent)).toEqual([`${text}✕`]);
    const described = document.getElementById(input.getAttribute("aria-describedby")!);
    expect(described?.textContent).toBe(text);
  });

  it("a refusal of the cell's own (not in the bar) is the cell's alert", async () => {
    const { editor } = testEditor();
    const onCommit = vi.fn(async () => "vx: must be a number");
    render(
      <EditorContext.Provider value={editor}>
        <MessageBar />
        <EditableCell label="A vx" value="1" onCommit={onCommit} />
      </EditorContext.Provider>,
    );
    const input = openCell("A vx");
    fireEvent.change(input, { target: { value: "x" } });
    await act(async () => {
      fireEvent.keyDown(input, { key: "Enter" });
    });
    expect(screen.getAllByRole("alert").map((a) => a.textContent)).toEqual(["vx: must be a number"]);
  });

  it("a refused draft stays when the time moves, saying where Enter now applies it (it saved r at t = 3 for t = 1 without a word, then closed, the text lost)", async () => {
    const { editor } = testEditor();
    editor.ui.setState({ t: 1 });
    const onCommit = vi.fn(async () => "ball1 r: would overlap ball2 at time 1");
    render(
      <EditorContext.Provider value={editor}>
        <EditableCell label="ball1 r" value="0.3" onCommit={onCommit} />
      </EditorContext.Provider>,
    );
    const input = openCell("ball1 r");
    fireEvent.change(input, { target: { value: "100" } });
    await act(async () => {
      fireEvent.keyDown(input, { key: "Enter" });
    });
    expect(screen.getByRole("textbox", { name: "ball1 r" })).toBeTruthy();
    act(() => editor.ui.setState({ t: 3 }));
    const kept = screen.getByRole("textbox", { name: "ball1 r" }) as HTMLInputElement;
    expect(kept.value).toBe("100");
    const note = () => document.getElementById(kept.getAttribute("aria-describedby") ?? "")?.textContent;
    expect(note()).toBe(
      "ball1 r: refused at t = 1 s; the time is now 3 s, where Enter applies it (Escape drops it)",
    );
    // back at the time it was refused, the refusal is shown again
    act(() => editor.ui.setState({ t: 1 }));
    expect(note()).toBe("ball1 r: would overlap ball2 at time 1");
    expect(onCommit).toHaveBeenCalledTimes(1);
    // Enter at another time tries it there; a refusal there is noted from that time
    act(() => editor.ui.setState({ t: 2 }));
    await act(async () => {
      fireEvent.keyDown(kept, { key: "Enter" });
    });
    expect(onCommit).toHaveBeenCalledTimes(2);
    act(() => editor.ui.setState({ t: 4 }));
    expect(note()).toBe(
      "ball1 r: refused at t = 2 s; the time is now 4 s, where Enter applies it (Escape drops it)",
    );
    fireEvent.keyDown(kept, { key: "Escape" });
    expect(screen.getByRole("button", { name: "ball1 r" }).textContent).toBe("0.3");
  });

  it("a cell whose commit does not apply at the current time (the refused action's) keeps its refusal when the time moves", async () => {
    const { editor } = testEditor();
    editor.ui.setState({ t: 1 });
    const refusal = "refused action r: must be a positive finite number (got -1)";
    render(
      <EditorContext.Provider value={editor}>
        <EditableCell
          label="refused action r"
          value="1"
          onCommit={async () => refusal}
          atCurrentTime={false}
        />
      </EditorContext.Provider>,
    );
    const input = openCell("refused action r");
    fireEvent.change(input, { target: { value: "-1" } });
    await act(async () => {
      fireEvent.keyDown(input, { key: "Enter" });
    });
    act(() => editor.ui.setState({ t: 3 }));
    expect(document.getElementById(input.getAttribute("aria-describedby") ?? "")?.textContent).toBe(refusal);
    expect(input.value).toBe("-1");
  });
});
