/**
 * Applies a zoom of the Time slider's window (the Zoom buttons, the wheel over the slider, a typed
 * width) to the editor's UI store. The state is read at the request, not from a render: the time
 * moves without re-rendering the Time panel while playing. `end` is where the history ends
 * (timeWindowGuard's historyEnd: the horizon, a running restore's target or a time held past them)
 * and the whole history is [0, end]: during an undo's restore a zoom step is relative to the history
 * being restored, not to the restore's progress (Zoom in at 7 s of a 30 s restore gave a 3.56 s
 * window). Zooming is not an edit (no undo step) and is not saved; the store is written only on a
 * change.
 */
import type { Editor } from "../editor";
import type { TimeWindow } from "../store/timeWindow";
import { historyEnd } from "../store/timeWindowGuard";

/** What a zoom request is computed from: the window (null: the whole history [0, end]), the time. */
export interface ZoomState {
  w: TimeWindow | null;
  t: number;
  end: number;
}

/** The zoom state of `editor` now. */
export function zoomState(editor: Pick<Editor, "ui" | "client">): ZoomState {
  const { timeWindow, t } = editor.ui.getState();
  return { w: timeWindow, t, end: historyEnd(editor.client.getSnapshot(), t) };
}

export function applyZoom(
  editor: Pick<Editor, "ui" | "client">,
  request: (s: ZoomState) => TimeWindow | null,
): void {
  const s = zoomState(editor);
  const next = request(s);
  if (next !== s.w) editor.ui.setState({ timeWindow: next });
}
