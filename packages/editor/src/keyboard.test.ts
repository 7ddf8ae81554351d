// @vitest-environment jsdom
import { afterEach, describe, expect, it } from "vitest";
import type { Editor } from "./editor";
import { bindKeyboard } from "./keyboard";
import { createUiStore } from "./store/uiStore";
import { press } from "./testing/keys";

/** An editor that records which shortcut ran. */
function recorder() {
  const calls: string[] = [];
  const editor = {
    ui: createUiStore(),
    undo: async () => void calls.push("undo"),
    redo: async () => void calls.push("redo"),
    togglePlay: () => void calls.push("play"),
    stepEvent: async (d: number) => void calls.push(`step ${d}`),
    deleteSelection: async () => void calls.push("delete"),
  } as unknown as Editor;
  return { editor, calls };
}

/** A focused control of the given kind in the page. */
function control(tag: "input" | "textarea" | "button" | "select", type?: string): HTMLElement {
  const el = document.createElement(tag);
  if (type) el.setAttribute("type", type);
  document.body.append(el);
  el.focus();
  return el;
}

afterEach(() => {
  document.body.replaceChildren();
});

describe("keyboard shortcuts", () => {
  it("Ctrl+S and Cmd+S save the file anywhere, in a text field too (the browser's Save page is kept off)", () => {
    const { editor, calls } = recorder();
    const off = bindKeyboard(editor, window, () => calls.push("save"));
    expect(press(document.body, "s", { ctrlKey: true })).toBe(false);
    expect(press(control("input", "text"), "s", { ctrlKey: true })).toBe(false);
    expect(press(control("textarea"), "S", { metaKey: true })).toBe(false);
    expect(press(document.body, "s")).toBe(true); // plain s is nothing
    expect(calls).toEqual(["save", "save", "save"]);
    off();
  });

  it("on the Time slider: Ctrl+Z, Ctrl+Shift+Z and space work; the arrows stay the slider's", () => {
    const { editor, calls } = recorder();
    const off = bindKeyboard(editor);
    const slider = control("input", "range");
    expect(press(slider, "z", { ctrlKey: true })).toBe(false);
    expect(press(slider, "Z", { ctrlKey: true, shiftKey: true })).toBe(false);
    expect(press(slider, " ")).toBe(false);
    expect(press(slider, "ArrowLeft")).toBe(true);
    expect(calls).toEqual(["undo", "redo", "play"]);
    off();
  });

  it("on a checkbox: Ctrl+Z undoes, space stays the checkbox's", () => {
    const { editor, calls } = recorder();
    const off = bindKeyboard(editor);
    const box = control("input", "checkbox");
    expect(press(box, " ")).toBe(true);
    expect(press(box, "z", { ctrlKey: true })).toBe(false);
    expect(calls).toEqual(["undo"]);
    off();
  });

  it("on a list (a line's kind): Ctrl+Z undoes, its other keys stay the list's", () => {
    const { editor, calls } = recorder();
    const off = bindKeyboard(editor);
    const list = control("select");
    expect(press(list, " ")).toBe(true);
    expect(press(list, "ArrowDown")).toBe(true);
    expect(press(list, "Delete")).toBe(true);
    expect(press(list, "z", { ctrlKey: true })).toBe(false);
    expect(calls).toEqual(["undo"]);
    off();
  });

  it("on a button: space and Enter press it (no play/pause); the other shortcuts work", () => {
    const { editor, calls } = recorder();
    const off = bindKeyboard(editor);
    for (const button of [control("button"), control("input", "button")]) {
      expect(press(button, " ")).toBe(true);
      expect(press(button, "Enter")).toBe(true);
      expect(press(button, "ArrowRight")).toBe(false);
      expect(press(button, "z", { ctrlKey: true })).toBe(false);
    }
    expect(calls).toEqual(["step 1", "undo", "step 1", "undo"]);
    off();
  });

  it("typing in a text field or a text area runs no shortcut", () => {
    const { editor, calls } = recorder();
    const off = bindKeyboard(editor);
    for (const field of [control("input", "text"), control("input"), control("textarea")]) {
      for (const [key, mods] of [
        ["z", { ctrlKey: true }],
        [" ", {}],
        ["ArrowLeft", {}],
        ["Backspace", {}],
      ] as const)
        expect(press(field, key, mods)).toBe(true);
    }
    expect(calls).toEqual([]);
    off();
  });

  it("in a table cell (a cell's button): Delete and Backspace delete nothing, the others work", () => {
    // a focused cell selects its row: Backspace after Enter in a cell deleted that body (audit)
    const { editor, calls } = recorder();
    const off = bindKeyboard(editor);
    const table = document.createElement("table");
    const cell = document.createElement("td");
    const button = document.createElement("button");
    cell.append(button);
    table.append(cell);
    document.body.append(table);
    button.focus();
    expect(press(button, "Backspace")).toBe(true);
    expect(press(button, "Delete")).toBe(true);
    press(button, "z", { ctrlKey: true });
    expect(calls).toEqual(["undo"]);
    off();
  });

  it("on a focused table row (an Event log entry): Delete and Backspace delete nothing, the others work", () => {
    // Enter on an entry selects a participant: Delete then removed that body at the entry's time (audit)
    const { editor, calls } = recorder();
    const off = bindKeyboard(editor);
    const table = document.createElement("table");
    const row = document.createElement("tr");
    row.tabIndex = 0;
    table.append(row);
    document.body.append(table);
    row.focus();
    expect(press(row, "Delete")).toBe(true);
    expect(press(row, "Backspace")).toBe(true);
    press(row, "ArrowRight");
    expect(calls).toEqual(["step 1"]);
    off();
  });

  it("elsewhere (the page, a button): every shortcut", () => {
    const { editor, calls } = recorder();
    const off = bindKeyboard(editor);
    press(document.body, " ");
    press(document.body, "ArrowRight");
    press(document.body, "ArrowLeft");
    press(control("button"), "Delete");
    press(document.body, "y", { ctrlKey: true });
    expect(calls).toEqual(["play", "step 1", "step -1", "delete", "redo"]);
    off();
  });
});
