/**
 * Calculation: compute ahead by seconds and/or events, or without limit (∞); the horizon; automatic
 * extension during playback; progress and Cancel while the worker computes. Compute and Auto-extend
 * say what they do in their titles (a new user read "Time 10 s" as the current time). The horizon is plain
 * text, not an <output> (a live region: a screen reader announced it every 50 ms while computing).
 * Cancel goes with the computation: if it had the keyboard focus, the focus goes to Compute (it
 * fell to the page: review). Compute, greyed out while the worker computes, keeps the focus
 * (FocusKeptButton: pressed from the keyboard, it dropped the focus to the page).
 */
import { useEffect, useRef } from "react";
import { useEditor, useInfoValue, useUi } from "../EditorContext";
import type { CalcSettings } from "../store/uiStore";
import { formatNumber, parseNumber } from "./EditableCell";
import { EngineWatch } from "./EngineWatch";
import { FocusKeptButton } from "./FocusKeptButton";

/** Enter in a settings field applies it (as leaving the field does; it only applied on leaving). */
function blurOnEnter(e: React.KeyboardEvent<HTMLInputElement>): void {
  if (e.key === "Enter") e.currentTarget.blur();
}

export function CalculationPanel() {
  const editor = useEditor();
  const calc = useUi((s) => s.calc);
  const horizon = useInfoValue((i) => i.horizon);
  const computing = useInfoValue((i) => i.computing);
  const idle = useInfoValue((i) => i.idle);
  const stopped = useInfoValue((i) => i.stopped);
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
  const accept = (name: string, patch: Partial<CalcSettings>) => {
    set(patch);
    if (editor.ui.getState().message?.text.startsWith(`${name}: must be `))
      editor.ui.setState({ message: null });
  };
  // A refused setting is put back, and the message bar says so (it was restored without a word).
  const refuse = (input: HTMLInputElement, name: string, what: string, kept: number) => {
    const typed = input.value;
    input.value = String(kept);
    if (typed.trim() !== String(kept))
      editor.ui.setState({
        message: { text: `${name}: must be ${what}, got "${typed}" (kept ${kept})`, tone: "error" },
      });
  };

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
        <input
          aria-label="Seconds ahead"
          size={5}
          defaultValue={calc.seconds}
          onKeyDown={blurOnEnter}
          onBlur={(e) => {
            const x = parseNumber(e.target.value);
            if (x !== null && x > 0 && Number.isFinite(x)) accept("Seconds ahead", { seconds: x });
            else refuse(e.target, "Seconds ahead", "a positive finite number", calc.seconds);
          }}
        />{" "}
        s
        <label>
          <input
            type="checkbox"
            aria-label="Limit by events"
            checked={calc.useEvents}
            onChange={(e) => set({ useEvents: e.target.checked })}
          />{" "}
          Events
        </label>
        <input
          aria-label="Events ahead"
          size={6}
          defaultValue={calc.events}
          onKeyDown={blurOnEnter}
          onBlur={(e) => {
            const x = parseNumber(e.target.value);
            if (x !== null && x >= 1 && Number.isInteger(x)) accept("Events ahead", { events: x });
            else refuse(e.target, "Events ahead", "a whole number of at least 1", calc.events);
          }}
        />
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
