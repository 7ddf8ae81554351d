/**
 * The ✕ of an Event-log action entry: removes that one action from the scene (Editor.removeAction,
 * one undo step) in two steps (removeConfirm.ts): the first press (click, Enter or Space) arms it
 * and it reads "Remove?"; a second press removes. Leaving it (pointer or focus), Escape, or a few
 * seconds without a press disarm it; a double-click only arms it; and a row that now shows another
 * action (the log moved up after a removal) shows its button at rest. Its accessible name says which
 * action, and when armed that the next press removes it: `Remove action updateBody of b1 at t = 4`,
 * `Confirm: remove action updateBody of b1 at t = 4 (press again; Escape keeps it)`, then
 * `Removing action updateBody of b1 at t = 4` until the log shows the scene without it. The press does
 * not reach the row (which would jump to the entry's time).
 */
import { useEffect, useState } from "react";
import { useEditor } from "../EditorContext";
import { formatNumber } from "./EditableCell";
import { ARMED_MS, current, disarm, idle, press } from "./removeConfirm";

export function RemoveActionButton(props: { index: number; time: number; type: string; id: string | null }) {
  const editor = useEditor();
  const { index, time, type, id } = props;
  const key = `${index} ${time} ${type} ${id}`;
  const [stored, setState] = useState(() => idle(key));
  const state = current(stored, key);
  const armed = state.phase === "armed";
  useEffect(() => {
    if (!armed) return;
    const timer = setTimeout(() => setState((s) => disarm(s)), ARMED_MS);
    return () => clearTimeout(timer);
  }, [armed]);

  const what = `action ${id === null ? type : `${type} of ${id}`} at t = ${formatNumber(time)}`;
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
        void editor.removeAction(index, { time, type, id }).then((err) => {
          // Refused: the message says why; the button is at rest again.
          if (err !== null) setState((s) => (s.key === key ? idle(key) : s));
        });
      }}
      onMouseLeave={() => setState((s) => disarm(current(s, key)))}
      onBlur={() => setState((s) => disarm(current(s, key)))}
      onKeyDown={(ev) => {
        if (ev.key !== "Escape" || !armed) return;
        ev.stopPropagation();
        setState((s) => disarm(current(s, key)));
      }}
    >
      {armed ? "Remove?" : state.phase === "removing" ? "…" : "✕"}
    </button>
  );
}
