// @vitest-environment jsdom
import { act, cleanup, fireEvent, render, screen } from "@testing-library/react";
import { afterEach, describe, expect, it, vi } from "vitest";
import { EditorContext } from "../EditorContext";
import { UNDONE_DURING_CHECK } from "../remote/protocol";
import { testEditor } from "../testing/harness";
import { EditableCell, SLOW_COMMIT_MS } from "./EditableCell";
import { MessageBar } from "./MessageBar";

afterEach(cleanup);

/**
 * Enter as a browser (and user-event) presses it: keydown on the focused element, then, unless the
 * keydown's default was prevented, keypress on the element focused by then, whose default action on
 * a button is a click. fireEvent.keyDown alone never clicks, so it hid the cell reopening.
 */
function pressEnter(): void {
  const go = fireEvent.keyDown(document.activeElement ?? document.body, { key: "Enter", code: "Enter" });
  if (!go) return;
  const target = document.activeElement ?? document.body;
  const pressed = fireEvent.keyPress(target, { key: "Enter", code: "Enter", charCode: 13 });
  if (pressed && target instanceof HTMLButtonElement) fireEvent.click(target);
}

function open(label: string): HTMLInputElement {
  fireEvent.click(screen.getByRole("button", { name: label }));
  return screen.getByRole("textbox", { name: label }) as HTMLInputElement;
}

describe("EditableCell", () => {
  it("shows the value at rest and commits a changed value on Enter", async () => {
    const onCommit = vi.fn(async () => null);
    render(<EditableCell label="a x" value="1" onCommit={onCommit} />);
    expect(screen.getByRole("button", { name: "a x" }).textContent).toBe("1");
    const input = open("a x");
    expect(input.value).toBe("1");
    fireEvent.change(input, { target: { value: "2.5" } });
    await act(async () => {
      fireEvent.keyDown(input, { key: "Enter" });
    });
    expect(onCommit).toHaveBeenCalledWith("2.5");
    expect(screen.queryByRole("alert")).toBeNull();
    expect(screen.getByRole("button", { name: "a x" }).textContent).toBe("1");
  });

  it("opened, the cell's value is selected, so typing replaces it (it appended to it)", () => {
    render(<EditableCell label="l1 x1" value="-100" onCommit={async () => null} />);
    const input = open("l1 x1");
    expect(document.activeElement).toBe(input);
    expect([input.selectionStart, input.selectionEnd]).toEqual([0, 4]);
    // a draft kept for correction is not selected again when the input gets the focus back
    fireEvent.change(input, { target: { value: "-30" } });
    input.setSelectionRange(3, 3);
    fireEvent.focus(input);
    expect([input.selectionStart, input.selectionEnd]).toEqual([3, 3]);
  });

  it("commits once when Enter is followed by leaving the cell before the edit is applied (it recorded two edits)", async () => {
    let resolve: (v: string | null) => void = () => {};
    const onCommit = vi.fn(() => new Promise<string | null>((r) => (resolve = r)));
    render(<EditableCell label="a m" value="1" onCommit={onCommit} />);
    const input = open("a m");
    fireEvent.change(input, { target: { value: "4" } });
    fireEvent.keyDown(input, { key: "Enter" });
    fireEvent.blur(input);
    fireEvent.keyDown(input, { key: "Enter" });
    await act(async () => {
      resolve(null);
    });
    expect(onCommit).toHaveBeenCalledTimes(1);
    expect(screen.getByRole("button", { name: "a m" }).textContent).toBe("1");
  });

  it("a commit not answered within SLOW_COMMIT_MS says it is being checked, until it is answered", async () => {
    vi.useFakeTimers();
    try {
      let resolve: (v: string | null) => void = () => {};
      const onCommit = vi.fn(() => new Promise<string | null>((r) => (resolve = r)));
      render(<EditableCell label="a r" value="1" onCommit={onCommit} />);
      const input = open("a r");
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
    const input = open("a r");
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
    const input = open("a vx");
    fireEvent.change(input, { target: { value: "3" } });
    await act(async () => {
      fireEvent.keyDown(input, { key: "Enter" });
    });
    expect(screen.queryByRole("alert")).toBeNull();
    expect(screen.queryByRole("textbox", { name: "a vx" })).toBeNull();
    expect(screen.getByRole("button", { name: "a vx" }).textContent).toBe("1");
    expect(onCommit).toHaveBeenCalledTimes(1);
  });

  it("Escape drops the draft without committing; an unchanged value is not committed", async () => {
    const onCommit = vi.fn(async () => null);
    render(<EditableCell label="a y" value="3" onCommit={onCommit} />);
    let input = open("a y");
    fireEvent.change(input, { target: { value: "9" } });
    fireEvent.keyDown(input, { key: "Escape" });
    expect(screen.getByRole("button", { name: "a y" }).textContent).toBe("3");
    input = open("a y");
    await act(async () => {
      fireEvent.keyDown(input, { key: "Enter" });
    });
    expect(onCommit).not.toHaveBeenCalled();
  });

  it("closed by Enter or Escape, the cell keeps the focus on its button, closed (focus went to the page)", async () => {
    const onCommit = vi.fn(async () => null);
    render(<EditableCell label="a vx" value="1" onCommit={onCommit} />);
    let input = open("a vx");
    fireEvent.change(input, { target: { value: "2" } });
    await act(async () => {
      fireEvent.keyDown(input, { key: "Enter" });
    });
    const button = screen.getByRole("button", { name: "a vx" });
    expect(document.activeElement).toBe(button);
    expect(screen.queryByRole("textbox")).toBeNull(); // not opened again by that focus
    input = open("a vx");
    fireEvent.keyDown(input, { key: "Escape" });
    expect(document.activeElement).toBe(screen.getByRole("button", { name: "a vx" }));
    expect(screen.queryByRole("textbox")).toBeNull();
  });

  it("Enter on an unchanged value, or the same value retyped, closes the cell with focus on its button, not reopened", async () => {
    // The unchanged path closed the cell during the keydown; the same Enter then clicked the button
    // focused in its place and opened the cell again (audit s09c).
    const onCommit = vi.fn(async () => null);
    render(<EditableCell label="A y" value="3" onCommit={onCommit} />);
    let input = open("A y");
    input.focus();
    pressEnter(); // not inside an act: React renders a key's updates before the key's next event
    await act(async () => {});
    expect(screen.queryByRole("textbox")).toBeNull();
    expect(document.activeElement).toBe(screen.getByRole("button", { name: "A y" }));

    input = open("A y");
    input.focus();
    fireEvent.change(input, { target: { value: "3" } });
    pressEnter(); // not inside an act: React renders a key's updates before the key's next event
    await act(async () => {});
    expect(screen.queryByRole("textbox")).toBeNull();
    expect(document.activeElement).toBe(screen.getByRole("button", { name: "A y" }));
    expect(onCommit).not.toHaveBeenCalled();
  });

  it("Enter committing a changed value closes the cell, not reopened", async () => {
    const onCommit = vi.fn(async () => null);
    render(<EditableCell label="A x" value="1" onCommit={onCommit} />);
    const input = open("A x");
    input.focus();
    fireEvent.change(input, { target: { value: "2" } });
    pressEnter(); // not inside an act: React renders a key's updates before the key's next event
    await act(async () => {});
    expect(onCommit).toHaveBeenCalledWith("2");
    expect(screen.queryByRole("textbox")).toBeNull();
    expect(document.activeElement).toBe(screen.getByRole("button", { name: "A x" }));
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
    const input = open("A r");
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
    const input = open("A vx");
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
    const input = open("ball1 r");
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

  it("opened while the value changes (playing), follows it and commits nothing until typed in", async () => {
    // A cell opened during playback: the table refreshes to the paused time after it opened.
    const onCommit = vi.fn(async () => null);
    const { rerender } = render(<EditableCell label="a x" value="1" onCommit={onCommit} />);
    let input = open("a x");
    rerender(<EditableCell label="a x" value="1.5" onCommit={onCommit} />);
    expect(input.value).toBe("1.5");
    await act(async () => {
      fireEvent.blur(input);
    });
    expect(onCommit).not.toHaveBeenCalled();
    expect(screen.getByRole("button", { name: "a x" }).textContent).toBe("1.5");

    input = open("a x");
    rerender(<EditableCell label="a x" value="2" onCommit={onCommit} />);
    await act(async () => {
      fireEvent.keyDown(input, { key: "Enter" });
    });
    expect(onCommit).not.toHaveBeenCalled();

    // Typed text is kept while the value moves on, and committed.
    input = open("a x");
    fireEvent.change(input, { target: { value: "7" } });
    rerender(<EditableCell label="a x" value="2.5" onCommit={onCommit} />);
    expect(input.value).toBe("7");
    await act(async () => {
      fireEvent.blur(input);
    });
    expect(onCommit).toHaveBeenCalledWith("7");
  });
});

describe("EditableCell: a draft", () => {
  it("is marked while typed and differing from the value (Save file says it is not in the file)", () => {
    render(<EditableCell label="A x" value="3" onCommit={async () => null} />);
    const input = open("A x");
    expect(input.hasAttribute("data-draft")).toBe(false); // opened, nothing typed
    fireEvent.change(input, { target: { value: "5" } });
    expect(input.hasAttribute("data-draft")).toBe(true);
    fireEvent.change(input, { target: { value: "3" } }); // typed back to the value: nothing to commit
    expect(input.hasAttribute("data-draft")).toBe(false);
  });
});
