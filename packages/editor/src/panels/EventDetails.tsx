/**
 * Event details: the entry of the Event log last clicked or entered (uiStore `selectedEvent`), read
 * from the worker (protocol op `eventDetail`, the engine's Timeline.eventDetail): its time, kind,
 * participants (each a button selecting that object), contact point, normal, impulse, and each
 * body's velocity just before and just after it as the engine computed them (not sampled at t ± ε).
 * Numbers are shown like the other panels' (formatNumber); a cell's title holds the full value.
 * Without a selected entry it says how to get one. The detail is read again whenever the timeline
 * changes (an edit recomputes the history): an entry the new history does not hold (or not yet, while
 * it is being recomputed) is said to be gone. Previous entry / Next entry select the entry logged just
 * before or after it (entryStep.ts), one by one also among entries of one instant.
 */
import type { ReactNode } from "react";
import { useEditor, useInfoValue, useUi } from "../EditorContext";
import type { BodyState, EventDetail, Vec2 } from "../engineTypes";
import { refKey } from "../remote/eventDetail";
import type { EntryDetail } from "../remote/protocol";
import type { Selection } from "../store/uiStore";
import { formatNumber } from "./EditableCell";
import { kindLabel, selectionOf } from "./EventLog";
import { NO_EARLIER, NO_LATER, stepEntry } from "./entryStep";
import { FocusKeptButton } from "./FocusKeptButton";
import { useRefreshed } from "./useRefreshed";

/** Shortest interval between two reads while the timeline keeps changing (a computation). */
const REFRESH_MS = 250;

/** What clicking participant k of an entry selects: a collision's body or bodies, its line or
 *  point; an action's object (EventLog's selectionOf). */
export function participantSelection(e: EventDetail, k: number): Selection {
  const id = e.ids[k];
  if (id === undefined) return null;
  if (e.type === "action") return selectionOf(e);
  if (k === 0 || e.type === "bodyBody") return { kind: "body", id };
  return { kind: e.type === "bodyLine" ? "line" : "point", id };
}

const vec = (v: Vec2 | null): string => (v === null ? "—" : `(${formatNumber(v[0])}, ${formatNumber(v[1])})`);
const full = (v: Vec2 | null): string | undefined => (v === null ? undefined : `(${v[0]}, ${v[1]})`);
const velocity = (s: BodyState | null): Vec2 | null => (s === null ? null : [s.vx, s.vy]);
const speed = (s: BodyState | null): number | null => (s === null ? null : Math.hypot(s.vx, s.vy));

function VecCell({ v }: { v: Vec2 | null }) {
  return <td title={full(v)}>{vec(v)}</td>;
}

function SpeedCell({ s }: { s: number | null }) {
  return <td title={s === null ? undefined : String(s)}>{s === null ? "—" : formatNumber(s)}</td>;
}

function Details({ d }: { d: EventDetail }) {
  const editor = useEditor();
  return (
    <>
      <dl className="event-details">
        <dt>time</dt>
        <dd title={String(d.time)}>{formatNumber(d.time)}</dd>
        <dt>kind</dt>
        <dd>{kindLabel(d)}</dd>
        <dt>participants</dt>
        <dd>
          {d.ids.length === 0
            ? "—"
            : d.ids.map((id, k) => {
                const sel = participantSelection(d, k);
                return (
                  // a body and a line may share an id: the kind tells them apart
                  <span key={`${sel?.kind ?? ""}:${id}`}>
                    {k > 0 && ", "}
                    {sel === null ? (
                      id
                    ) : (
                      <button
                        type="button"
                        className="link"
                        title={`Select ${sel.kind} ${id}`}
                        onClick={() => editor.ui.setState({ selection: sel })}
                      >
                        {id}
                      </button>
                    )}
                  </span>
                );
              })}
        </dd>
        <dt>contact point</dt>
        <dd title={full(d.point)}>{vec(d.point)}</dd>
        <dt>normal</dt>
        <dd title={full(d.normal)}>{vec(d.normal)}</dd>
        <dt>impulse</dt>
        <dd title={d.impulse === null ? undefined : String(d.impulse)}>
          {d.impulse === null ? "—" : formatNumber(d.impulse)}
        </dd>
      </dl>
      {d.bodies.length > 0 && (
        <table aria-label="Velocities before and after">
          <thead>
            <tr>
              <th>body</th>
              <th>v before</th>
              <th>v after</th>
              <th>|v| before</th>
              <th>|v| after</th>
            </tr>
          </thead>
          <tbody>
            {d.bodies.map((b) => (
              <tr key={b.id}>
                <td>{b.id}</td>
                <VecCell v={velocity(b.before)} />
                <VecCell v={velocity(b.after)} />
                <SpeedCell s={speed(b.before)} />
                <SpeedCell s={speed(b.after)} />
              </tr>
            ))}
          </tbody>
        </table>
      )}
    </>
  );
}

export function EventDetails() {
  const editor = useEditor();
  const ref = useUi((s) => s.selectedEvent);
  const revision = useInfoValue((i) => i.revision);
  const key = refKey(ref);
  // Each reply keeps the key it was asked for: one for an entry selected before is not shown.
  const read = useRefreshed<{ key: string; detail: EntryDetail | null } | null>(
    () =>
      ref === null || revision < 0
        ? Promise.resolve(null)
        : editor.client.eventDetail(ref).then((detail) => ({ key, detail })),
    `${revision} ${key}`,
    null,
    REFRESH_MS,
    key,
  );
  let body: ReactNode;
  if (ref === null) body = <p className="hint">Select an entry of the Event log to see its details.</p>;
  else if (read === null || read.key !== key) body = <p className="hint">Reading…</p>;
  else if (read.detail === null)
    body = (
      <p className="hint" role="status">
        The entry at t = {formatNumber(ref.time)} ({ref.ids.join(", ")}) is no longer in the history: an edit
        changed it, or it is not computed again yet.
      </p>
    );
  else body = <Details d={read.detail} />;
  const shown = read !== null && read.key === key && read.detail !== null;
  // greyed out at the ends of the log (the last one computed so far), saying why
  const first = shown && read.detail?.first === true;
  const last = shown && read.detail?.last === true;
  return (
    <section className="panel" aria-labelledby="event-details-title">
      <div className="panel-head">
        <h2 id="event-details-title">Event details</h2>
        <span className="head-buttons">
          <FocusKeptButton
            enabled={shown && !first}
            title={first ? NO_EARLIER : "Select the entry logged just before this one (at the same time too)"}
            onPress={() => void stepEntry(editor, -1)}
          >
            ◀ Previous entry
          </FocusKeptButton>
          <FocusKeptButton
            enabled={shown && !last}
            title={last ? NO_LATER : "Select the entry logged just after this one (at the same time too)"}
            onPress={() => void stepEntry(editor, 1)}
          >
            Next entry ▶
          </FocusKeptButton>
        </span>
      </div>
      {body}
    </section>
  );
}
