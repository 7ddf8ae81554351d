/**
 * The scene's refused action, over the Event log's entries (doc/refusedAction.ts): the action the
 * engine refused when the computation reached it, which stopped the computation there. It never
 * happened, so the log (the computed history) has no entry for it and no table a row: shown here,
 * marked "refused", named as the author knows it ("the action at t = 1 s that adds disc "b3"") with
 * the engine's reason as its description, with the log's ✕ (RemoveActionButton: two presses, one
 * undo step) and a cell for each of its fields (t, x, y, r, m, μ, vx, vy for a disc; EditableCell as
 * in the tables), whose commit replaces the action (Editor.changeAction, one undo step; a value
 * still refused is said in place, the action kept as it was, and stays said as it is when the time
 * moves: unlike a table cell's, the edit does not apply at the current time). Removed or changed so that it is
 * accepted, the rest of the scene computes on. Nothing is drawn when no action is refused.
 */
import { useId } from "react";
import { actionFields, entryOf, refusedAction } from "../doc/refusedAction";
import { useEditor, useInfoValue } from "../EditorContext";
import { EditableCell, formatNumber, parseNumber } from "./EditableCell";
import { RemoveActionButton } from "./RemoveActionButton";
import { notANumber } from "./typedRefusal";
import type { ArmedNotice } from "./useArmedNotice";

export function RefusedActionRow({ notice }: { notice: ArmedNotice }) {
  const editor = useEditor();
  // primitives: the refused action is read from the snapshot they belong to
  const stopped = useInfoValue((i) => i.stopped);
  const path = useInfoValue((i) => i.stoppedPath);
  const docRevision = useInfoValue((i) => i.docRevision);
  const reasonId = useId();
  const refused = refusedAction({ stopped, stoppedPath: path, doc: editor.client.getSnapshot().doc });
  if (refused === null) return null;
  const { index, action, reason, name } = refused;
  const entry = entryOf(action);
  const what = name.replace(/^the action/, "refused action");
  const fields = actionFields(action);
  return (
    <div className="refused-action">
      <p id={reasonId}>
        <strong className="refused-mark">refused</strong> {name}: {reason}
      </p>
      <div className="table-scroll">
        <table aria-label="Refused action" aria-describedby={reasonId}>
          <thead>
            <tr>
              {fields.map((f) => (
                <th key={f.name}>{f.name}</th>
              ))}
              <th />
            </tr>
          </thead>
          <tbody>
            <tr className="refused">
              {fields.map((f) => (
                <td key={f.name}>
                  <EditableCell
                    label={`${what} ${f.name}`}
                    value={formatNumber(f.value)}
                    size={6}
                    // the action's own time is one of its fields: its edits apply whatever the time shown
                    atCurrentTime={false}
                    onCommit={async (text) => {
                      const v = parseNumber(text);
                      if (v === null) return notANumber(`${what} ${f.name}`, text);
                      return editor.changeAction(index, entry, f.set(v), f.name);
                    }}
                  />
                </td>
              ))}
              <td className="row-end">
                <RemoveActionButton
                  index={index}
                  time={entry.time}
                  type={entry.type}
                  id={entry.id}
                  revision={docRevision}
                  notice={notice}
                />
              </td>
            </tr>
          </tbody>
        </table>
      </div>
    </div>
  );
}
