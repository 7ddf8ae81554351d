/** The Points table: id and position of every fixed point; editable; Add and Delete. */

import { useEditor, useUi } from "../EditorContext";
import type { Vec2 } from "../engineTypes";
import { DeleteRowButton } from "./DeleteRowButton";
import { EditableCell, formatNumber, parseNumber } from "./EditableCell";
import { useLiveFrame } from "./useLiveFrame";

export function PointsTable() {
  const editor = useEditor();
  const frame = useLiveFrame();
  const selection = useUi((s) => s.selection);
  const points = frame?.points ?? [];

  return (
    <section className="panel" aria-labelledby="points-title">
      <h2 id="points-title">
        Points <small>({points.length})</small>
        <button
          type="button"
          onClick={() => {
            const v = editor.ui.getState().view;
            void editor.addPoint([v.cx, v.cy]);
          }}
        >
          Add point
        </button>
      </h2>
      <div className="table-scroll">
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
            {points.map((p) => {
              const hot = selection?.kind === "point" && selection.id === p.id;
              const cell = (axis: 0 | 1) => (
                <EditableCell
                  label={`${p.id} ${axis === 0 ? "x" : "y"}`}
                  value={formatNumber(p.p[axis])}
                  size={6}
                  onCommit={async (text) => {
                    const x = parseNumber(text);
                    if (x === null) return `${axis === 0 ? "x" : "y"}: must be a number`;
                    const q: Vec2 = axis === 0 ? [x, p.p[1]] : [p.p[0], x];
                    return editor.updatePoint(p.id, q);
                  }}
                />
              );
              return (
                <tr
                  key={p.id}
                  aria-selected={hot}
                  className={hot ? "selected" : undefined}
                  onClick={() => editor.ui.setState({ selection: { kind: "point", id: p.id } })}
                >
                  <td>
                    <EditableCell
                      label={`${p.id} id`}
                      value={p.id}
                      size={5}
                      onCommit={(t) => editor.rename("point", p.id, t)}
                    />
                  </td>
                  <td>{cell(0)}</td>
                  <td>{cell(1)}</td>
                  <td>
                    <DeleteRowButton kind="point" id={p.id} />
                  </td>
                </tr>
              );
            })}
          </tbody>
        </table>
      </div>
    </section>
  );
}
