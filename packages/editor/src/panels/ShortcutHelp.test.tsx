// @vitest-environment jsdom
// The Keyboard shortcuts dialog: the toolbar's ? button and the ? key open it; it lists every
// shortcut of the table the keyboard handler runs (shortcuts.ts), takes the focus and gives it back.
import { act, cleanup, fireEvent, render, screen, within } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { loadCharacterKeys } from "../characterKeys";
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
    const toggle = within(dialog).getByRole("checkbox", { name: /One-character shortcuts/ });
    await act(async () => fireEvent.keyDown(close, { key: "Tab" }));
    expect(document.activeElement).toBe(toggle);
    await act(async () => fireEvent.keyDown(toggle, { key: "Tab" }));
    expect(document.activeElement).toBe(close);
    await act(async () => fireEvent.keyDown(close, { key: "Tab", shiftKey: true }));
    expect(document.activeElement).toBe(toggle);
    await act(async () => fireEvent.keyDown(toggle, { key: "?", shiftKey: true }));
    expect(screen.queryByRole("dialog")).toBeNull();
    off();
  });

  it("its switch turns the one-character shortcuts off and on, kept across reloads (WCAG 2.1.4)", async () => {
    localStorage.clear();
    const h = setup();
    const off = bindKeyboard(h.editor);
    await act(async () => fireEvent.click(screen.getByRole("button", { name: "Keyboard shortcuts" })));
    const toggle = within(screen.getByRole("dialog")).getByRole("checkbox", { name: /One-character/ });
    expect((toggle as HTMLInputElement).checked).toBe(true);
    await act(async () => fireEvent.click(toggle));
    expect(h.editor.ui.getState().characterKeys).toBe(false);
    expect(loadCharacterKeys(localStorage)).toBe(false);
    await act(async () =>
      fireEvent.click(within(screen.getByRole("dialog")).getByRole("button", { name: "Close" })),
    );
    // off: the letters, digits, + and ? do nothing; the keys with Ctrl, the arrows and Delete still work
    const before = h.editor.ui.getState();
    for (const key of ["3", "t", "p", "+", "f", "?"]) fireEvent.keyDown(document.body, { key });
    expect(h.editor.ui.getState()).toMatchObject({
      tool: before.tool,
      trails: before.trails,
      path: before.path,
      view: before.view,
      fitRequest: before.fitRequest,
      help: false,
    });
    // on again, a digit picks a tool
    await act(async () => fireEvent.click(screen.getByRole("button", { name: "Keyboard shortcuts" })));
    await act(async () => fireEvent.click(within(screen.getByRole("dialog")).getByRole("checkbox")));
    expect(loadCharacterKeys(localStorage)).toBe(true);
    await act(async () => fireEvent.keyDown(document.activeElement!, { key: "Escape" }));
    fireEvent.keyDown(document.body, { key: "3" });
    expect(h.editor.ui.getState().tool).toBe("cue");
    off();
  });
});
