/**
 * The Time slider's window width field ("window [5] s"): shows how many seconds the slider spans
 * (the whole history's for the whole history: during an undo's restore, the history being restored);
 * a width typed there (Enter, or leaving the field) zooms in one step to a window that wide centred
 * on the current time (store/zoomRequest.ts zoomToSpan: inside the history, at least the smallest
 * span; a width covering the history, or ∞, is the whole history). From a billion seconds to 5 s is
 * one typed number instead of 28 presses of Zoom in.
 * As in the time field, only typed text is applied (clicking in and out changes nothing), Escape
 * drops it, and text that is not a positive number of seconds is refused with a message. A width
 * narrower than the smallest window there is widened to it, which a note says; an applied width
 * clears the field's earlier message (zoomWidthMessages.ts). The field widens to show its width
 * whole (0.000123457 was cut to 7 characters).
 */
import { useState } from "react";
import { useEditor, useUi } from "../EditorContext";
import { viewRange } from "../store/timeWindow";
import { zoomToSpan } from "../store/zoomRequest";
import { formatNumber, parseNumber } from "./EditableCell";
import { useHistoryEnd } from "./useHistoryEnd";
import { applyZoom, zoomState } from "./zoomActions";
import { messageAfterWidth, refusedWidth, WIDTH_LABEL } from "./zoomWidthMessages";

export function ZoomWidthField() {
  const editor = useEditor();
  const w = useUi((s) => s.timeWindow);
  /** The text typed in the field (null: nothing typed; the field shows the window's width). */
  const [draft, setDraft] = useState<string | null>(null);
  const r = viewRange(w, useHistoryEnd());
  const text = draft ?? formatNumber(r.hi - r.lo);

  const commit = () => {
    if (draft === null) return;
    const typed = draft.trim();
    const span = parseNumber(draft);
    setDraft(null);
    if (span === null || !(span > 0)) {
      editor.ui.setState({ message: refusedWidth(typed) });
      return;
    }
    const s = zoomState(editor);
    const { message } = editor.ui.getState();
    const after = messageAfterWidth(message, typed, span, s.t, s.end);
    if (after !== message) editor.ui.setState({ message: after });
    applyZoom(editor, () => zoomToSpan(s.w, span, s.t, s.end));
  };

  return (
    <label className="zoom-width">
      window{" "}
      <input
        aria-label={WIDTH_LABEL}
        size={Math.max(7, text.length + 1)}
        value={text}
        onChange={(e) => setDraft(e.target.value)}
        onBlur={commit}
        onKeyDown={(e) => {
          if (e.key === "Enter") commit();
          else if (e.key === "Escape") setDraft(null);
        }}
      />{" "}
      s
    </label>
  );
}
