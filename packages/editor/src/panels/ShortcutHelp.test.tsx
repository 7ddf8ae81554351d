// @vitest-environment jsdom
// The Keyboard shortcuts dialog: the toolbar's ? button and the ? key open it; it lists every
// shortcut of the table the keyboard handler runs (shortcuts.ts), takes the focus and gives it back.
import { act, cleanup, fireEvent, render, screen, within } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { EditorContext } from "../EditorContext";
import { bindKeyboard } from "../keyboard";
import { SHORTCUTS } from "../shortcuts";
import { testEditor } from "../testing/harness";
import { ShortcutHelp } from "./ShortcutHelp";
import { Toolbar } from "./Toolbar";

afterEach(cleanup);

function setup() {
  const h = testEditor();
  render(
    <EditorContext.Provider value={h.editor}>
      <Toolbar />
      <ShortcutHelp />
    </EditorContext.Provider>,
  );
  return h;
}

describe("Keyboard shortcuts dialog", () => {
  it("the toolbar's ? opens a list of every shortcut; Escape closes it and the focus goes back", async () => {
    setup();
    expect(screen.queryByRole("dialog")).toBeNull();
    const button = screen.getByRole("button", { name: "Keyboard shortcuts" });
    button.focus();
    await act(async () => fireEvent.click(button));
    const dialog = screen.getByRole("dialog", { name: "Keyboard shortcuts" });
    expect(document.activeElement).toBe(within(dialog).getByRole("button", { name: "Close" }));
    const rows = within(dialog).getAllByRole("row");
    expect(rows).toHaveLength(SHORTCUTS.length);
    for (const s of SHORTCUTS) {
      const row = rows.find((r) => r.textContent === `${s.keys.join(" ")}${s.what}`);
      expect(row, s.what).toBeDefined();
    }
    // the scene view's keys have a group of their own
    expect(within(dialog).getByRole("table", { name: /In the scene view/ })).toBeTruthy();
    await act(async () => fireEvent.keyDown(document.activeElement!, { key: "Escape" }));
    expect(screen.queryByRole("dialog")).toBeNull();
    expect(document.activeElement).toBe(button);
  });

  it("the ? key opens it and closes it; Tab keeps the focus in it", async () => {
    const h = setup();
    const off = bindKeyboard(h.editor);
    await act(async () => fireEvent.keyDown(document.body, { key: "?", shiftKey: true }));
    const dialog = screen.getByRole("dialog");
    const close = within(dialog).getByRole("button", { name: "Close" });
    await act(async () => fireEvent.keyDown(close, { key: "Tab" }));
    expect(document.activeElement).toBe(close);
    await act(async () => fireEvent.keyDown(close, { key: "?", shiftKey: true }));
    expect(screen.queryByRole("dialog")).toBeNull();
    off();
  });
});
