/**
 * The Bodies table: id, x, y, vx, vy, |v|, r, m, μ of every body at the current time (live while
 * playing, refreshed a few times a second). Every cell is editable; an edit is an action at the
 * current time; refused values show the engine's message in place. Rows select bodies (clicked, or a
 * cell of theirs focused or opened), listed in natural id order (ball2 before ball10), at most
 * MAX_ROWS of them: the filter field (a part of the id) reaches any other body (bodyList.ts). Only the
 * rows in view are rendered (useRowWindow), and the rows holding an open cell wherever they are, so a
 * draft survives any scroll (useHeldRows); rows are keyed by the scene too, so a load that replaces
 * it drops every draft (EditorSession.sceneSerial). The selected body's row is scrolled into view when the
 * selection changes (useRevealRow). A "Skip the Bodies table" button (shown when focused)
 * passes its cells in one Tab press.
 */
import { type ReactNode, useRef, useState } from "react";
import { useEditor, useSceneSerial, useUi } from "../EditorContext";
import { F_M, F_MU, F_R, F_VX, F_VY, F_X, F_Y, FRAME_STRIDE } from "../remote/protocol";
import { addBodyNearCentre } from "./addNear";
import { listBodies, listNote } from "./bodyList";
import { DeleteRowButton } from "./DeleteRowButton";
import { EditableCell, formatNumber, isInfinityWord, parseNumber } from "./EditableCell";
import { SkipTable } from "./SkipTable";
import { notANumber, refusedTyped } from "./typedRefusal";
import { useHeldRows } from "./useHeldRows";
import { useLiveFrame } from "./useLiveFrame";
import { useRevealRow } from "./useRevealRow";
import { rowRuns, spacerRow, useRowWindow } from "./useRowWindow";

/** Rows shown at most (the selected body is always shown); the canvas shows them all. */
export const MAX_ROWS = 60;

type Field = "x" | "y" | "vx" | "vy" | "speed" | "r" | "m" | "mu";
const COLUMNS: { field: Field; title: string; offset: number | null }[] = [
  { field: "x", title: "x", offset: F_X },
  { field: "y", title: "y", offset: F_Y },
  { field: "vx", title: "vx", offset: F_VX },
  { field: "vy", title: "vy", offset: F_VY },
  { field: "speed", title: "|v|", offset: null },
  { field: "r", title: "r", offset: F_R },
  { field: "m", title: "m", offset: F_M },
  { field: "mu", title: "μ", offset: F_MU },
];

export function BodiesTable() {
  const editor = useEditor();
  const frame = useLiveFrame(250);
  const scrollRef = useRef<HTMLDivElement>(null);
  const selection = useUi((s) => s.selection);
  const selectedId = selection?.kind === "body" ? selection.id : null;
  const [filter, setFilter] = useState("");
  const { held, holder } = useHeldRows();
  const scene = useSceneSerial();

  // The velocity at the time the edit is stamped with: the row's values may be a refresh old (up to
  // PLAYING_INTERVAL_MS after a pause), and a vx edit built from them committed an old vy.
  const velocityNow = async (id: string, shown: [number, number]): Promise<[number, number]> => {
    const f = await editor.client.frame(editor.ui.getState().t);
    const i = f.ids.indexOf(id);
    return i < 0 ? shown : [f.data[i * FRAME_STRIDE + F_VX]!, f.data[i * FRAME_STRIDE + F_VY]!];
  };

  const commit = (id: string, field: Field, shownVx: number, shownVy: number) => async (text: string) => {
    const x = parseNumber(text);
    // Named as the engine's refusals are (doc/refusalTerms.ts): the body, then the column.
    const cell = `${id} ${COLUMNS.find((c) => c.field === field)?.title ?? field}`;
    if (x === null) return notANumber(cell, text);
    if (field === "speed" && x < 0) return refusedTyped(cell, "must be zero or positive", text);
    // (scaling the velocity by an infinite speed gave NaN components: "v: must be an array of two
    // finite numbers", a field the table does not have: audit of session 20)
    if (field === "speed" && !Number.isFinite(x)) return refusedTyped(cell, "must be a finite number", text);
    // 1e999 overflows to Infinity: an immovable body only when asked for by name (audit)
    if (field === "m" && !Number.isFinite(x) && !isInfinityWord(text))
      return refusedTyped(
        cell,
        "is too large for a number",
        text,
        "type ∞ or Infinity for an immovable body",
      );
    const [vx, vy] =
      field === "vx" || field === "vy" || field === "speed"
        ? await velocityNow(id, [shownVx, shownVy])
        : [shownVx, shownVy];
    switch (field) {
      case "vx":
        return editor.updateBody(id, { v: [x, vy] });
      case "vy":
        return editor.updateBody(id, { v: [vx, x] });
      case "speed": {
        const s = Math.hypot(vx, vy);
        return editor.updateBody(id, { v: s > 0 ? [(vx * x) / s, (vy * x) / s] : [x, 0] });
      }
      default:
        return editor.updateBody(id, { [field]: x });
    }
  };

  // The bodies listed (the first MAX_ROWS matching the filter, the selected one and those holding an
  // open cell), then the window of them rendered, with the rows holding an open cell wherever they are.
  const n = frame?.ids.length ?? 0;
  const list = listBodies(frame?.ids ?? [], filter, selectedId, MAX_ROWS, held);
  const { listed } = list;
  const note = listNote(list, n, filter);
  const win = useRowWindow(scrollRef, listed.length);
  // a body selected elsewhere (the canvas, the Event log) is scrolled into view
  useRevealRow(
    scrollRef,
    selectedId,
    selectedId === null || !frame ? -1 : listed.findIndex((i) => frame.ids[i] === selectedId),
    win.geometry,
  );
  const heldAt = frame ? listed.flatMap((i, k) => (held.has(frame.ids[i]!) ? [k] : [])) : [];
  const rows: ReactNode[] = [];
  for (const run of frame ? rowRuns(win, heldAt, listed.length, win.geometry.row) : []) {
    if ("gap" in run) {
      rows.push(spacerRow(`gap${run.from}`, run.gap, COLUMNS.length + 2));
      continue;
    }
    const i = listed[run.row]!;
    const id = frame!.ids[i]!;
    const hold = holder(id);
    const o = i * FRAME_STRIDE;
    const vx = frame!.data[o + F_VX]!;
    const vy = frame!.data[o + F_VY]!;
    rows.push(
      <tr
        key={`${scene}:${id}`}
        aria-selected={id === selectedId}
        className={id === selectedId ? "selected" : undefined}
        // Focusing a cell selects the body too: a cell opens on focus (its input replaces the button
        // under the pointer), so the row's click was lost and the disc being edited was not lit.
        onClick={() => editor.ui.setState({ selection: { kind: "body", id } })}
        onFocus={() => editor.ui.setState({ selection: { kind: "body", id } })}
      >
        <td>
          <EditableCell
            label={`${id} id`}
            value={id}
            size={6}
            onCommit={(text) => editor.rename("body", id, text)}
            onOpenChange={hold}
            owner={{ kind: "body", id, field: "id" }}
          />
        </td>
        {COLUMNS.map((c) => (
          <td key={c.field}>
            <EditableCell
              label={`${id} ${c.field}`}
              value={formatNumber(c.offset === null ? Math.hypot(vx, vy) : frame!.data[o + c.offset]!)}
              onCommit={commit(id, c.field, vx, vy)}
              onOpenChange={hold}
              owner={{ kind: "body", id, field: c.field }}
            />
          </td>
        ))}
        <td className="row-end">
          <DeleteRowButton kind="body" id={id} />
        </td>
      </tr>,
    );
  }

  return (
    <section className="panel" aria-labelledby="bodies-title">
      <div className="panel-head">
        <h2 id="bodies-title">
          Bodies <small>({n})</small>
        </h2>
        <button type="button" onClick={() => void addBodyNearCentre(editor)}>
          Add body
        </button>
      </div>
      {n > MAX_ROWS || filter !== "" ? (
        <div className="row">
          <input
            type="search"
            aria-label="Filter bodies by id"
            placeholder="filter by id"
            size={12}
            value={filter}
            onChange={(e) => {
              setFilter(e.target.value);
              // the matches start at the top: a scroll kept from the whole list hid the first ones
              if (scrollRef.current) scrollRef.current.scrollTop = 0;
            }}
          />
        </div>
      ) : null}
      {listed.length > 0 && <SkipTable name="Bodies" region={scrollRef} />}
      <div className="table-scroll" ref={scrollRef}>
        <table aria-label="Bodies">
          <thead>
            <tr>
              <th>id</th>
              {COLUMNS.map((c) => (
                <th key={c.field}>{c.title}</th>
              ))}
              <th />
            </tr>
          </thead>
          <tbody>{rows}</tbody>
        </table>
      </div>
      {note !== null && <p className="note">{note}</p>}
    </section>
  );
}
