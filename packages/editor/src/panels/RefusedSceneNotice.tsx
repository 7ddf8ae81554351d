/**
 * The notice that this tab's autosaved scene was refused at start (boot.ts; doc/refusedScene.ts):
 * the engine's reason, and the refused scene offered as a file (Save it as a file downloads its
 * text, to repair or open elsewhere). It stays, across reloads of this tab too, until dismissed;
 * Dismiss forgets the kept scene. When the storage could not keep it, the text is offered from
 * memory, and the notice says it goes with the page.
 */

import { dropRefused } from "../doc/refusedScene";
import { useEditor, useUi } from "../EditorContext";
import { NoticeText } from "./NoticeText";
import { downloadText } from "./sceneFile";

/** The downloaded file's name. */
export const REFUSED_NAME = "refused-scene.chapgame.json";

export function RefusedSceneNotice({ local = window.localStorage }: { local?: Storage }) {
  const editor = useEditor();
  const refused = useUi((s) => s.refusedScene);
  if (!refused) return null;
  const kept = refused.tab !== null;
  return (
    <div className="newer-work" role="alert" aria-label="Autosaved scene refused">
      <NoticeText
        text={`This tab's autosaved scene could not be opened: ${refused.reason}.${
          kept
            ? " The refused scene is kept until you dismiss this notice."
            : " It could not be kept in this browser's storage: save it now, or it goes with this page."
        }`}
      />
      <button type="button" onClick={() => downloadText(refused.text, REFUSED_NAME)}>
        Save it as a file
      </button>
      <button
        type="button"
        onClick={() => {
          if (refused.tab !== null) dropRefused(local, refused.tab);
          editor.ui.setState({ refusedScene: null });
        }}
      >
        Dismiss
      </button>
    </div>
  );
}
