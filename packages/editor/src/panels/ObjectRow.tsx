/**
 * Shared pieces of the Lines and Points tables.
 * - ObjectRow: a row that selects its object when clicked or when one of its cells is focused (a
 *   cell opening to be edited), and is marked while selected. It starts with the editable id cell
 *   (a rename is one undo step) and ends with the ✕ button.
 * - CoordinateCell: one coordinate of a point, editable. Text that is not a number is refused in
 *   place and names the field. A number commits the point with that one coordinate replaced.
 */
import type { ReactNode } from "react";
import { useEditor, useUi } from "../EditorContext";
import type { Vec2 } from "../engineTypes";
import { DeleteRowButton } from "./DeleteRowButton";
import { EditableCell, formatNumber, parseNumber } from "./EditableCell";
import { notANumber } from "./typedRefusal";

export function ObjectRow({
  kind,
  id,
  children,
}: {
  kind: "line" | "point";
  id: string;
  children: ReactNode;
}) {
  const editor = useEditor();
  const hot = useUi((s) => s.selection?.kind === kind && s.selection.id === id);
  return (
    <tr
      aria-selected={hot}
      className={hot ? "selected" : undefined}
      onClick={() => editor.ui.setState({ selection: { kind, id } })}
      // A cell opens on focus (its input replaces the button under the pointer), losing the click.
      onFocus={() => editor.ui.setState({ selection: { kind, id } })}
    >
      <td>
        <EditableCell
          label={`${id} id`}
          value={id}
          size={5}
          onCommit={(t) => editor.rename(kind, id, t)}
          owner={{ kind, id, field: "id" }}
        />
      </td>
      {children}
      <td className="row-end">
        <DeleteRowButton kind={kind} id={id} />
      </td>
    </tr>
  );
}

export function CoordinateCell(props: {
  /** The object's kind and id; the cell's accessible name is "<id> <name>". */
  kind: "line" | "point";
  id: string;
  /** The field's name, e.g. "x" or "y2". */
  name: string;
  point: Vec2;
  axis: 0 | 1;
  onCommit: (p: Vec2) => Promise<string | null>;
}) {
  const { kind, id, name, point, axis, onCommit } = props;
  return (
    <td>
      <EditableCell
        label={`${id} ${name}`}
        value={formatNumber(point[axis])}
        size={6}
        owner={{ kind, id, field: name }}
        onCommit={async (text) => {
          const x = parseNumber(text);
          if (x === null) return notANumber(`${id} ${name}`, text);
          return onCommit(axis === 0 ? [x, point[1]] : [point[0], x]);
        }}
      />
    </td>
  );
}
