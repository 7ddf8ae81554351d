/**
 * The Time slider's window width field ("window [5] s"): shows how many seconds the slider spans
 * (the whole history's for the whole history: during an undo's restore, the history being restored);
 * a width typed there (Enter, or leaving the field) zooms in one step to a window that wide centred
 * on the current time (store/zoomRequest.ts zoomToSpan: inside the history, at least the smallest
 * span; a width covering the history, or ∞, is the whole history). From a billion seconds to 5 s is
 * one typed number instead of 28 presses of Zoom in.
 * As in the time field, only typed text is applied (clicking in and out changes nothing), Escape
 * drops it, and text that is not a positive number of seconds is refused beside the field and in the
 * message bar, the text kept for correction (useTypedField.tsx). A width
 * narrower than the smallest window there is widened to it, which a note says; an applied width
 * clears the field's earlier message (zoomWidthMessages.ts). The field widens to show its width
 * whole (0.000123457 was cut to 7 characters).
 */
import { useEditor, useUi } from "../EditorContext";
import { viewRange } from "../store/timeWindow";
import { zoomToSpan } from "../store/zoomRequest";
import { formatNumber, parseNumber } from "./EditableCell";
import { useHistoryEnd } from "./useHistoryEnd";
import { useTypedField } from "./useTypedField";
import { applyZoom, zoomState } from "./zoomActions";
import { messageAfterWidth, refusedWidth, WIDTH_LABEL } from "./zoomWidthMessages";

export function ZoomWidthField() {
  const editor = useEditor();
  const w = useUi((s) => s.timeWindow);
  const r = viewRange(w, useHistoryEnd());
  const field = useTypedField(formatNumber(r.hi - r.lo), (typed) => {
    const span = parseNumber(typed);
    if (span === null || !(span > 0)) return refusedWidth(typed);
    const s = zoomState(editor);
    const { message } = editor.ui.getState();
    const after = messageAfterWidth(message, typed, span, s.t, s.end);
    if (after !== message) editor.ui.setState({ message: after });
    applyZoom(editor, () => zoomToSpan(s.w, span, s.t, s.end));
    return null;
  });

  return (
    <label className="zoom-width">
      window <input aria-label={WIDTH_LABEL} size={Math.max(7, field.text.length + 1)} {...field.input} /> s
      {field.refusal}
    </label>
  );
}
