/**
 * Time: the `Time` scrubber over the time window (the whole history [0, its end] unless zoomed,
 * TimeZoom; the wheel over it zooms, useWheelZoom; during an undo's restore the end is the history
 * being restored, useHistoryEnd) with the window's event ticks, a time field (a time past the
 * horizon is computed first), −1 / 0 / +1 s and stepping to the previous / next event. Scrubbing and
 * zooming are not edits (no undo step).
 * While playing, this panel re-renders about 10 times a second (useShownTime); the slider's thumb
 * follows every frame by itself (TimeSlider). The time field shows the current time until the user
 * types in it; only typed text is gone to (Enter or leaving the field), so clicking into the field
 * while playing and away again leaves the time alone; text that is not a time is refused beside the
 * field and in the message bar, the text kept for correction (useTypedField.tsx); a valid time then
 * clears the message (fieldMessages.ts). Zoomed, it shows the time to the
 * window's precision (timeInWindow) and widens to fit. The horizon is plain text, not an <output>:
 * that is a live region, and a computation changes the horizon every 50 ms.
 */
import { useMemo, useRef } from "react";
import { useEditor, useInfoValue, useUi } from "../EditorContext";
import { timeInWindow, viewRange } from "../store/timeWindow";
import { formatNumber, parseNumber } from "./EditableCell";
import { isFieldMessage } from "./fieldMessages";
import { TimeSlider } from "./TimeSlider";
import { TimeZoom } from "./TimeZoom";
import { refusedTyped } from "./typedRefusal";
import { useHistoryEnd } from "./useHistoryEnd";
import { useRefreshed } from "./useRefreshed";
import { useShownTime } from "./useThrottledTime";
import { useTypedField } from "./useTypedField";
import { useWheelZoom } from "./useWheelZoom";

const TICKS = 300;
/**
 * Shortest interval between two requests for the ticks (ms): they follow a computation as it goes,
 * once a second (each refresh re-renders up to TICKS lines of the slider's SVG).
 */
const TICKS_EVERY_MS = 1000;
const NO_TICKS: number[] = [];
const TIME_LABEL = "Time (s)";

export function TimePanel() {
  const editor = useEditor();
  const t = useShownTime();
  const horizon = useInfoValue((i) => i.horizon);
  const revision = useInfoValue((i) => i.revision);
  const computing = useInfoValue((i) => i.computing !== null);
  const docRevision = useInfoValue((i) => i.docRevision);
  const timeWindow = useUi((s) => s.timeWindow);
  const end = useHistoryEnd();
  const windowKey = timeWindow === null ? "all" : `${timeWindow.lo}:${timeWindow.hi}`;
  // Throttled while a computation extends the history; at once when the scene itself changes (an
  // edit in the past moves the ticks after it, which stayed stale for up to TICKS_EVERY_MS) or the
  // slider's window does (a zoom or a page turn).
  const ticks = useRefreshed(
    () =>
      revision < 0
        ? Promise.resolve([])
        : timeWindow === null
          ? editor.client.ticks(TICKS)
          : editor.client.ticks(TICKS, timeWindow.lo, timeWindow.hi),
    `${revision} ${windowKey}`,
    NO_TICKS,
    TICKS_EVERY_MS,
    `${docRevision} ${windowKey}`,
  );
  const scrubber = useRef<HTMLDivElement>(null);
  useWheelZoom(editor, scrubber);
  // Typed text is applied by goTo; text that is not a time is refused (useTypedField keeps it for
  // correction; it was dropped without a word, and a negative time went to 0 without one: audit).
  const field = useTypedField(
    // zoomed, to the window's precision (6 digits read 1e+9 for every time of a window of seconds there)
    timeInWindow(t, timeWindow, formatNumber),
    (typed) => {
      const x = parseNumber(typed);
      if (x === null || !Number.isFinite(x))
        return refusedTyped(TIME_LABEL, "must be a finite number of seconds", typed);
      if (x < 0) return refusedTyped(TIME_LABEL, "must be 0 or later", typed);
      // the field's earlier refusal no longer holds (it stayed up)
      const { message } = editor.ui.getState();
      if (isFieldMessage(message, TIME_LABEL)) editor.ui.setState({ message: null });
      void editor.goTo(x);
      return null;
    },
  );

  // Ticks are times: a reply asked for an earlier window is drawn on the current one, in its range.
  const tickLines = useMemo(() => {
    const { lo, hi } = viewRange(timeWindow, end);
    if (!(hi > lo)) return null;
    return ticks
      .filter((x) => x >= lo && x <= hi)
      .map((x, i) => {
        const at = ((x - lo) / (hi - lo)) * 1000;
        // biome-ignore lint/suspicious/noArrayIndexKey: ticks are positional (equal times repeat) and never reordered
        return <line key={i} x1={at} x2={at} y1={0} y2={10} />;
      });
  }, [ticks, end, timeWindow]);

  return (
    <section className="panel time-panel" aria-labelledby="time-title">
      <h2 id="time-title">Time</h2>
      <div className="scrubber" ref={scrubber} title="Wheel: zoom in and out around the current time">
        <TimeSlider />
        <svg className="ticks" viewBox="0 0 1000 10" preserveAspectRatio="none" aria-hidden="true">
          {tickLines}
        </svg>
      </div>
      <div className="row">
        <label>
          t = <input aria-label={TIME_LABEL} size={Math.max(9, field.text.length + 1)} {...field.input} /> s
          of <span className="horizon">{formatNumber(horizon)}</span> s
        </label>
        {field.refusal}
        <TimeZoom />
        {/* After an undo, a redo or a rename the history is recomputed from the start while the time
            stays: say why the canvas and tables show an earlier state until it gets there. */}
        {t > horizon ? (
          <span aria-live="polite" className="behind">
            {" "}
            {computing ? "computing up to t" : "past the computed history"}: the view shows t ={" "}
            {formatNumber(horizon)} s{computing ? " until then" : ""}
          </span>
        ) : null}
      </div>
      <div className="row">
        <button
          type="button"
          aria-label="−1 s: back 1 second"
          onClick={() => editor.setTime(editor.ui.getState().t - 1)}
        >
          −1 s
        </button>
        <button
          type="button"
          aria-label="0: go to start"
          title="Go to start"
          onClick={() => editor.setTime(0)}
        >
          0
        </button>
        <button
          type="button"
          aria-label="+1 s: forward 1 second"
          onClick={() => void editor.goTo(editor.ui.getState().t + 1)}
        >
          +1 s
        </button>
        <button type="button" onClick={() => void editor.stepEvent(-1)}>
          Previous event
        </button>
        <button type="button" onClick={() => void editor.stepEvent(1)}>
          Next event
        </button>
      </div>
    </section>
  );
}
