/**
 * The ✕ of an Event-log action entry: removes that one action from the scene (Editor.removeAction,
 * one undo step) in two steps (removeConfirm.ts): the first press (click, Enter or Space) arms it
 * and it reads "Remove?"; a second press removes. Leaving it (pointer or focus), Escape, or a few
 * seconds without a press disarm it; a double-click only arms it, and so do a held key's repeats
 * (they never press it). Armed, the button keeps its size and place: "Remove?" is drawn to its left
 * outside the table's layout, as a part of the button (pointing at it is pointing at the button), so
 * the second click lands on it at any window width. A row that now shows another action (the log
 * moved up after a removal, or the scene changed: the state's key holds the scene's revision and
 * the action's index) shows its button at rest, and a finished removal (done or refused) brings it
 * to rest. Its accessible name says which action, and when armed that the next press removes it:
 * `Remove action update body "b1" at t = 4`,
 * `Confirm: remove action update body "b1" at t = 4 (press again; Escape keeps it)`, then
 * `Removing action update body "b1" at t = 4` until the removal is done. The press does not reach
 * the row (which would jump to the entry's time). `onRemoved(focused)` is called once the action is
 * removed, `focused` when the button had the keyboard focus at the confirming press (the Event log
 * then moves the focus on: the button may be gone). Armed, it tells the log's live region (`notice`,
 * useArmedNotice.ts) "Press again to remove action update body "b1" at t = 4" until it disarms.
 */
import { useEffect, useState } from "react";
import { describeEntry } from "../doc/actionRefs";
import { useEditor } from "../EditorContext";
import { formatNumber } from "./EditableCell";
import { ARMED_MS, current, disarm, finished, idle, press } from "./removeConfirm";
import type { ArmedNotice } from "./useArmedNotice";

export function RemoveActionButton(props: {
  index: number;
  time: number;
  type: string;
  id: string | null;
  /** The scene revision (docRevision) of the log page that shows the entry. */
  revision: number;
  onRemoved?: (focused: boolean) => void;
  /** The log's live region, told the prompt while the button is armed. */
  notice?: ArmedNotice;
}) {
  const editor = useEditor();
  const { index, time, type, id, revision, onRemoved, notice } = props;
  const key = `${revision} ${index} ${time} ${type} ${id}`;
  const [stored, setState] = useState(() => idle(key));
  const state = current(stored, key);
  const armed = state.phase === "armed";
  useEffect(() => {
    if (!armed) return;
    const timer = setTimeout(() => setState((s) => disarm(s)), ARMED_MS);
    return () => clearTimeout(timer);
  }, [armed]);

  const what = `action ${describeEntry(type, id)} at t = ${formatNumber(time)}`;
  const prompt = armed ? `Press again to remove ${what}` : null;
  useEffect(() => {
    if (prompt === null || notice === undefined) return;
    notice.show(prompt);
    return () => notice.hide(prompt);
  }, [prompt, notice]);
  const label = armed
    ? `Confirm: remove ${what} (press again; Escape keeps it)`
    : state.phase === "removing"
      ? `Removing ${what}`
      : `Remove ${what}`;
  return (
    <button
      type="button"
      className={armed ? "log-remove armed" : "log-remove"}
      aria-label={label}
      aria-disabled={state.phase === "removing"}
      data-action-index={index}
      title={
        armed
          ? "Click again to remove this action (Undo brings it back)"
          : "Remove this action from the scene"
      }
      onClick={(ev) => {
        ev.stopPropagation();
        const next = press(state, performance.now());
        setState(next.state);
        if (!next.remove) return;
        const focused = document.activeElement === ev.currentTarget;
        void editor.removeAction(index, { time, type, id }).then((err) => {
          // Done or refused (the message says why): at rest again, whichever action the row shows now.
          setState((s) => finished(s));
          if (err === null) onRemoved?.(focused);
        });
      }}
      onMouseLeave={() => setState((s) => disarm(current(s, key)))}
      onBlur={() => setState((s) => disarm(current(s, key)))}
      onKeyDown={(ev) => {
        // A held key's repeats would press it again and again (Enter presses on keydown): only the
        // first keydown counts.
        if (ev.repeat && (ev.key === "Enter" || ev.key === " ")) {
          ev.preventDefault();
          return;
        }
        if (ev.key !== "Escape" || !armed) return;
        ev.stopPropagation();
        setState((s) => disarm(current(s, key)));
      }}
    >
      {armed && (
        <span className="log-remove-prompt" aria-hidden="true">
          Remove?
        </span>
      )}
      {state.phase === "removing" ? "…" : "✕"}
    </button>
  );
}
