/**
 * Opening a scene the user hands over: pasted text, a file from Load file, a file dropped on the
 * page. One path for all: the engine's validation (a refusal names the field, and a file's name
 * before it), the current scene kept on any refusal, and an opened scene is one undo step over the
 * one it replaces. droppedSceneFile says which file of a drop to open, or why none.
 */
import type { Editor } from "../editor";
import { parseSceneText } from "./sceneIo";

/** Loads scene text; a refusal names `origin` (a file's name and ": ") before the field and the reason. */
export async function openSceneText(editor: Editor, source: string, origin = ""): Promise<string | null> {
  let err: string | null;
  try {
    err = await editor.loadScene(parseSceneText(source));
  } catch (e) {
    err = e instanceof Error ? e.message : String(e);
  }
  if (err !== null) {
    const text = origin + err;
    editor.ui.setState({ message: { text, tone: "error" } });
    return text;
  }
  return null;
}

/** Opens a scene file (Load file, or dropped); says so, and that Undo returns to the scene before. */
export async function openSceneFile(editor: Editor, file: File): Promise<string | null> {
  let text: string;
  try {
    text = await file.text();
  } catch (e) {
    const msg = `${file.name}: could not be read (${e instanceof Error ? e.message : String(e)})`;
    editor.ui.setState({ message: { text: msg, tone: "error" } });
    return msg;
  }
  const err = await openSceneText(editor, text, `${file.name}: `);
  if (err === null) editor.info(`Opened ${file.name}. Undo returns to the scene you had before.`);
  return err;
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
