/**
 * Calculation: compute ahead by seconds and/or events, or without limit (∞); the horizon; automatic
 * extension during playback; progress and Cancel while the worker computes. Compute and Auto-extend
 * say what they do in their titles (a new user read "Time 10 s" as the current time). The horizon is plain
 * text, not an <output> (a live region: a screen reader announced it every 50 ms while computing).
 * Cancel goes with the computation: if it had the keyboard focus, the focus goes to Compute (it
 * fell to the page: review). Compute, greyed out while the worker computes, keeps the focus
 * (FocusKeptButton: pressed from the keyboard, it dropped the focus to the page). Seconds ahead and
 * Events ahead apply on Enter or on leaving them; a refused value stays typed, the refusal beside it
 * (useTypedField.tsx) saying which value Compute still uses.
 */
import { useEffect, useRef } from "react";
import { useEditor, useInfoValue, useUi } from "../EditorContext";
import type { CalcSettings } from "../store/uiStore";
import { formatNumber, parseNumber } from "./EditableCell";
import { EngineWatch } from "./EngineWatch";
import { FocusKeptButton } from "./FocusKeptButton";
import { isFieldMessage } from "./fieldMessages";
import { refusedTyped } from "./typedRefusal";
import { useTypedField } from "./useTypedField";

const SECONDS = "Seconds ahead";
const EVENTS = "Events ahead";

export function CalculationPanel() {
  const editor = useEditor();
  const calc = useUi((s) => s.calc);
  const horizon = useInfoValue((i) => i.horizon);
  const computing = useInfoValue((i) => i.computing);
  const idle = useInfoValue((i) => i.idle);
  const stopped = useInfoValue((i) => i.stopped);
  const refusedAction = useInfoValue((i) => i.stoppedPath?.startsWith("actions[") === true);
  const set = (patch: Partial<CalcSettings>) =>
    editor.ui.setState((s) => ({ calc: { ...s.calc, ...patch } }));
  const unlimited = !calc.useTime && !calc.useEvents;
  const computeRef = useRef<HTMLButtonElement>(null);
  /** Whether Cancel has the focus (a removed element fires no blur, so this stays true then). */
  const cancelFocused = useRef(false);
  const running = computing !== null;
  useEffect(() => {
    if (running || !cancelFocused.current) return;
    cancelFocused.current = false;
    if (document.activeElement === null || document.activeElement === document.body)
      computeRef.current?.focus();
  }, [running]);
  // An accepted setting takes down its field's refusal still in the message bar (a refusal of
  // "1e999" stayed up after 20 was accepted, as if 20 had been refused too).
  const accept = (name: string, patch: Partial<CalcSettings>): null => {
    set(patch);
    if (isFieldMessage(editor.ui.getState().message, name)) editor.ui.setState({ message: null });
    return null;
  };
  // A refused setting stays in its field for correction (it was put back, the text typed lost:
  // useTypedField.tsx); the setting in use is the one before, which the refusal says.
  const seconds = useTypedField(String(calc.seconds), (typed) => {
    const x = parseNumber(typed);
    return x !== null && x > 0 && Number.isFinite(x)
      ? accept(SECONDS, { seconds: x })
      : refusedTyped(
          SECONDS,
          "must be a positive finite number",
          typed,
          `Compute still uses ${calc.seconds} s`,
        );
  });
  const events = useTypedField(String(calc.events), (typed) => {
    const x = parseNumber(typed);
    return x !== null && x >= 1 && Number.isInteger(x)
      ? accept(EVENTS, { events: x })
      : refusedTyped(
          EVENTS,
          "must be a whole number of at least 1",
          typed,
          `Compute still uses ${calc.events} events`,
        );
  });

  let progress: number | null = null;
  if (computing) {
    const parts: number[] = [];
    if (computing.targetTime !== null && computing.targetTime > computing.startHorizon)
      parts.push((horizon - computing.startHorizon) / (computing.targetTime - computing.startHorizon));
    if (computing.targetEvents !== null && computing.targetEvents > 0)
      parts.push(computing.events / computing.targetEvents);
    progress = parts.length ? Math.min(1, Math.max(...parts)) : null;
  }

  return (
    <section className="panel" aria-labelledby="calc-title">
      <h2 id="calc-title">Calculation</h2>
      <div className="row">
        <label>
          <input
            type="checkbox"
            aria-label="Limit by time"
            checked={calc.useTime}
            onChange={(e) => set({ useTime: e.target.checked })}
          />{" "}
          Time
        </label>
        <input aria-label={SECONDS} size={5} {...seconds.input} /> s
        <label>
          <input
            type="checkbox"
            aria-label="Limit by events"
            checked={calc.useEvents}
            onChange={(e) => set({ useEvents: e.target.checked })}
          />{" "}
          Events
        </label>
        <input aria-label={EVENTS} size={6} {...events.input} />
        <button
          type="button"
          aria-pressed={unlimited}
          aria-label="∞: compute until no event is left"
          title="Compute until no event is left"
          onClick={() => set({ useTime: false, useEvents: false })}
        >
          ∞
        </button>
      </div>
      {/* under the settings: beside its field, a refusal pushed the Events box away from its own */}
      {seconds.refusal || events.refusal ? (
        <div className="row">
          {seconds.refusal}
          {events.refusal}
        </div>
      ) : null}
      <div className="row">
        <FocusKeptButton
          ref={computeRef}
          enabled={computing === null}
          onPress={() => editor.computeAhead()}
          title="Compute further past the horizon: the seconds and/or events ticked above (∞: until no event is left)"
        >
          Compute
        </FocusKeptButton>
        <label title="While playing forwards, compute further by itself as the time nears the horizon (as Compute does)">
          <input
            type="checkbox"
            checked={calc.autoExtend}
            onChange={(e) => set({ autoExtend: e.target.checked })}
          />{" "}
          Auto-extend
        </label>
        <span>
          horizon <span className="horizon">{formatNumber(horizon)}</span> s{idle ? " (no more events)" : ""}
          {stopped !== null && (
            <span title={stopped}>
              {stopped.startsWith("the history holds")
                ? " (stopped: history too large)"
                : refusedAction
                  ? " (stopped: an action is refused)"
                  : " (stopped: the engine cannot go on)"}
            </span>
          )}
        </span>
      </div>
      <EngineWatch />
      {computing && (
        <div className="row">
          <progress aria-label="Computation progress" max={1} value={progress ?? undefined} />
          <span>{computing.events} events</span>
          <button
            type="button"
            onClick={() => editor.cancelCompute()}
            onFocus={() => {
              cancelFocused.current = true;
            }}
            onBlur={() => {
              cancelFocused.current = false;
            }}
          >
            Cancel
          </button>
        </div>
      )}
    </section>
  );
}
