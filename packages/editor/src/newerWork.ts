/**
 * Another tab's newer work, as the notice under the header offers it (panels/NewerWorkNotice.tsx):
 * the clock time of its save, and opening it as one undo step over this tab's scene.
 */
import { readSlot } from "./doc/autosaveSlots";
import type { Editor } from "./editor";

/** The clock time of a save, for the user (hh:mm:ss, local time). */
export const clockTime = (ms: number) => new Date(ms).toLocaleTimeString();

/** Opens the scene another tab saved (one undo step over this tab's scene). */
export async function openNewerWork(editor: Editor, storage: Storage, tab: string): Promise<string | null> {
  editor.ui.setState({ newerWork: null });
  const slot = readSlot(storage, tab);
  if (!slot) {
    const text = "That tab's scene is no longer stored (it was closed long ago or pruned).";
    editor.ui.setState({ message: { text, tone: "error" } });
    return text;
  }
  const err = await editor.loadScene(slot.scene, { name: slot.name }); // with its file name
  if (err === null)
    editor.info(
      `Opened the scene another tab saved at ${clockTime(slot.savedAt)}. Undo returns to the scene you had.`,
    );
  return err;
}
