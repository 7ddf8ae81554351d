// @vitest-environment jsdom
/**
 * The scene view's keys and the keys of the view and the tools, run by keyboard.ts from the table of
 * shortcuts.ts: the focused canvas pans with the arrows (elsewhere they step through events).
 */
import { afterEach, describe, expect, it } from "vitest";
import type { Editor } from "./editor";
import { bindKeyboard } from "./keyboard";
import { packFrame } from "./remote/packFrame";
import { SHORTCUTS } from "./shortcuts";
import { createUiStore } from "./store/uiStore";
import { press } from "./testing/keys";

const frame = packFrame(
  {
    time: 0,
    g: 9.81,
    gravity: [0, 0],
    bodies: ["b2", "b1", "b10"].map((id, i) => ({
      id,
      x: i * 1000,
      y: 0,
      vx: 0,
      vy: 0,
      ax: 0,
      ay: 0,
      r: 1,
      m: 1,
      mu: 0,
    })),
    lines: [{ id: "far", p1: [0, 5000], p2: [10, 5000], kind: "segment" }],
    points: [{ id: "q", p: [0, -3000] }],
  },
  0,
);

/** An editor over a real UI store that records the edits and steps asked for. */
function editorWith() {
  const calls: string[] = [];
  const ui = createUiStore({ view: { cx: 0, cy: 0, scale: 1 } });
  const editor = {
    ui,
    client: { latestFrame: frame },
    undo: async () => void calls.push("undo"),
    redo: async () => void calls.push("redo"),
    togglePlay: () => void calls.push("play"),
    stepEvent: async (d: number) => void calls.push(`step ${d}`),
    deleteSelection: async () => void calls.push("delete"),
  } as unknown as Editor;
  return { editor, ui, calls };
}

/** A focusable scene view in the page, as SceneCanvas renders it. */
function canvas(): HTMLElement {
  const el = document.createElement("canvas");
  el.tabIndex = 0;
  el.dataset.keys = "canvas";
  document.body.append(el);
  el.focus();
  return el;
}

afterEach(() => {
  document.body.replaceChildren();
});

describe("the scene view's keys", () => {
  it("the focused canvas pans with the arrows; the page's arrows still step through events", () => {
    const { editor, ui, calls } = editorWith();
    const off = bindKeyboard(editor);
    const c = canvas();
    expect(press(c, "ArrowRight")).toBe(false);
    expect(ui.getState().view.cx).toBeGreaterThan(0);
    press(c, "ArrowUp", { shiftKey: true });
    expect(ui.getState().view.cy).toBeGreaterThan(0);
    expect(calls).toEqual([]);
    press(document.body, "ArrowRight");
    expect(calls).toEqual(["step 1"]);
    // the page's other shortcuts work on the canvas
    press(c, " ");
    press(c, "z", { ctrlKey: true });
    expect(calls).toEqual(["step 1", "play", "undo"]);
    off();
  });

  it("+ and − zoom, F fits, digits pick a tool, T and P toggle Trails and Path, anywhere but in a field", () => {
    const { editor, ui } = editorWith();
    const off = bindKeyboard(editor);
    press(canvas(), "+");
    expect(ui.getState().view.scale).toBeGreaterThan(1);
    press(document.body, "-");
    press(document.body, "-");
    expect(ui.getState().view.scale).toBeLessThan(1);
    press(document.body, "f");
    expect(ui.getState().fitRequest).toBe(1);
    press(document.body, "4");
    expect(ui.getState().tool).toBe("disc");
    press(document.body, "t");
    press(document.body, "p");
    expect([ui.getState().trails, ui.getState().path]).toEqual([true, true]);
    press(document.body, "T", { shiftKey: true });
    expect(ui.getState().trails).toBe(false);
    const field = document.createElement("input");
    document.body.append(field);
    field.focus();
    for (const key of ["1", "+", "f", "n", "t", "?"]) expect(press(field, key)).toBe(true);
    expect(ui.getState().tool).toBe("disc");
    expect(ui.getState().help).toBe(false);
    off();
  });

  it("N and Shift+N go through the bodies, the lines and the points and bring each into view; Escape on the canvas selects nothing", () => {
    const { editor, ui } = editorWith();
    const off = bindKeyboard(editor);
    const c = canvas();
    // jsdom lays nothing out: the view's size on screen
    c.getBoundingClientRect = () => ({ width: 400, height: 300 }) as DOMRect;
    press(c, "n");
    expect(ui.getState().selection).toEqual({ kind: "body", id: "b1" });
    expect(ui.getState().view.cx).toBeGreaterThan(1000 - 200); // b1 at x = 1000, shown
    press(c, "n");
    expect(ui.getState().selection).toEqual({ kind: "body", id: "b2" }); // at x = 0
    press(c, "n");
    press(c, "n");
    // after the last body, the line: the view moves up to it (y = 5000)
    expect(ui.getState().selection).toEqual({ kind: "line", id: "far" });
    expect(ui.getState().view.cy).toBeGreaterThan(5000 - 150);
    press(c, "n");
    expect(ui.getState().selection).toEqual({ kind: "point", id: "q" });
    expect(ui.getState().view.cy).toBeLessThan(-3000 + 150);
    press(c, "n");
    expect(ui.getState().selection).toEqual({ kind: "body", id: "b1" }); // wraps round
    press(c, "N", { shiftKey: true });
    press(c, "N", { shiftKey: true });
    expect(ui.getState().selection).toEqual({ kind: "line", id: "far" });
    press(c, "Escape");
    expect(ui.getState().selection).toBeNull();
    press(c, "N", { shiftKey: true });
    expect(ui.getState().selection).toEqual({ kind: "point", id: "q" });
    off();
  });

  it("? opens the shortcuts list; inside a dialog no shortcut runs (Delete removed a body behind it)", () => {
    const { editor, ui, calls } = editorWith();
    const off = bindKeyboard(editor);
    press(document.body, "?", { shiftKey: true });
    expect(ui.getState().help).toBe(true);
    const dialog = document.createElement("div");
    dialog.setAttribute("role", "dialog");
    const close = document.createElement("button");
    dialog.append(close);
    document.body.append(dialog);
    close.focus();
    for (const key of ["Delete", " ", "ArrowLeft", "n"]) press(close, key);
    expect(calls).toEqual([]);
    expect(ui.getState().selection).toBeNull();
    off();
  });

  it("while the shortcuts list is open nothing runs behind it, also with the focus on the page (a click in it)", () => {
    const { editor, ui, calls } = editorWith();
    const off = bindKeyboard(editor);
    ui.setState({ selection: { kind: "body", id: "b1" }, help: true });
    const tool = ui.getState().tool;
    for (const key of ["Delete", " ", "ArrowLeft", "n", "3", "z"])
      expect(press(document.body, key, { ctrlKey: key === "z" })).toBe(true);
    expect(calls).toEqual([]);
    expect(ui.getState()).toMatchObject({ selection: { kind: "body", id: "b1" }, tool, help: true });
    // Escape (or ?) from the page closes it, and then the keys work again
    expect(press(document.body, "Escape")).toBe(false);
    expect(ui.getState().help).toBe(false);
    press(document.body, "Delete");
    expect(calls).toEqual(["delete"]);
    off();
  });

  it("every shortcut has keys and words for the list, and no two of one place share a key", () => {
    const seen = new Set<string>();
    for (const s of SHORTCUTS) {
      expect(s.keys.length).toBeGreaterThan(0);
      expect(s.what.length).toBeGreaterThan(3);
      for (const k of s.keys) {
        const key = `${s.where === "canvas" ? "canvas" : "page"} ${k}`;
        expect(seen.has(key), key).toBe(false);
        seen.add(key);
      }
    }
  });
});
