/**
 * A shared link opened in a tab that is already open: only the address's hash changes (no reload),
 * so boot.ts never saw it, and the link sat in the address bar until the next reload replaced the
 * work done since (review, session 19). On `hashchange` to `#scene=...` the scene is loaded at once
 * as one undo step (Undo returns to the scene the tab had), or its damage is said; either way the
 * hash is then removed, as at start, so a reload keeps the tab's own work.
 */
import { sceneFromHash } from "./doc/persistence";
import type { Editor } from "./editor";

/** What is said once a shared scene is opened over the tab's scene. */
export const OPENED_SHARED = "Opened the shared scene. Undo returns to the scene you had before.";

/** Opens the scene of `hash` (`#scene=...`) in `editor`; false when the hash holds no scene link. */
export async function openSharedHash(editor: Editor, hash: string): Promise<boolean> {
  if (!/^#?scene=/.test(hash)) return false;
  let scene: ReturnType<typeof sceneFromHash>;
  try {
    scene = sceneFromHash(hash);
  } catch (e) {
    editor.ui.setState({ message: { text: `Shared link: ${(e as Error).message}`, tone: "error" } });
    return true;
  }
  if (scene === null) return false;
  if ((await editor.loadScene(scene)) === null) editor.info(OPENED_SHARED);
  return true;
}

/** Listens for shared links opened in this tab (see the header); returns a function that stops. */
export function listenForSharedLinks(editor: Editor, win: Window): () => void {
  const onHash = () => {
    const hash = win.location.hash;
    if (!/^#?scene=/.test(hash)) return;
    win.history.replaceState(null, "", win.location.pathname + win.location.search);
    void openSharedHash(editor, hash);
  };
  win.addEventListener("hashchange", onHash);
  return () => win.removeEventListener("hashchange", onHash);
}
