/**
 * The ✕ of an Event-log action entry: removes that one action from the scene (Editor.removeAction,
 * one undo step). Its accessible name says which action: `Remove action updateBody of b1 at t = 4`
 * (`Remove action setGlobal at t = 2` without an id). The click does not reach the row (which
 * would jump to the entry's time).
 */
import { useEditor } from "../EditorContext";
import { formatNumber } from "./EditableCell";

export function RemoveActionButton(props: { index: number; time: number; type: string; id: string | null }) {
  const editor = useEditor();
  const { index, time, type, id } = props;
  const what = id === null ? type : `${type} of ${id}`;
  return (
    <button
      type="button"
      className="log-remove"
      aria-label={`Remove action ${what} at t = ${formatNumber(time)}`}
      title="Remove this action from the scene"
      onClick={(ev) => {
        ev.stopPropagation();
        void editor.removeAction(index, { time, type, id });
      }}
    >
      ✕
    </button>
  );
}
