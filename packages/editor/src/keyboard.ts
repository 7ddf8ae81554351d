/**
 * Keyboard shortcuts: space play/pause, ←/→ previous/next event, Ctrl+Z undo, Ctrl+Shift+Z (or
 * Ctrl+Y) redo, Delete/Backspace delete the selection. Ignored while typing in a field.
 */
import type { Editor } from "./editor";

function typing(target: EventTarget | null): boolean {
  if (!(target instanceof HTMLElement)) return false;
  const tag = target.tagName;
  return tag === "INPUT" || tag === "TEXTAREA" || tag === "SELECT" || target.isContentEditable;
}

export function handleKey(editor: Editor, e: KeyboardEvent): boolean {
  if (typing(e.target)) return false;
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
