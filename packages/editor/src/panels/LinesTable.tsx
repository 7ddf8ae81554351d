/** The Lines table: id, kind, both points of every line, ray and segment; editable; Add and Delete. */

import { useEditor, useUi } from "../EditorContext";
import type { LineKind, Vec2 } from "../engineTypes";
import { DeleteRowButton } from "./DeleteRowButton";
import { EditableCell, formatNumber, parseNumber } from "./EditableCell";
import { useLiveFrame } from "./useLiveFrame";

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
  const selection = useUi((s) => s.selection);
  const lines = frame?.lines ?? [];

  const add = () => {
    const v = editor.ui.getState().view;
    const half = 100 / v.scale;
    void editor.addLine([v.cx - half, v.cy], [v.cx + half, v.cy], "segment");
  };

  return (
    <section className="panel" aria-labelledby="lines-title">
      <h2 id="lines-title">
        Lines <small>({lines.length})</small>
        <button type="button" onClick={add}>
          Add line
        </button>
      </h2>
      <div className="table-scroll">
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
            {lines.map((l) => {
              const hot = selection?.kind === "line" && selection.id === l.id;
              return (
                <tr
                  key={l.id}
                  aria-selected={hot}
                  className={hot ? "selected" : undefined}
                  onClick={() => editor.ui.setState({ selection: { kind: "line", id: l.id } })}
                >
                  <td>
                    <EditableCell
                      label={`${l.id} id`}
                      value={l.id}
                      size={5}
                      onCommit={(t) => editor.rename("line", l.id, t)}
                    />
                  </td>
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
                    <td key={e.name}>
                      <EditableCell
                        label={`${l.id} ${e.name}`}
                        value={formatNumber(l[e.end][e.axis])}
                        size={6}
                        onCommit={async (text) => {
                          const x = parseNumber(text);
                          if (x === null) return `${e.name}: must be a number`;
                          const p: Vec2 = e.axis === 0 ? [x, l[e.end][1]] : [l[e.end][0], x];
                          return editor.updateLine(l.id, { [e.end]: p });
                        }}
                      />
                    </td>
                  ))}
                  <td>
                    <DeleteRowButton kind="line" id={l.id} />
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
