/**
 * The Points table: id and position of every fixed point; editable; Add and Delete. "Skip the Points
 * table" (SkipTable, shown when focused) passes its cells in one Tab press.
 */

import { useRef } from "react";
import { freeSpot } from "../canvas/freeSpot";
import { pointerStep, roundPoint } from "../canvas/pointerGrid";
import { useEditor } from "../EditorContext";
import type { Vec2 } from "../engineTypes";
import { CoordinateCell, ObjectRow } from "./ObjectRow";
import { SkipTable } from "./SkipTable";
import { useLiveFrame } from "./useLiveFrame";

export function PointsTable() {
  const editor = useEditor();
  const frame = useLiveFrame();
  const points = frame?.points ?? [];
  const scrollRef = useRef<HTMLDivElement>(null);

  return (
    <section className="panel" aria-labelledby="points-title">
      <div className="panel-head">
        <h2 id="points-title">
          Points <small>({points.length})</small>
        </h2>
        <button
          type="button"
          onClick={() => {
            // at the free place nearest the centre of the view, at the pointer's precision
            const v = editor.ui.getState().view;
            const grid = pointerStep(v.scale);
            const at: Vec2 = [v.cx, v.cy];
            void editor.addPoint(
              freeSpot(editor.client.latestFrame, { kind: "point" }, at, 20 / v.scale, grid) ??
                roundPoint(at, grid),
            );
          }}
        >
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
              <ObjectRow key={p.id} kind="point" id={p.id}>
                {([0, 1] as const).map((axis) => (
                  <CoordinateCell
                    key={axis}
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
