/**
 * The header's Title field: the scene's title (`meta.title`, doc/sceneTitle.ts), saved in the file.
 * Typed text is applied on Enter or on leaving the field (Editor.setTitle: one undo step, nothing
 * recomputed; blank removes the title), Escape drops it (useTypedField.tsx). The format limits a
 * title in nothing, so none is refused. The field's tooltip (its accessible description) says the
 * file name Save file suggests (doc/saveName.ts: made from the title when the scene has no file of the author's), which
 * follows the title as it changes.
 */
import { saveNameFor } from "../doc/saveName";
import { titleOf } from "../doc/sceneTitle";
import { useEditor, useInfoValue } from "../EditorContext";
import { useStore } from "../store/createStore";
import { useTypedField } from "./useTypedField";

export const TITLE_LABEL = "Scene title";

export function SceneTitle() {
  const editor = useEditor();
  const doc = useInfoValue((i) => i.doc);
  const fileName = useStore(editor.names.current, (s) => s.name);
  const saveName = doc === null ? null : saveNameFor(fileName, doc);
  const field = useTypedField(doc === null ? "" : titleOf(doc), (typed) => {
    void editor.setTitle(typed);
    return null;
  });
  return (
    <label className="scene-title">
      Title{" "}
      <input
        aria-label={TITLE_LABEL}
        // a title that is not text (a file written elsewhere) is not shown: say it is there
        placeholder={
          doc !== null && doc.meta?.title !== undefined && titleOf(doc) === ""
            ? "the file's title is not text"
            : "untitled"
        }
        size={18}
        title={saveName === null ? undefined : `Save file suggests ${saveName}`}
        {...field.input}
      />
    </label>
  );
}
