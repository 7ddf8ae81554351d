/**
 * The Lines table: id, kind, both points of every line, ray and segment; editable; Add and Delete.
 * "Skip the Lines table" (SkipTable, shown when focused) passes its cells in one Tab press.
 */

import { useRef } from "react";
import { useEditor, useSceneSerial } from "../EditorContext";
import type { LineKind } from "../engineTypes";
import { addLineNearCentre } from "./addNear";
import { inNaturalOrder } from "./naturalOrder";
import { CoordinateCell, ObjectRow } from "./ObjectRow";
import { SkipTable } from "./SkipTable";
import { useLiveFrame } from "./useLiveFrame";

/** No rows (one array, so its natural order is computed once). */
const NONE: readonly never[] = [];

const KINDS: LineKind[] = ["line", "ray", "segment"];
const ENDS = [
  { name: "x1", end: "p1", axis: 0 },
  { name: "y1", end: "p1", axis: 1 },
  { name: "x2", end: "p2", axis: 0 },
  { name: "y2", end: "p2", axis: 1 },
] as const;

export function LinesTable() {
  const editor = useEditor();
  const frame = useLiveFrame();
  const lines = inNaturalOrder(frame?.lines ?? NONE);
  const scrollRef = useRef<HTMLDivElement>(null);
  // rows keyed by the scene too: a load that replaces it drops every draft (EditorSession.sceneSerial)
  const scene = useSceneSerial();

  return (
    <section className="panel" aria-labelledby="lines-title">
      <div className="panel-head">
        <h2 id="lines-title">
          Lines <small>({lines.length})</small>
        </h2>
        <button type="button" onClick={() => void addLineNearCentre(editor)}>
          Add line
        </button>
      </div>
      {lines.length > 0 && <SkipTable name="Lines" region={scrollRef} />}
      <div className="table-scroll" ref={scrollRef}>
        <table aria-label="Lines">
          <thead>
            <tr>
              <th>id</th>
              <th>kind</th>
              {ENDS.map((e) => (
                <th key={e.name}>{e.name}</th>
              ))}
              <th />
            </tr>
          </thead>
          <tbody>
            {lines.map((l) => (
              <ObjectRow key={`${scene}:${l.id}`} kind="line" id={l.id}>
                <td>
                  <select
                    aria-label={`${l.id} kind`}
                    value={l.kind}
                    onChange={(e) => void editor.updateLine(l.id, { kind: e.target.value as LineKind })}
                  >
                    {KINDS.map((k) => (
                      <option key={k}>{k}</option>
                    ))}
                  </select>
                </td>
                {ENDS.map((e) => (
                  <CoordinateCell
                    key={e.name}
                    kind="line"
                    id={l.id}
                    name={e.name}
                    point={l[e.end]}
                    axis={e.axis}
                    onCommit={(p) => editor.updateLine(l.id, { [e.end]: p })}
                  />
                ))}
              </ObjectRow>
            ))}
          </tbody>
        </table>
      </div>
    </section>
  );
}
