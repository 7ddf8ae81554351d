/**
 * The notice that this tab's autosaved scene was refused at start (boot.ts; doc/refusedScene.ts):
 * the engine's reason, and the refused scene offered as a file (Save it as a file downloads its
 * text as it was kept, to repair or open elsewhere). It stays, across reloads too, until dismissed;
 * Dismiss forgets the kept scene.
 */

import { dropRefused, readRefused } from "../doc/refusedScene";
import { useEditor, useUi } from "../EditorContext";

/** The downloaded file's name. */
export const REFUSED_NAME = "refused-scene.chapgame.json";

function download(text: string, page: Document): void {
  const a = page.createElement("a");
  a.href = URL.createObjectURL(new Blob([text], { type: "application/json" }));
  a.download = REFUSED_NAME;
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}

export function RefusedSceneNotice({ local = window.localStorage }: { local?: Storage }) {
  const editor = useEditor();
  const refused = useUi((s) => s.refusedScene);
  if (!refused) return null;
  const kept = readRefused(local);
  return (
    <div className="newer-work" role="alert" aria-label="Autosaved scene refused">
      <span>
        This tab's autosaved scene could not be opened: {refused.reason}.
        {kept ? " The refused scene is kept until you dismiss this notice." : " It could not be kept."}
      </span>
      {kept && (
        <button type="button" onClick={() => download(kept.text, document)}>
          Save it as a file
        </button>
      )}
      <button
        type="button"
        onClick={() => {
          dropRefused(local);
          editor.ui.setState({ refusedScene: null });
        }}
      >
        Dismiss
      </button>
    </div>
  );
}
