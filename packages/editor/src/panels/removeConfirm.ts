/**
 * The two-step confirm of an Event-log entry's remove button (RemoveActionButton), as pure state
 * transitions. A first press arms the button (it then reads "Remove?"); a second press at least
 * CONFIRM_DELAY_MS later removes the action; a press sooner (the second click of a double-click, a
 * held key's repeat) leaves it armed. Leaving the button (pointer, focus), Escape, or ARMED_MS
 * without a press disarm it. A removal that finishes (done or refused) brings the button to rest.
 * The state belongs to one action (`key`, which must tell every action of the scene apart: it holds
 * the scene's revision and the action's index): once the row shows another action (the log moved up
 * under the pointer after a removal), the button is at rest again, so a press meant for the action
 * removed only arms the next one, and the next action never shows the removed one's "removing".
 */

/** A second press sooner than this after arming does not confirm (ms). */
export const CONFIRM_DELAY_MS = 400;
/** An armed button with no press for this long disarms (ms). */
export const ARMED_MS = 4000;

export type ConfirmPhase = "idle" | "armed" | "removing";

export interface ConfirmState {
  phase: ConfirmPhase;
  /** The action the state belongs to (RemoveActionButton's key: scene revision and action index). */
  key: string;
  /** When the button was armed (ms, same clock as press's `now`). */
  at: number;
}

export const idle = (key: string): ConfirmState => ({ phase: "idle", key, at: 0 });

/** The state as seen by the button of action `key`: another action's state is at rest. */
export function current(s: ConfirmState, key: string): ConfirmState {
  return s.key === key ? s : idle(key);
}

/** A press at time `now` (ms): the next state, and whether the action is to be removed now. */
export function press(s: ConfirmState, now: number): { state: ConfirmState; remove: boolean } {
  if (s.phase === "idle") return { state: { phase: "armed", key: s.key, at: now }, remove: false };
  if (s.phase === "removing" || now - s.at < CONFIRM_DELAY_MS) return { state: s, remove: false };
  return { state: { ...s, phase: "removing" }, remove: true };
}

/** Leaving the button, Escape or the timeout: an armed button is at rest again. */
export function disarm(s: ConfirmState): ConfirmState {
  return s.phase === "armed" ? idle(s.key) : s;
}

/** The removal asked for has finished (done or refused): the button is at rest again. */
export function finished(s: ConfirmState): ConfirmState {
  return s.phase === "removing" ? idle(s.key) : s;
}
