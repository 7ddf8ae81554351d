/**
 * Opening a scene the user hands over: pasted text, a file from Load file, a file dropped on the
 * page. One path for all: the engine's validation (a refusal names the field, and a file's name
 * before it; an action's field names the action as the author knows it, doc/actionRefs.ts), the current scene kept on any refusal, and an opened scene is one undo step over the
 * one it replaces; an opened file's name is what Save file suggests for it. A refused file or paste
 * names where the text came from and ends saying the scene is kept (KEPT). droppedSceneFile says
 * which file of a drop to open, or why none.
 */
import type { Editor } from "../editor";
import { namedTextRefusal } from "./actionRefs";
import { parseSceneText } from "./sceneIo";

/**
 * Loads scene text; a refusal names `origin` (a file's name and ": ") before the field and the
 * reason, and ends with `after`. `name`: the file name the scene came from, which Save file then
 * suggests (null: none).
 */
export async function openSceneText(
  editor: Editor,
  source: string,
  origin = "",
  name: string | null = null,
  after = "",
): Promise<string | null> {
  let err: string | null;
  try {
    err = await editor.loadScene(parseSceneText(source), { name });
  } catch (e) {
    // the engine's `actions[i]` of the text given, named as the author knows the action
    err = namedTextRefusal(e, source);
  }
  if (err !== null) {
    const text = origin + err + after;
    editor.ui.setState({ message: { text, tone: "error" } });
    return text;
  }
  return null;
}

/** What a refused file's message ends with. */
export const KEPT = "; nothing was opened (your scene is as it was).";

/**
 * Opens pasted scene text (the State panel's Paste); says so, and that Undo returns to the scene
 * before. A refusal is worded as a refused file's is, "Pasted text: " in place of the file's name.
 */
export async function openPastedText(editor: Editor, text: string): Promise<string | null> {
  const err = await openSceneText(editor, text, "Pasted text: ", null, KEPT);
  if (err === null) editor.info("Pasted the scene. Undo returns to the scene you had before.");
  return err;
}

/** Opens a scene file (Load file, or dropped); says so, and that Undo returns to the scene before. */
export async function openSceneFile(editor: Editor, file: File): Promise<string | null> {
  let bytes: Uint8Array;
  try {
    bytes = new Uint8Array(await file.arrayBuffer());
  } catch (e) {
    const msg = `${file.name}: could not be read (${e instanceof Error ? e.message : String(e)})`;
    editor.ui.setState({ message: { text: msg, tone: "error" } });
    return msg;
  }
  const text = decodeUtf8OrNull(bytes);
  if (text === null) {
    const msg = `${file.name}: not UTF-8 text (a scene file is UTF-8 JSON: save it as UTF-8 and open it again); nothing was opened.`;
    editor.ui.setState({ message: { text: msg, tone: "error" } });
    return msg;
  }
  // A refusal says the scene is kept, as the other refusals of a file do ("nothing was opened").
  const err = await openSceneText(editor, text, `${file.name}: `, file.name, KEPT);
  if (err === null) editor.info(`Opened ${file.name}. Undo returns to the scene you had before.`);
  return err;
}

/**
 * The file's bytes as text, or null when they are not UTF-8. A lenient decode (what `File.text()`
 * does) would turn each bad byte into U+FFFD, and an id like "café" saved as Latin-1 would open as
 * a different id without a word; the CLI refuses such a file too. A leading BOM is dropped.
 */
function decodeUtf8OrNull(bytes: Uint8Array): string | null {
  try {
    return new TextDecoder("utf-8", { fatal: true }).decode(bytes);
  } catch {
    return null;
  }
}

/** Whether a file is offered as JSON (by its name or its type): only those are read on a drop. */
export function isJsonFile(file: { name: string; type: string }): boolean {
  return /\.json$/i.test(file.name) || file.type === "application/json";
}

/** The one scene file of a drop, or the message that says why nothing is opened. */
export function droppedSceneFile(files: ArrayLike<File>): File | string {
  if (files.length === 0) return "Nothing to open: drop a scene file (.json).";
  if (files.length > 1)
    return `Drop one scene file at a time (${files.length} files were dropped); nothing was opened.`;
  const file = files[0]!;
  if (!isJsonFile(file))
    return `${file.name}: not a scene file (drop a .json scene file, format chapgame v1); nothing was opened.`;
  return file;
}
