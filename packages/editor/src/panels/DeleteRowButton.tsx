/**
 * The ✕ button at the end of a Bodies / Lines / Points row: selects the object and deletes the
 * selection (one undo step, like the Delete key). Its accessible name is `Delete <id>`.
 */
import { useEditor } from "../EditorContext";

export function DeleteRowButton({ kind, id }: { kind: "body" | "line" | "point"; id: string }) {
  const editor = useEditor();
  return (
    <button
      type="button"
      aria-label={`Delete ${id}`}
      onClick={() => {
        editor.ui.setState({ selection: { kind, id } });
        void editor.deleteSelection();
      }}
    >
      ✕
    </button>
  );
}
