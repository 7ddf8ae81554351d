// @vitest-environment jsdom
/**
 * EditableCell, how it opens, commits and closes: the value at rest, selected when opened; Enter
 * commits a changed value once and closes on the cell's button (an unchanged one commits nothing);
 * Escape drops the draft; a value that moves while the cell is open is followed until typed in; a
 * draft is marked. What the cell does with the commit's answer (a refusal, a late answer, an Undo
 * during the check): EditableCellAnswers.test.tsx.
 */
import { act, cleanup, fireEvent, render, screen } from "@testing-library/react";
import { afterEach, describe, expect, it, vi } from "vitest";
import { openCell } from "../testing/editableCell";
import { EditableCell } from "./EditableCell";

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

describe("EditableCell", () => {
  it("shows the value at rest and commits a changed value on Enter", async () => {
    const onCommit = vi.fn(async () => null);
    render(<EditableCell label="a x" value="1" onCommit={onCommit} />);
    expect(screen.getByRole("button", { name: "a x" }).textContent).toBe("1");
    const input = openCell("a x");
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
    const input = openCell("l1 x1");
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
    const input = openCell("a m");
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

  it("Escape drops the draft without committing; an unchanged value is not committed", async () => {
    const onCommit = vi.fn(async () => null);
    render(<EditableCell label="a y" value="3" onCommit={onCommit} />);
    let input = openCell("a y");
    fireEvent.change(input, { target: { value: "9" } });
    fireEvent.keyDown(input, { key: "Escape" });
    expect(screen.getByRole("button", { name: "a y" }).textContent).toBe("3");
    input = openCell("a y");
    await act(async () => {
      fireEvent.keyDown(input, { key: "Enter" });
    });
    expect(onCommit).not.toHaveBeenCalled();
  });

  it("closed by Enter or Escape, the cell keeps the focus on its button, closed (focus went to the page)", async () => {
    const onCommit = vi.fn(async () => null);
    render(<EditableCell label="a vx" value="1" onCommit={onCommit} />);
    let input = openCell("a vx");
    fireEvent.change(input, { target: { value: "2" } });
    await act(async () => {
      fireEvent.keyDown(input, { key: "Enter" });
    });
    const button = screen.getByRole("button", { name: "a vx" });
    expect(document.activeElement).toBe(button);
    expect(screen.queryByRole("textbox")).toBeNull(); // not opened again by that focus
    input = openCell("a vx");
    fireEvent.keyDown(input, { key: "Escape" });
    expect(document.activeElement).toBe(screen.getByRole("button", { name: "a vx" }));
    expect(screen.queryByRole("textbox")).toBeNull();
  });

  it("Enter on an unchanged value, or the same value retyped, closes the cell with focus on its button, not reopened", async () => {
    // The unchanged path closed the cell during the keydown; the same Enter then clicked the button
    // focused in its place and opened the cell again (audit s09c).
    const onCommit = vi.fn(async () => null);
    render(<EditableCell label="A y" value="3" onCommit={onCommit} />);
    let input = openCell("A y");
    input.focus();
    pressEnter(); // not inside an act: React renders a key's updates before the key's next event
    await act(async () => {});
    expect(screen.queryByRole("textbox")).toBeNull();
    expect(document.activeElement).toBe(screen.getByRole("button", { name: "A y" }));

    input = openCell("A y");
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
    const input = openCell("A x");
    input.focus();
    fireEvent.change(input, { target: { value: "2" } });
    pressEnter(); // not inside an act: React renders a key's updates before the key's next event
    await act(async () => {});
    expect(onCommit).toHaveBeenCalledWith("2");
    expect(screen.queryByRole("textbox")).toBeNull();
    expect(document.activeElement).toBe(screen.getByRole("button", { name: "A x" }));
  });

  it("opened while the value changes (playing), follows it and commits nothing until typed in", async () => {
    // A cell opened during playback: the table refreshes to the paused time after it opened.
    const onCommit = vi.fn(async () => null);
    const { rerender } = render(<EditableCell label="a x" value="1" onCommit={onCommit} />);
    let input = openCell("a x");
    rerender(<EditableCell label="a x" value="1.5" onCommit={onCommit} />);
    expect(input.value).toBe("1.5");
    await act(async () => {
      fireEvent.blur(input);
    });
    expect(onCommit).not.toHaveBeenCalled();
    expect(screen.getByRole("button", { name: "a x" }).textContent).toBe("1.5");

    input = openCell("a x");
    rerender(<EditableCell label="a x" value="2" onCommit={onCommit} />);
    await act(async () => {
      fireEvent.keyDown(input, { key: "Enter" });
    });
    expect(onCommit).not.toHaveBeenCalled();

    // Typed text is kept while the value moves on, and committed.
    input = openCell("a x");
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
    const input = openCell("A x");
    expect(input.hasAttribute("data-draft")).toBe(false); // opened, nothing typed
    fireEvent.change(input, { target: { value: "5" } });
    expect(input.hasAttribute("data-draft")).toBe(true);
    fireEvent.change(input, { target: { value: "3" } }); // typed back to the value: nothing to commit
    expect(input.hasAttribute("data-draft")).toBe(false);
  });
});
