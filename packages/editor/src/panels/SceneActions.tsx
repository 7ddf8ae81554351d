/**
 * The header's scene actions, first in the tab order and always in view (they sat at the foot of the
 * side column, off-screen at 1280×800 and hundreds of tab stops after the tables): Undo / Redo
 * (editorUndo.ts; Ctrl+Z, Ctrl+Shift+Z or Ctrl+Y), Save file (Ctrl/Cmd+S) and Load file (as a dropped
 * file, doc/openScene.ts). Clear scene, Share link and the scene JSON stay in the State panel.
 */
import { useRef } from "react";
import { openSceneFile } from "../doc/openScene";
import { canRedo as redoable, canUndo as undoable } from "../doc/undoIntents";
import { useEditor, useHistory } from "../EditorContext";
import { useStore } from "../store/createStore";
import { FocusKeptButton } from "./FocusKeptButton";
import { saveScene } from "./sceneFile";

export function SceneActions() {
  const editor = useEditor();
  // Undo is offered as soon as an edit is asked (also while its later actions are being checked:
  // Undo then takes it back), Redo for what Undo took (doc/undoIntents.ts). An edit asked clears
  // Redo at once, also during its check (the edit is shown); one the check refuses was never made,
  // so Redo comes back with the same entries (editorUndoDuringCheck.test.ts).
  const intents = useStore(editor.intents, (s) => s);
  const canUndo = undoable(
    intents,
    useHistory((h) => h.past.length),
  );
  const canRedo = redoable(
    intents,
    useHistory((h) => h.future.length),
  );
  const fileRef = useRef<HTMLInputElement>(null);
  return (
    <div className="scene-actions" role="toolbar" aria-label="Scene">
      <FocusKeptButton title="Ctrl+Z" enabled={canUndo} onPress={() => void editor.undo()}>
        Undo
      </FocusKeptButton>
      <FocusKeptButton title="Ctrl+Shift+Z or Ctrl+Y" enabled={canRedo} onPress={() => void editor.redo()}>
        Redo
      </FocusKeptButton>
      <button type="button" title="Ctrl+S" onClick={() => void saveScene(editor)}>
        Save file
      </button>
      <button type="button" onClick={() => fileRef.current?.click()}>
        Load file
      </button>
      <input
        ref={fileRef}
        type="file"
        accept=".json,application/json"
        aria-label="Scene file"
        hidden
        onChange={async (e) => {
          const f = e.target.files?.[0];
          if (f) await openSceneFile(editor, f);
          e.target.value = "";
        }}
      />
    </div>
  );
}
