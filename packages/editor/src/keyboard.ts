/**
 * Keyboard shortcuts: space play/pause, ←/→ previous/next event, Ctrl+Z undo, Ctrl+Shift+Z (or
 * Ctrl+Y) redo, Delete/Backspace delete the selection. Ignored while typing in a field; on other
 * controls (the Time slider, a checkbox, a list) only the keys the control uses itself are left to
 * it (the slider's arrows, a checkbox's or a button's space and Enter, a list's keys but Ctrl+Z/Y),
 * so Ctrl+Z and space still work after scrubbing or picking a line kind, and space on a focused
 * button presses it.
 */
import type { Editor } from "./editor";

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

export function handleKey(editor: Editor, e: KeyboardEvent): boolean {
  if (ownsKey(e.target, e)) return false;
  const mod = e.ctrlKey || e.metaKey;
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

export function bindKeyboard(editor: Editor, target: Window = window): () => void {
  const listener = (e: KeyboardEvent) => {
    if (handleKey(editor, e)) e.preventDefault();
  };
  target.addEventListener("keydown", listener);
  return () => target.removeEventListener("keydown", listener);
}
