/**
 * The Time slider's window width field ("window [5] s"): shows how many seconds the slider spans
 * (the horizon for the whole history); a width typed there (Enter, or leaving the field) zooms in
 * one step to a window that wide centred on the current time (store/zoomRequest.ts zoomToSpan:
 * inside the history, at least the smallest span; a width covering the history, or ∞, is the whole
 * history). From a billion seconds to 5 s is one typed number instead of 28 presses of Zoom in.
 * As in the time field, only typed text is applied (clicking in and out changes nothing), Escape
 * drops it, and text that is not a positive number of seconds is refused with a message.
 */
import { useState } from "react";
import { useEditor, useInfoValue, useUi } from "../EditorContext";
import { viewRange } from "../store/timeWindow";
import { zoomToSpan } from "../store/zoomRequest";
import { formatNumber, parseNumber } from "./EditableCell";
import { applyZoom } from "./zoomActions";

export function ZoomWidthField() {
  const editor = useEditor();
  const w = useUi((s) => s.timeWindow);
  const horizon = useInfoValue((i) => i.horizon);
  /** The text typed in the field (null: nothing typed; the field shows the window's width). */
  const [draft, setDraft] = useState<string | null>(null);
  const r = viewRange(w, horizon);

  const commit = () => {
    if (draft === null) return;
    const span = parseNumber(draft);
    setDraft(null);
    if (span === null || !(span > 0)) {
      const text = `Window width (s): must be a positive number of seconds, got "${draft.trim()}"`;
      editor.ui.setState({ message: { text, tone: "error" } });
      return;
    }
    applyZoom(editor, (s) => zoomToSpan(s.w, span, s.t, s.end));
  };

  return (
    <label className="zoom-width">
      window{" "}
      <input
        aria-label="Window width (s)"
        size={7}
        value={draft ?? formatNumber(r.hi - r.lo)}
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
