/**
 * Where the history ends for the Time slider (store/timeWindowGuard.ts historyEnd): the horizon, the
 * target of a running restore (an undo, a redo, an edit in the past: the history the user had,
 * computed again) or the time held past them. The whole history the slider, the window's width and
 * the zoom steps span is [0, this end], not the restore's progress. Re-renders only when the end
 * changes (not on every time change while playing, where the time stays inside the history).
 */
import { useInfoValue, useUi } from "../EditorContext";
import { historyEnd } from "../store/timeWindowGuard";

export function useHistoryEnd(): number {
  const known = useInfoValue((i) => historyEnd(i));
  return useUi((s) => Math.max(known, s.t));
}
