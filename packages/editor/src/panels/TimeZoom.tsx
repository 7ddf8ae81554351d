/**
 * The Time slider's zoom controls (store/timeWindow.ts): Zoom in (half the span around the current
 * time), Zoom out (twice the span, up to the whole history) and Whole history, and, when zoomed,
 * the part of the history the slider shows ("showing 12.5–25 s"). Zooming is not an edit (no undo
 * step) and is not saved.
 */
import { useEditor, useInfoValue, useUi } from "../EditorContext";
import { canZoomIn, type TimeWindow, windowLabel, zoomIn, zoomOut } from "../store/timeWindow";
import { historyEnd } from "../store/timeWindowGuard";

export function TimeZoom() {
  const editor = useEditor();
  const w = useUi((s) => s.timeWindow);
  const horizon = useInfoValue((i) => i.horizon);
  const set = (next: TimeWindow | null) => editor.ui.setState({ timeWindow: next });
  // Read at the click: the time moves without re-rendering this panel while playing.
  const now = () => ({ ...editor.ui.getState(), info: editor.client.getSnapshot() });
  return (
    <span className="zoom">
      <button
        type="button"
        disabled={!canZoomIn(w, horizon)}
        onClick={() => {
          const { timeWindow, t, info } = now();
          set(zoomIn(timeWindow, t, info.horizon));
        }}
      >
        Zoom in
      </button>
      <button
        type="button"
        disabled={w === null}
        onClick={() => {
          const { timeWindow, t, info } = now();
          set(zoomOut(timeWindow, t, historyEnd(info, t)));
        }}
      >
        Zoom out
      </button>
      <button type="button" disabled={w === null} onClick={() => set(null)}>
        Whole history
      </button>
      {w === null ? null : <output aria-label="Time range shown">showing {windowLabel(w)} s</output>}
    </span>
  );
}
