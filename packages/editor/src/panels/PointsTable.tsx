/**
 * The Points table: id and position of every fixed point; editable; Add and Delete. "Skip the Points
 * table" (SkipTable, shown when focused) passes its cells in one Tab press.
 */

import { useRef } from "react";
import { useEditor, useSceneSerial } from "../EditorContext";
import { addPointNearCentre } from "./addNear";
import { inNaturalOrder } from "./naturalOrder";
import { CoordinateCell, ObjectRow } from "./ObjectRow";
import { SkipTable } from "./SkipTable";
import { useLiveFrame } from "./useLiveFrame";

/** No rows (one array, so its natural order is computed once). */
const NONE: readonly never[] = [];

export function PointsTable() {
  const editor = useEditor();
  const frame = useLiveFrame();
  const points = inNaturalOrder(frame?.points ?? NONE);
  const scrollRef = useRef<HTMLDivElement>(null);
  // rows keyed by the scene too: a load that replaces it drops every draft (EditorSession.sceneSerial)
  const scene = useSceneSerial();

  return (
    <section className="panel" aria-labelledby="points-title">
      <div className="panel-head">
        <h2 id="points-title">
          Points <small>({points.length})</small>
        </h2>
        <button type="button" onClick={() => void addPointNearCentre(editor)}>
          Add point
        </button>
      </div>
      {points.length > 0 && <SkipTable name="Points" region={scrollRef} />}
      <div className="table-scroll" ref={scrollRef}>
        <table aria-label="Points">
          <thead>
            <tr>
              <th>id</th>
              <th>x</th>
              <th>y</th>
              <th />
            </tr>
          </thead>
          <tbody>
            {points.map((p) => (
              <ObjectRow key={`${scene}:${p.id}`} kind="point" id={p.id}>
                {([0, 1] as const).map((axis) => (
                  <CoordinateCell
                    key={axis}
                    kind="point"
                    id={p.id}
                    name={axis === 0 ? "x" : "y"}
                    point={p.p}
                    axis={axis}
                    onCommit={(q) => editor.updatePoint(p.id, q)}
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
