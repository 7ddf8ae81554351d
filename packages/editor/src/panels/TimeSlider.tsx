/**
 * The `Time` slider over the time window: the whole history unless zoomed (store/timeWindow.ts; the
 * window follows the time by itself, store/timeWindowGuard.ts). The whole history is [0, where it
 * ends] (historyEnd): during an undo's restore, the history being restored, the thumb at the
 * restore's progress (the time shown until the restore reaches the time held). Its thumb
 * and range follow the store outside React (a store subscription writes the input's value): playback
 * changes the time on every animation frame and re-rendering a panel per frame is not needed to move
 * one thumb. While playing, a change that moves the thumb by less than a pixel is not written (each
 * write of a range input's value costs Chromium a relayout, repaint and re-layerization of the page,
 * about 1 ms per frame in the 2,000-disc profile); a new range is always written. Paused, the slider
 * always shows the exact time. While the time is held past the horizon (an undo's or an edit's
 * recomputation), the thumb shows the recomputation's progress and the time stays held: an input or
 * change event carrying the value the slider wrote itself is not the user's and is ignored (a click
 * at 5,000 s snapped the time back to the progress). Its aria-valuetext ("t = 8.21 s") is written on every change of the time
 * (a string attribute, no layout): what a screen reader reports never lags behind the time, although
 * the value can. Dragging it sets the time (not an edit), within its range (sliderTime:
 * Chromium's value at an end can read just past it, which turned the page under the pointer);
 * holding it while playing pauses until it is let go. Zoomed, its arrow and page keys move the time
 * on past the window's edges, turning the page (sliderKeys.ts); Home and End go to the window's ends.
 */
import { useEffect, useRef } from "react";
import { useEditor, useUi } from "../EditorContext";
import { sliderTime, viewRange } from "../store/timeWindow";
import { historyEnd } from "../store/timeWindowGuard";
import { formatNumber } from "./EditableCell";
import { sliderKeyTime } from "./sliderKeys";
import { useHistoryEnd } from "./useHistoryEnd";

/** What a screen reader says of the slider: the current time. */
export const valueText = (t: number): string => `t = ${formatNumber(t)} s`;

export function TimeSlider() {
  const editor = useEditor();
  const range = viewRange(
    useUi((s) => s.timeWindow),
    useHistoryEnd(),
  );
  const ref = useRef<HTMLInputElement>(null);
  /** The value the slider last wrote itself (as the input reads it back); null before the first. */
  const written = useRef<string | null>(null);

  useEffect(() => {
    const input = ref.current!;
    const { ui, client } = editor;
    let width = input.getBoundingClientRect().width;
    const ro =
      typeof ResizeObserver === "undefined"
        ? null
        : new ResizeObserver((entries) => {
            width = entries[0]?.contentRect.width ?? width;
          });
    ro?.observe(input);
    let shown = Number.NaN;
    let shownLo = Number.NaN;
    let shownHi = Number.NaN;
    let shownText = "";
    const show = (force: boolean) => {
      const s = ui.getState();
      const text = valueText(s.t);
      if (text !== shownText) {
        shownText = text;
        input.setAttribute("aria-valuetext", text);
      }
      const info = client.getSnapshot();
      const { lo, hi } = viewRange(s.timeWindow, historyEnd(info, s.t));
      const t = Math.min(s.t, info.horizon);
      const sameRange = lo === shownLo && hi === shownHi;
      // (a value the user moved the thumb to is rewritten: held past the horizon, it is not the time's)
      if (t === shown && sameRange && input.value === written.current) return;
      if (!force && sameRange && s.playing && Math.abs(t - shown) * Math.max(width, 1) < hi - lo) return;
      shown = t;
      shownLo = lo;
      shownHi = hi;
      if (!sameRange) {
        // the range before the value: a value outside the old range would be clamped
        input.min = String(lo);
        input.max = String(hi);
      }
      input.value = String(t);
      // read back: Chromium keeps about 15 significant digits of what is written
      written.current = input.value;
    };
    show(true);
    const offUi = ui.subscribe((s, p) => {
      if (s.t !== p.t || s.playing !== p.playing || s.timeWindow !== p.timeWindow) show(!s.playing);
    });
    const offInfo = client.subscribe(() => show(true));
    return () => {
      ro?.disconnect();
      offUi();
      offInfo();
    };
  }, [editor]);

  // Holding the thumb while playing holds the time there (playback would pull the thumb away from
  // under the pointer); letting go plays on.
  const onPointerDown = () => {
    if (!editor.ui.getState().playing) return;
    editor.ui.setState({ playing: false });
    const resume = () => {
      window.removeEventListener("pointerup", resume);
      window.removeEventListener("pointercancel", resume);
      editor.ui.setState({ playing: true });
    };
    window.addEventListener("pointerup", resume);
    window.addEventListener("pointercancel", resume);
  };

  return (
    <input
      ref={ref}
      onPointerDown={onPointerDown}
      type="range"
      aria-label="Time"
      min={range.lo}
      max={range.hi}
      step="any"
      defaultValue={0}
      onKeyDown={(e) => {
        // zoomed, the input would stop at the window's edges: the time moves on and the page turns
        if (e.ctrlKey || e.metaKey || e.altKey) return;
        const { timeWindow, t } = editor.ui.getState();
        const next = sliderKeyTime(e.key, t, timeWindow, historyEnd(editor.client.getSnapshot(), t));
        if (next === null) return;
        e.preventDefault();
        editor.setTime(next);
      }}
      onChange={(e) => {
        // The slider's own value is no change by the user (a user's change moves the value): with the
        // time held past the horizon the thumb shows the restore's progress, and the change event
        // Chromium fires on letting go of a click (React sees the value it wrote, reformatted) set
        // the time to that progress.
        if (e.target.value === written.current) return;
        // clamped to the range: a value read just past an end turned the page (sliderTime)
        const { timeWindow, t } = editor.ui.getState();
        const end = historyEnd(editor.client.getSnapshot(), t);
        editor.setTime(sliderTime(Number(e.target.value), timeWindow, end));
      }}
    />
  );
}
