/**
 * Keyboard shortcuts: space play/pause, ←/→ previous/next event, Ctrl+Z undo, Ctrl+Shift+Z (or
 * Ctrl+Y) redo, Ctrl+S (Cmd+S) save file, Delete/Backspace delete the selection. Ctrl+S works
 * everywhere, in a field too (no field uses it, and the browser would offer to save the page); it
 * saves the scene as it is (text typed in a cell and not yet committed is not in it). Ignored while typing in a field; on other
 * controls (the Time slider, a checkbox, a list) only the keys the control uses itself are left to
 * it (the slider's arrows, a checkbox's or a button's space and Enter, a list's keys but Ctrl+Z/Y),
 * so Ctrl+Z and space still work after scrubbing or picking a line kind, and space on a focused
 * button presses it.
 */
import type { Editor } from "./editor";
import { saveSceneFile } from "./panels/sceneFile";

/** Input types whose keys are text editing (every shortcut is left to them). */
const TEXT_INPUTS = new Set(["text", "search", "number", "email", "url", "tel", "password"]);

/** Whether the focused element `target` uses `e` itself, so it is no shortcut. */
function ownsKey(target: EventTarget | null, e: KeyboardEvent): boolean {
  if (!(target instanceof HTMLElement)) return false;
  // A table cell keeps Delete and Backspace (as a spreadsheet's does): they deleted the body whose
  // row a focused cell had selected.
  if ((e.key === "Delete" || e.key === "Backspace") && target.closest("td, th") !== null) return true;
  const tag = target.tagName;
  if (tag === "TEXTAREA" || target.isContentEditable) return true;
  if (tag === "SELECT") return !(e.ctrlKey || e.metaKey); // a list keeps its keys, not Ctrl+Z
  if (tag === "BUTTON" || tag === "SUMMARY" || target.getAttribute("role") === "button")
    return !(e.ctrlKey || e.metaKey || e.altKey) && (e.key === " " || e.key === "Enter");
  if (tag !== "INPUT") return false;
  const type = (target as HTMLInputElement).type;
  if (TEXT_INPUTS.has(type) || type.startsWith("date") || type === "time" || type === "month") return true;
  if (e.ctrlKey || e.metaKey) return false;
  if (e.key === " ") return type !== "range";
  if (e.key.startsWith("Arrow")) return type === "range" || type === "radio";
  return false;
}

export function handleKey(editor: Editor, e: KeyboardEvent, save: () => void = () => {}): boolean {
  const mod = e.ctrlKey || e.metaKey;
  if (mod && !e.shiftKey && !e.altKey && e.key.toLowerCase() === "s") {
    save();
    return true;
  }
  if (ownsKey(e.target, e)) return false;
  if (mod && e.key.toLowerCase() === "z") {
    void (e.shiftKey ? editor.redo() : editor.undo());
    return true;
  }
  if (mod && e.key.toLowerCase() === "y") {
    void editor.redo();
    return true;
  }
  if (mod || e.altKey) return false;
  switch (e.key) {
    case " ":
      editor.togglePlay();
      return true;
    case "ArrowLeft":
      void editor.stepEvent(-1);
      return true;
    case "ArrowRight":
      void editor.stepEvent(1);
      return true;
    case "Delete":
    case "Backspace":
      void editor.deleteSelection();
      return true;
  }
  return false;
}

/** `save`: what Ctrl+S does (Save file: panels/sceneFile.ts). */
export function bindKeyboard(
  editor: Editor,
  target: Window = window,
  save: () => void = () => saveSceneFile(editor.doc),
): () => void {
  const listener = (e: KeyboardEvent) => {
    if (handleKey(editor, e, save)) e.preventDefault();
  };
  target.addEventListener("keydown", listener);
  return () => target.removeEventListener("keydown", listener);
}
