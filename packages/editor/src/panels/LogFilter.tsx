/**
 * The Event log's filter field (one id, or ids separated by commas: remote/eventFilter.ts) and the
 * line under it that says why the filter keeps no entry (filterNote.ts: no body, line or point has
 * the id, with the ids close to it; or the object takes part in no entry of the computed history),
 * empty otherwise (no filter, entries shown, no page read yet: `total` null). The note is the
 * field's description, so a screen reader reads it with the field; the log keeps its one live
 * region for its ✕ (useArmedNotice). The scene's ids are read again only when the scene changes.
 */
import { useId, useMemo } from "react";
import { useEditor, useInfoValue } from "../EditorContext";
import { filterNote, sceneIds } from "./filterNote";

export function LogFilter(props: { filter: string; shown: number; total: number | null }) {
  const { filter, shown, total } = props;
  const editor = useEditor();
  const noteId = useId();
  const docRevision = useInfoValue((i) => i.docRevision);
  const horizon = useInfoValue((i) => i.horizon);
  // biome-ignore lint/correctness/useExhaustiveDependencies: the scene's ids change with its revision
  const ids = useMemo(() => sceneIds(editor.client.getSnapshot().doc?.actions ?? []), [editor, docRevision]);
  const note = total === null ? null : filterNote(filter, shown, ids, total, horizon);
  return (
    <>
      <div className="row">
        <input
          aria-label="Filter by body"
          aria-describedby={noteId}
          placeholder="id, or ids: a, b"
          title="Shows only the entries of one body, line or point; with ids separated by commas, the entries they all take part in (a pair's collisions)"
          size={14}
          value={filter}
          onChange={(e) => editor.ui.setState({ eventFilter: e.target.value })}
        />
      </div>
      <p className="log-note" id={noteId}>
        {note}
      </p>
    </>
  );
}
