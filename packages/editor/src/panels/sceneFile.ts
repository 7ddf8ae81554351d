/**
 * Save file: the scene (format v1, sceneIo.sceneText) written to a file named as doc/saveName.ts
 * suggests (the file the scene came from, else one made from its title, else scene.chapgame.json).
 * One function for the header's Save file button and Ctrl/Cmd+S (keyboard.ts), `saveScene`. Where
 * the browser offers the File System Access API (`showSaveFilePicker`: Chromium-based browsers, in a
 * secure context) its save dialog opens with that name, and the name the user picks becomes the
 * scene's (the next save suggests it). Elsewhere, or when the browser refuses the dialog (a
 * SecurityError: no user gesture, a cross-origin frame), the scene is downloaded under the name.
 * Every outcome is said in the message bar with the file's name: saved (and where), not saved
 * because the dialog was closed, or not written (the scene is kept: save again); a saved one also
 * says when a value typed in a table cell is not in it (not committed yet: draftNote).
 */
import { saveNameFor } from "../doc/saveName";
import { sceneText } from "../doc/sceneIo";
import type { SceneFile } from "../engineTypes";
import type { SceneNames } from "../sceneNames";
import type { UiStore } from "../store/uiStore";

/** The part of a FileSystemFileHandle Save file uses. */
export interface SaveHandle {
  readonly name: string;
  createWritable(): Promise<{ write(data: string): Promise<void>; close(): Promise<void> }>;
}

/** The options of `showSaveFilePicker` Save file passes (File System Access API). */
export interface SavePickerOptions {
  suggestedName: string;
  id: string;
  types: { description: string; accept: Record<string, string[]> }[];
}

/** `window.showSaveFilePicker`, or null where the browser has none. */
export type SavePicker = ((options: SavePickerOptions) => Promise<SaveHandle>) | null;

/** The dialog's id: the browser opens the next one in the folder of the last scene saved. */
export const PICKER_ID = "chapgame-scene";

const TYPES = [{ description: "chapgame scene (JSON)", accept: { "application/json": [".json"] } }];

/** The save dialog of the page's window, where it has one. */
export function savePickerOf(page: Document): SavePicker {
  const w = page.defaultView as (Window & { showSaveFilePicker?: unknown }) | null;
  const picker = w?.showSaveFilePicker;
  return typeof picker === "function" ? (options) => picker.call(w, options) : null;
}

/** Downloads `text` as a file named `name` (the browser may add a number to a name taken). */
export function downloadText(text: string, name: string, page: Document = document): void {
  const blob = new Blob([text], { type: "application/json" });
  const a = page.createElement("a");
  a.href = URL.createObjectURL(blob);
  a.download = name;
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}

/** The editor's parts Save file uses. */
export interface SavingEditor {
  doc: SceneFile;
  names: SceneNames;
  ui: UiStore;
  info(text: string): void;
}

/** An error's own words (a DOMException is not an Error everywhere). */
const reasonOf = (e: unknown): string => {
  const m = (e as { message?: unknown } | null)?.message;
  return typeof m === "string" && m !== "" ? m : String(e);
};
const nameOf = (e: unknown): string | undefined =>
  (e as { name?: unknown } | null)?.name as string | undefined;

/**
 * Saves the editor's scene as it is now and says so in the message bar, with the file's name.
 * `picker` is called before anything is awaited: the browser opens its dialog only within the
 * click or key press that asked for it.
 */
export async function saveScene(
  editor: SavingEditor,
  page: Document = document,
  picker: SavePicker = savePickerOf(page),
): Promise<void> {
  const doc = editor.doc;
  const name = saveNameFor(editor.names.name, doc);
  const text = sceneText(doc);
  const draft = draftNote(page);
  if (picker === null) {
    downloadText(text, name, page);
    editor.info(`Saved the scene as ${name} (in the browser's downloads).${draft}`);
    return;
  }
  let handle: SaveHandle;
  try {
    handle = await picker({ suggestedName: name, id: PICKER_ID, types: TYPES });
  } catch (e) {
    if (nameOf(e) === "AbortError") {
      editor.info(`Not saved: the save dialog was closed without saving (it suggested ${name}).`);
      return;
    }
    downloadText(text, name, page);
    editor.info(
      `Saved the scene as ${name} (in the browser's downloads: the browser refused its save dialog: ${reasonOf(e)}).${draft}`,
    );
    return;
  }
  try {
    const out = await handle.createWritable();
    await out.write(text);
    await out.close();
  } catch (e) {
    editor.ui.setState({
      message: {
        text: `Not saved: ${handle.name} could not be written (${reasonOf(e)}). The scene is still here: save it again, in another folder or under another name.`,
        tone: "error",
      },
    });
    return;
  }
  editor.names.saved(handle.name);
  editor.info(`Saved the scene as ${handle.name}.${draft}`);
}

/**
 * What a save says of a value typed in a table cell and not committed (Ctrl+S works in a cell): it
 * is not in the file, so the author who typed x = 5 and pressed Ctrl+S is told; "" when none is.
 */
export function draftNote(page: Document): string {
  const label = page.querySelector("input[data-draft]")?.getAttribute("aria-label");
  return label ? ` The value typed in ${label} is not in it: press Enter there, then save again.` : "";
}
