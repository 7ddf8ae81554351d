/**
 * The Time slider's zoom controls (store/timeWindow.ts): Zoom in (half the span around the current
 * time), Zoom out (twice the span, up to the whole history), Whole history, the window's width
 * (ZoomWidthField: type 5 for 5 s around the current time) and, when zoomed, the part of the
 * history the slider shows ("showing 12.5–25 s"). The wheel over the slider zooms too
 * (useWheelZoom). The whole history is [0, where the history ends] (useHistoryEnd): during an undo's
 * restore, the history being restored, so a zoom step halves that and not the restore's progress.
 * Zooming is not an edit (no undo step) and is not saved.
 * A button that cannot act is aria-disabled (FocusKeptButton) rather than disabled: a disabled
 * button drops the keyboard focus to the page, so pressing Zoom in until the smallest span, or Whole
 * history, lost the user's place in the tab order.
 */
import { useEditor, useUi } from "../EditorContext";
import { canZoomIn, windowLabel, zoomIn, zoomOut } from "../store/timeWindow";
import { FocusKeptButton } from "./FocusKeptButton";
import { useHistoryEnd } from "./useHistoryEnd";
import { ZoomWidthField } from "./ZoomWidthField";
import { applyZoom } from "./zoomActions";

export function TimeZoom() {
  const editor = useEditor();
  const w = useUi((s) => s.timeWindow);
  const end = useHistoryEnd();
  return (
    <span className="zoom">
      <FocusKeptButton
        enabled={canZoomIn(w, end)}
        onPress={() => applyZoom(editor, (s) => zoomIn(s.w, s.t, s.end))}
      >
        Zoom in
      </FocusKeptButton>
      <FocusKeptButton
        enabled={w !== null}
        onPress={() => applyZoom(editor, (s) => zoomOut(s.w, s.t, s.end))}
      >
        Zoom out
      </FocusKeptButton>
      <FocusKeptButton enabled={w !== null} onPress={() => applyZoom(editor, () => null)}>
        Whole history
      </FocusKeptButton>
      <ZoomWidthField />
      {w === null ? null : <output aria-label="Time range shown">showing {windowLabel(w)} s</output>}
    </span>
  );
}
