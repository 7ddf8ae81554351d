/**
 * The Event log: the events around the current time (time, kind, participants; an action entry says
 * what the action did). Clicking an entry
 * jumps there, highlights its participants, selects one (selectionOf) and makes it the selected event
 * (shown by EventDetails, and marked in the log: aria-selected, class "chosen"); the filter keeps only
 * one id's entries, or with ids separated by commas the entries they all take part in (a pair's
 * collisions; remote/eventFilter.ts). An action entry's ✕ removes that action from the scene once confirmed by a
 * second press (RemoveActionButton); when the ✕ had the keyboard focus, the focus then goes to the
 * ✕ of the next action entry shown, else the previous one, else the log's table (removeFocus.ts),
 * once the log shows the scene without the action. An armed ✕ says "Press again to remove …" in the
 * log's one visually hidden polite live region (useArmedNotice), which is empty otherwise.
 * Each entry is described to assistive technology by what activating it does (ROW_HINT); ↑ and ↓ move
 * the focus between entries.
 * Only the rows in view are rendered (useRowWindow); the view follows the current time (useFollowTime).
 * "Skip the Event log table" (SkipTable, shown when focused) passes its entries in one Tab press.
 * A filter that keeps no entry says why (LogFilter: no such id, or no entry in the computed
 * history); the scene's refused action, if any, is listed over the entries (RefusedActionRow).
 */
import { useEffect, useId, useRef, useState } from "react";
import { actionWords } from "../doc/actionRefs";
import { kindOfType } from "../doc/rename";
import { useEditor, useInfoValue, useUi } from "../EditorContext";
import type { LogEvent } from "../engineTypes";
import { refKey, refOf } from "../remote/eventDetail";
import type { EventPage, PageEvent } from "../remote/protocol";
import type { Selection } from "../store/uiStore";
import { formatNumber } from "./EditableCell";
import { LogFilter } from "./LogFilter";
import { RefusedActionRow } from "./RefusedActionRow";
import { RemoveActionButton } from "./RemoveActionButton";
import { focusAfterRemoval } from "./removeFocus";
import { SkipTable } from "./SkipTable";
import { type ArmedNotice, useArmedNotice } from "./useArmedNotice";
import { useFollowTime } from "./useFollowTime";
import { useRefreshed } from "./useRefreshed";
import { spacerRow, useRowWindow } from "./useRowWindow";
import { useSlowTime } from "./useThrottledTime";

const BEFORE = 30;
const AFTER = 30;
/**
 * Shortest interval between two page requests (ms): the log follows playback and a computation at
 * 4 Hz (each refresh re-renders and re-scrolls the log; at 10 Hz this cost about a millisecond of
 * the main thread per frame while playing 2,000 discs that the worker computes ahead).
 */
const REFRESH_MS = 250;
/** Every entry's accessible description: what activating it does. */
export const ROW_HINT = "Press Enter to go to this event's time and select what it involves.";
const KIND_NAMES: Record<string, string> = {
  bodyBody: "body–body",
  bodyLine: "body–line",
  bodyPoint: "body–point",
  stop: "stop",
  action: "action",
};

/** The entry row after (or before) `row` in the log's table, skipping the spacer rows; null at an end. */
export function siblingRow(row: HTMLTableRowElement, down: boolean): HTMLTableRowElement | null {
  let r = down ? row.nextElementSibling : row.previousElementSibling;
  while (r !== null && !(r instanceof HTMLTableRowElement && r.tabIndex === 0))
    r = down ? r.nextElementSibling : r.previousElementSibling;
  return r;
}

/** The kind column: the event's kind, and for an action entry what it did ("action: give velocity"). */
export function kindLabel(e: LogEvent): string {
  const kind = KIND_NAMES[e.type] ?? e.type;
  if (e.action === undefined) return kind;
  return `${kind}: ${actionWords(e.action)}`;
}

/**
 * What clicking an entry selects: an action's object (a body, line or point, by the action's type;
 * nothing for setGlobal); for a collision or a stop, its body (the first participant: ids are
 * [body, body], [body, line], [body, point] or [body]), never the obstacle, which would be taken
 * for a body of the same id.
 */
export function selectionOf(e: LogEvent): Selection {
  const id = e.ids[0];
  if (id === undefined) return null;
  if (e.type !== "action") return { kind: "body", id };
  const kind = e.action === undefined ? null : kindOfType(e.action);
  return kind === null ? null : { kind, id };
}

/**
 * What clicking an entry highlights on the canvas, as `kind:id` keys (uiStore's `highlight`): every
 * participant with its kind, so a body and a line of the same id are not both lit.
 */
export function highlightOf(e: LogEvent): string[] {
  const [a, b] = e.ids;
  if (a === undefined) return [];
  if (e.type === "action") {
    const kind = e.action === undefined ? null : kindOfType(e.action);
    return kind === null ? [] : [`${kind}:${a}`];
  }
  if (b === undefined) return [`body:${a}`];
  const other = e.type === "bodyLine" ? "line" : e.type === "bodyPoint" ? "point" : "body";
  return [`body:${a}`, `${other}:${b}`];
}

/**
 * The header's count: the log's number of events; filtered, how many of the body's events are shown
 * (those around the current time) and the log's number ("3 shown for c3 · 11 in all").
 */
export function logCount(total: number, shown: number, body: string | null): string {
  return body === null ? String(total) : `${shown} shown for ${body} · ${total} in all`;
}

/**
 * An action entry's remove button (null for other entries, and for an action not identified), on a
 * page read at scene revision `revision`; `onRemoved(index)` once it removed its action while focused.
 */
function removable(e: PageEvent, revision: number, onRemoved: (index: number) => void, notice: ArmedNotice) {
  if (e.type !== "action" || e.action === undefined || e.actionIndex === undefined) return null;
  const index = e.actionIndex;
  return (
    <RemoveActionButton
      index={index}
      time={e.time}
      type={e.action}
      id={e.ids[0] ?? null}
      revision={revision}
      notice={notice}
      onRemoved={(focused) => {
        if (focused) onRemoved(index);
      }}
    />
  );
}

export function EventLog() {
  const editor = useEditor();
  const t = useSlowTime();
  const filter = useUi((s) => s.eventFilter);
  const selectedKey = refKey(useUi((s) => s.selectedEvent));
  const revision = useInfoValue((i) => i.revision);
  const body = filter.trim() === "" ? null : filter.trim();
  // Each page keeps the time it was read around: the view follows that time, so a page that
  // arrives after the time moved on is not scrolled to rows it does not hold yet.
  // ... and the scene revision it was asked at: the remove buttons' state belongs to one revision.
  const read = useRefreshed<{ at: number; page: EventPage; doc: number } | null>(
    () => {
      if (revision < 0) return Promise.resolve(null);
      const doc = editor.client.getSnapshot().docRevision;
      return editor.client.events(t, BEFORE, AFTER, body).then((page) => ({ at: t, page, doc }));
    },
    `${revision} ${t} ${body}`,
    null,
    REFRESH_MS,
  );
  const page = read?.page ?? null;
  const scrollRef = useRef<HTMLDivElement>(null);
  const events = page?.events ?? [];
  const win = useRowWindow(scrollRef, events.length);
  useFollowTime(
    scrollRef,
    events.map((e) => e.time),
    read?.at ?? t,
    read,
    win.geometry,
  );

  // A removal made from the keyboard: the action's index and the revision of the page that showed it.
  const tableRef = useRef<HTMLTableElement>(null);
  const [refocus, setRefocus] = useState<{ index: number; from: number } | null>(null);
  const doc = read?.doc ?? -1;
  useEffect(() => {
    if (refocus === null || doc === refocus.from) return;
    setRefocus(null);
    const box = scrollRef.current;
    const active = document.activeElement;
    // the focus was lost with the button, or is still in the log; elsewhere, the user moved it on
    if (box === null || (active !== null && active !== document.body && !box.contains(active))) return;
    const buttons = [...box.querySelectorAll<HTMLButtonElement>("button[data-action-index]")];
    const at = focusAfterRemoval(
      refocus.index,
      buttons.map((b) => Number(b.dataset.actionIndex)),
    );
    const target = buttons.find((b) => Number(b.dataset.actionIndex) === at) ?? tableRef.current;
    target?.focus();
  }, [refocus, doc]);
  const onRemoved = (index: number) => setRefocus({ index, from: doc });

  // The entry the focused row shows. Rows are kept by position, so when the page is read again
  // around another time (Enter on a row goes to its time) the focused row shows another entry: the
  // focus follows its entry to the row that shows it now (audit of session 20: Enter on one entry
  // left the focus, and a screen reader, on an entry four rows up).
  const focusedEntry = useRef<string | null>(null);
  useEffect(() => {
    const box = scrollRef.current;
    const want = focusedEntry.current;
    const active = document.activeElement;
    if (box === null || want === null || !(active instanceof HTMLTableRowElement) || !box.contains(active))
      return;
    if (active.dataset.entry === want) return;
    const row = [...box.querySelectorAll<HTMLTableRowElement>("tr[data-entry]")].find(
      (r) => r.dataset.entry === want,
    );
    row?.focus({ preventScroll: true });
  });
  const armed = useArmedNotice();
  const hintId = useId();

  return (
    <section className="panel" aria-labelledby="log-title">
      <h2 id="log-title">
        Event log <small>({logCount(page?.total ?? 0, events.length, body)})</small>
      </h2>
      <LogFilter filter={filter} shown={events.length} total={page?.total ?? null} />
      <RefusedActionRow notice={armed.notice} />
      <div className="visually-hidden" role="status" aria-live="polite">
        {armed.text}
      </div>
      <p id={hintId} hidden>
        {ROW_HINT}
      </p>
      {events.length > 0 && <SkipTable name="Event log" region={scrollRef} />}
      <div className="table-scroll log" ref={scrollRef}>
        <table aria-label="Event log" ref={tableRef} tabIndex={-1}>
          <thead>
            <tr>
              <th>time</th>
              <th>kind</th>
              <th>participants</th>
              <th />
            </tr>
          </thead>
          <tbody>
            {spacerRow("before", win.before, 4)}
            {events.slice(win.start, win.end).map((e, j) => {
              const k = win.start + j;
              const chosen = selectedKey !== "" && refKey(refOf(e)) === selectedKey;
              const cls = [e.time === t ? "current" : e.time < t ? "past" : "", chosen ? "chosen" : ""]
                .filter(Boolean)
                .join(" ");
              return (
                <tr
                  // Rows are kept by position: while playing the page slides by dozens of events per
                  // refresh, and updating the text of existing rows costs far less layout and paint
                  // than replacing them (rows hold no state).
                  key={k}
                  data-entry={refKey(refOf(e))}
                  onFocus={(ev) => {
                    if (ev.target === ev.currentTarget)
                      focusedEntry.current = ev.currentTarget.dataset.entry ?? null;
                  }}
                  className={cls || undefined}
                  aria-selected={chosen}
                  tabIndex={0}
                  aria-describedby={hintId}
                  onClick={() =>
                    editor.ui.setState({
                      t: e.time,
                      playing: false,
                      highlight: highlightOf(e),
                      selection: selectionOf(e),
                      selectedEvent: refOf(e),
                    })
                  }
                  onKeyDown={(ev) => {
                    if (ev.target !== ev.currentTarget) return; // keys on the row's ✕ are the button's
                    // Enter on the row itself; Enter on its button presses only the button.
                    if (ev.key === "Enter") ev.currentTarget.click();
                    // ↑ and ↓ move between entries (Tab passes every row and its ✕)
                    if (ev.key === "ArrowDown" || ev.key === "ArrowUp") {
                      const to = siblingRow(ev.currentTarget, ev.key === "ArrowDown");
                      if (to) {
                        ev.preventDefault();
                        to.focus();
                      }
                    }
                  }}
                >
                  <td>{formatNumber(e.time)}</td>
                  {/* cut to the column's width in a narrow box (tables.css): whole in the title */}
                  <td title={kindLabel(e)}>{kindLabel(e)}</td>
                  <td title={e.ids.join(", ")}>{e.ids.join(", ")}</td>
                  <td className="row-end">{removable(e, doc, onRemoved, armed.notice)}</td>
                </tr>
              );
            })}
            {spacerRow("after", win.after, 4)}
          </tbody>
        </table>
      </div>
    </section>
  );
}
