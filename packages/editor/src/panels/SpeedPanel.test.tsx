// @vitest-environment jsdom
// The speed field: a speed too small to keep, or not a number, is refused with a message (it was
// rounded to 0 or dropped without a word).
import { cleanup, fireEvent, render, screen } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { EditorContext } from "../EditorContext";
import { testEditor } from "../testing/harness";
import { SpeedPanel } from "./SpeedPanel";

afterEach(cleanup);

function type(field: HTMLElement, text: string): void {
  fireEvent.focus(field);
  fireEvent.change(field, { target: { value: text } });
  fireEvent.keyDown(field, { key: "Enter" });
}

/** A test editor with its Speed panel rendered, and the panel's Speed field. */
function renderSpeed() {
  const { editor } = testEditor();
  render(
    <EditorContext.Provider value={editor}>
      <SpeedPanel />
    </EditorContext.Provider>,
  );
  return { editor, field: screen.getByRole("textbox", { name: "Speed" }) };
}

describe("SpeedPanel", () => {
  it("takes a typed speed, negative included, and refuses what it cannot keep, saying why", () => {
    const { editor, field } = renderSpeed();
    type(field, "-0.25");
    expect(editor.ui.getState().speed).toBe(-0.25);
    expect(editor.ui.getState().message).toBeNull();
    type(field, "0.0004");
    expect(editor.ui.getState().speed).toBe(-0.25);
    expect(editor.ui.getState().message?.text).toBe(
      "Speed: must be 0 or at least 0.001 in size (got 0.0004): speeds are kept to 0.001",
    );
    type(field, "fast");
    expect(editor.ui.getState().speed).toBe(-0.25);
    expect(editor.ui.getState().message?.text).toBe(
      'Speed: must be a finite number (got "fast"): a negative speed plays backwards',
    );
    type(field, "0");
    expect(editor.ui.getState().speed).toBe(0);
  });

  it("keeps a refused speed typed in the field, the refusal beside it, until corrected", () => {
    const { editor, field } = renderSpeed();
    const input = field as HTMLInputElement;
    type(input, "2x");
    expect(input.value).toBe("2x");
    expect(editor.ui.getState().speed).toBe(1);
    const beside = document.getElementById(input.getAttribute("aria-describedby") ?? "");
    expect(beside?.textContent).toBe(
      'Speed: must be a finite number (got "2x"): a negative speed plays backwards',
    );
    // focused again, the text refused is not replaced by the speed
    fireEvent.blur(input);
    fireEvent.focus(input);
    expect(input.value).toBe("2x");
    fireEvent.change(input, { target: { value: "2" } });
    fireEvent.keyDown(input, { key: "Enter" });
    expect(editor.ui.getState().speed).toBe(2);
    expect(input.value).toBe("2");
    expect(input.getAttribute("aria-invalid")).toBe("false");
  });

  it("a valid speed removes the field's earlier refusal, not another message", () => {
    const { editor, field } = renderSpeed();
    type(field, "fast");
    expect(editor.ui.getState().message?.text).toMatch(/^Speed: must be a finite number/);
    type(field, "2");
    expect(editor.ui.getState()).toMatchObject({ speed: 2, message: null });
    editor.ui.setState({ message: { text: "Time (s): must be 0 or later (got -3)", tone: "error" } });
    type(field, "3");
    expect(editor.ui.getState().message?.text).toBe("Time (s): must be 0 or later (got -3)");
  });

  it("Reverse (−1×) at t = 0 says why nothing plays instead of doing nothing", () => {
    const { editor } = testEditor();
    render(
      <EditorContext.Provider value={editor}>
        <SpeedPanel />
      </EditorContext.Provider>,
    );
    fireEvent.click(screen.getByRole("button", { name: "−1×: play backwards" }));
    expect(editor.ui.getState()).toMatchObject({ speed: -1, playing: false });
    expect(editor.ui.getState().message?.text).toMatch(/^Playing backwards from t = 0: nothing before it/);
  });
});
