/**
 * The notice that another tab saved newer work than this tab's (autosave.ts): not a modal, it hangs
 * over the top of the canvas (StageNotices.tsx) until the reader opens that work (one undo step over
 * this tab's scene) or dismisses it (that tab is not announced again until this one reloads).
 */

import { useEditor, useUi } from "../EditorContext";
import { clockTime, openNewerWork } from "../newerWork";
import { NoticeText } from "./NoticeText";

export function NewerWorkNotice() {
  const editor = useEditor();
  const newer = useUi((s) => s.newerWork);
  if (!newer) return null;
  return (
    <div className="newer-work" role="status" aria-label="Newer work in another tab">
      <NoticeText text={`Another editor tab saved a newer scene at ${clockTime(newer.savedAt)}.`} />
      <button type="button" onClick={() => void openNewerWork(editor, window.localStorage, newer.tab)}>
        Open it
      </button>
      <button type="button" onClick={() => editor.ui.setState({ newerWork: null })}>
        Dismiss
      </button>
    </div>
  );
}
