/**
 * Keeps the UI store's time window (the Time slider's zoom, timeWindow.ts) around the current time:
 * whenever the time moves (playing, stepping, scrubbing, a typed time) or the history changes
 * (computing, an edit, an undo), the window follows the time page by page inside the history
 * (`follow`). The history's end is the horizon, the target of a running restore (after an edit in
 * the past, an undo, a redo, the history the user had is computed again), or the current time while
 * it is held past the horizon for such a restore: an undo or an edit in the past keeps the zoom
 * though the horizon drops to the edit's time or to 0 before the restore starts (two messages from
 * the host). A load of another scene returns to the whole history with the time (editorSession.ts).
 * The history grows (`historyGrows`) while a computation runs or while playing forward can ask for
 * one (auto-extend, events left, not stopped): a page turned forward then is whole (timeWindow.ts).
 * When it stops growing for good (historyMayGrow: the computation ends and nothing is left to
 * compute, the engine stopped, auto-extend is turned off; not a pause) without being cut, a window
 * reaching past the history's end settles back inside it (`settle`), the time kept.
 */
import { canExtend } from "../playback";
import { type ComputeStatus, restoreTarget } from "../remote/protocol";
import { follow, settle } from "./timeWindow";
import type { UiState, UiStore } from "./uiStore";

/** The part of the TimelineClient's snapshot the guard reads. */
export interface HistoryInfo {
  horizon: number;
  computing: ComputeStatus | null;
  idle: boolean;
  stopped: string | null;
}

/** What the guard watches: the TimelineClient's snapshot and its changes. */
export interface HistorySource {
  getSnapshot(): HistoryInfo;
  subscribe(listener: () => void): () => void;
}

/** Whether the history is about to reach past its end: computing, or playing forward into it. */
export function historyGrows(
  s: Pick<UiState, "playing" | "speed" | "calc">,
  info: Pick<HistoryInfo, "computing" | "idle" | "stopped">,
): boolean {
  return info.computing !== null || (s.playing && s.speed > 0 && canExtend(s.calc.autoExtend, info));
}

/**
 * Where the history ends for the window: the horizon, the target of a running restore, or the time t
 * held past them (the history up to it is about to be computed again).
 */
export function historyEnd(info: { horizon: number; computing: ComputeStatus | null }, t = 0): number {
  return Math.max(info.horizon, restoreTarget(info.computing), t);
}

/**
 * Whether the history may still grow past its end: a computation runs, or playing forward would ask
 * for one (auto-extend on, events left, not stopped). Pausing does not change it (playing again
 * grows it): a page turned into the computation stays whole while paused, so pressing the slider's
 * thumb, which pauses, never moves the window under the pointer.
 */
export function historyMayGrow(
  s: Pick<UiState, "calc">,
  info: Pick<HistoryInfo, "computing" | "idle" | "stopped">,
): boolean {
  return info.computing !== null || canExtend(s.calc.autoExtend, info);
}

/**
 * Whether the history has just stopped growing for good (a check that found that it may grow, then
 * one that finds it may not: historyMayGrow) without being cut: its end has not dropped since (an
 * edit in the past or an undo drops the horizon before the restore starts: the window waits for the
 * history to be computed again) and the time is not held past the horizon.
 */
export function stoppedGrowing(
  was: { mayGrow: boolean; end: number },
  now: { mayGrow: boolean; end: number },
  t: number,
  horizon: number,
): boolean {
  return was.mayGrow && !now.mayGrow && now.end >= was.end && t <= horizon;
}

/** Keeps the time window of `ui` around the time and inside the history of `source`; returns the unsubscribe. */
export function keepTimeWindow(ui: UiStore, source: HistorySource): () => void {
  let last = { mayGrow: false, end: 0 };
  const check = () => {
    const s = ui.getState();
    const info = source.getSnapshot();
    const now = { mayGrow: historyMayGrow(s, info), end: historyEnd(info, s.t) };
    const stopped = stoppedGrowing(last, now, s.t, info.horizon);
    last = now;
    if (s.timeWindow === null) return;
    const turned = follow(s.timeWindow, s.t, now.end, historyGrows(s, info));
    // a page turned into the computation settles inside the history once it stops growing
    const next = stopped ? settle(turned, s.t, now.end) : turned;
    if (next !== s.timeWindow) ui.setState({ timeWindow: next });
  };
  const offUi = ui.subscribe((s, p) => {
    // auto-extend off: the history stops growing (historyMayGrow)
    if (s.t !== p.t || s.timeWindow !== p.timeWindow || s.calc !== p.calc) check();
  });
  const offSource = source.subscribe(check);
  return () => {
    offUi();
    offSource();
  };
}
