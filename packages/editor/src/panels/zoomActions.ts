/**
 * Applies a zoom of the Time slider's window (the Zoom buttons, the wheel over the slider, a typed
 * width) to the editor's UI store. The state is read at the request, not from a render: the time
 * moves without re-rendering the Time panel while playing. `end` is where the history ends
 * (timeWindowGuard's historyEnd: the horizon, a running restore's target or a time held past them).
 * Zooming is not an edit (no undo step) and is not saved; the store is written only on a change.
 */
import type { Editor } from "../editor";
import type { TimeWindow } from "../store/timeWindow";
import { historyEnd } from "../store/timeWindowGuard";

/** What a zoom request is computed from. */
export interface ZoomState {
  w: TimeWindow | null;
  t: number;
  horizon: number;
  end: number;
}

export function applyZoom(
  editor: Pick<Editor, "ui" | "client">,
  request: (s: ZoomState) => TimeWindow | null,
): void {
  const { timeWindow, t } = editor.ui.getState();
  const info = editor.client.getSnapshot();
  const next = request({ w: timeWindow, t, horizon: info.horizon, end: historyEnd(info, t) });
  if (next !== timeWindow) editor.ui.setState({ timeWindow: next });
}
