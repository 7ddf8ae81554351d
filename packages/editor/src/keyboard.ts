/**
 * Runs the keyboard shortcuts of shortcuts.ts (the one table the Keyboard shortcuts dialog lists):
 * space play/pause, ←/→ previous/next event, Ctrl+Z undo, Ctrl+Shift+Z (or Ctrl+Y) redo, Ctrl+S
 * (Cmd+S) save file, Delete/Backspace delete the selection, and the view's and tools' keys. Ctrl+S
 * works everywhere, in a field too (no field uses it, and the browser would offer to save the page);
 * it saves the scene as it is (text typed in a cell and not yet committed is not in it: the message
 * says so, panels/sceneFile.ts draftNote). Ignored
 * while typing in a field or inside a dialog; on other controls (the Time slider, a checkbox, a list)
 * only the keys the control uses itself are left to it (the slider's arrows, a checkbox's or a
 * button's space and Enter, a list's keys but Ctrl+Z/Y), so Ctrl+Z and space still work after
 * scrubbing or picking a line kind, and space on a focused button presses it. The scene view
 * (the element marked data-keys="canvas") focused, its own shortcuts come first: there the arrows pan.
 */
import type { Size } from "./canvas/viewTransform";
import type { Editor } from "./editor";
import { saveScene } from "./panels/sceneFile";
import { type KeyContext, SHORTCUTS } from "./shortcuts";

/** Input types whose keys are text editing (every shortcut is left to them). */
const TEXT_INPUTS = new Set(["text", "search", "number", "email", "url", "tel", "password"]);

/** Whether the focused element `target` uses `e` itself, so it is no shortcut. */
function ownsKey(target: EventTarget | null, e: KeyboardEvent): boolean {
  if (!(target instanceof HTMLElement)) return false;
  // a dialog (the shortcuts list) keeps every key: Delete must not remove a body behind it
  if (target.closest("[role=dialog]") !== null) return true;
  // A table row or cell keeps Delete and Backspace (as a spreadsheet's does): they deleted the body
  // whose row a focused cell had selected, and on a focused Event log entry (a row) the participant
  // that Enter on it had selected, at the entry's time, without a word (audit).
  if ((e.key === "Delete" || e.key === "Backspace") && target.closest("tr, td, th") !== null) return true;
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

/** The scene view's element in `doc`, marked data-keys="canvas" (SceneCanvas). */
function sceneView(doc: Document | null): HTMLElement | null {
  return doc?.querySelector<HTMLElement>('[data-keys="canvas"]') ?? null;
}

/** The size of the scene view on screen, or null when it is not laid out. */
function viewSizeOf(el: HTMLElement | null): Size | null {
  const r = el?.getBoundingClientRect();
  return r && r.width > 0 && r.height > 0 ? { width: r.width, height: r.height } : null;
}

/** Runs the shortcut `e` is, if any; true when one ran (the browser's own handling is then kept off). */
export function handleKey(editor: Editor, e: KeyboardEvent, save: () => void = () => {}): boolean {
  const target = e.target instanceof HTMLElement ? e.target : null;
  if (editor.ui.getState().help) {
    // The shortcuts dialog is open, and modal: nothing runs behind it, also when a click left the
    // focus outside it (review: Delete then removed the selected body behind the dialog). From
    // outside, Escape and ? close it, as they do inside (where the dialog handles its own keys).
    if (target?.closest("[role=dialog]") != null || (e.key !== "Escape" && e.key !== "?")) return false;
    editor.ui.setState({ help: false });
    return true;
  }
  const onCanvas = target?.closest('[data-keys="canvas"]') != null;
  const owned = ownsKey(e.target, e);
  const c: KeyContext = {
    editor,
    save,
    viewSize: () => viewSizeOf(sceneView(target?.ownerDocument ?? null)),
  };
  // the scene view's own shortcuts first: focused, its arrows pan rather than step through events
  const order = onCanvas
    ? [...SHORTCUTS.filter((s) => s.where === "canvas"), ...SHORTCUTS.filter((s) => s.where !== "canvas")]
    : SHORTCUTS;
  for (const s of order) {
    if (s.where === "canvas" && !onCanvas) continue;
    if (s.where === "page" && owned) continue;
    if (s.character && !editor.ui.getState().characterKeys) continue;
    if (!s.matches(e)) continue;
    s.run(c, e);
    return true;
  }
  return false;
}

/** `save`: what Ctrl+S does (Save file: panels/sceneFile.ts). */
export function bindKeyboard(
  editor: Editor,
  target: Window = window,
  save: () => void = () => void saveScene(editor),
): () => void {
  const listener = (e: KeyboardEvent) => {
    if (handleKey(editor, e, save)) e.preventDefault();
  };
  target.addEventListener("keydown", listener);
  return () => target.removeEventListener("keydown", listener);
}
