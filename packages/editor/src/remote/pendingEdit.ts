/**
 * PendingEdits: the host's (host.ts) change whose reply waits. An edit in the past is applied with
 * `checkLater: false` and a rewrite of the scene (a `load` with `check`, a removed action) replaces
 * the timeline; the restore job (hostCompute.ts) then checks their later actions in slices, and the
 * request is answered (DEFERRED until then) once the history passes `checkTo` (ok) or a later
 * action is refused (the change is taken back, and the reply carries the refusal as a synchronous
 * apply would have, its path renamed to the action list before the edit: beforeEdit). Cancel, the
 * `takeBack` request (an Undo during the check) and a load take the change back too. At most one
 * change is pending: a further edit is refused until it is answered, and a computation asked
 * meanwhile extends the check's job or waits for the check to pass (`afterCheck`). This module holds
 * that state and answers the reply; the host restores its timeline (HostCompute.takeBack).
 */
import { actionKey } from "../doc/actionDiff";
import type { Action } from "../engineTypes";
import { errorInfo } from "./errors";
import type { ComputeAsk, ComputeStatus, ErrorInfo, HostMessage } from "./protocol";
import type { TimelineLike } from "./timelineLike";

/**
 * An edit in the past, or a rewrite of the scene (a removed action), whose later actions the
 * running restore job is still checking: its reply waits until the history passes `checkTo` (ok)
 * or a later action is refused (the change is taken back, and the reply carries the refusal as a
 * synchronous apply would have).
 */
export interface PendingEdit {
  /** The request to answer. */
  id: number;
  /** How to take the change back: the action list before an edit, or the timeline before a load. */
  undo: { actions: Action[] } | { timeline: TimelineLike };
  /**
   * Why the timeline before a load had stopped (a later action refused: its message and path), put
   * back with it on a take-back: a refused change of a scene whose computation was stopped leaves
   * the scene stopped at the same refusal, still listed (a fix of a refused action refused again).
   */
  stoppedBefore?: ErrorInfo | null;
  /** The last action's time, up to the old history's end: the check is done once the horizon passes it. */
  checkTo: number;
  /** The old history's end, recomputed again after a take-back. */
  horizon: number;
  /** Appended to a refusal of a later action (an edit: " (once this action is in place)"). */
  suffix: string;
}

/** run()'s value for a request answered later (an edit whose later actions are being checked). */
export const DEFERRED = Symbol("deferred");

export class PendingEdits {
  /** The change whose later actions are being checked, or null. */
  edit: PendingEdit | null = null;
  /** A computation asked while an edit was being checked, to start once the check has passed
   *  and the old history is back (hostCompute.ts). */
  afterCheck: ComputeAsk | undefined = undefined;

  constructor(private readonly post: (message: HostMessage) => void) {}

  /** Answers the pending edit (ok when `error` is null) and forgets it. */
  answer(error: ErrorInfo | null): void {
    const p = this.edit;
    if (!p) return;
    this.edit = null;
    if (error === null) this.post({ type: "reply", id: p.id, ok: true, value: null });
    else this.post({ type: "reply", id: p.id, ok: false, error });
  }

  /**
   * A computation asked (not a restore) while `running` checks the pending edit's later actions:
   * whether it was held here. The check's job runs on (a compute-ahead request would otherwise
   * replace it and the edit's reply would never come); a request for more time extends it (the
   * absolute time it asks for is `target`).
   */
  hold(running: ComputeStatus | null, target: number | null, ask: ComputeAsk, restore: boolean): boolean {
    if (!this.edit || !running || restore) return false;
    if (target !== null && ask.until?.events === undefined && running.targetTime !== null)
      running.targetTime = Math.max(running.targetTime, target);
    // Another kind (until idle, a count of events) runs once the check has passed: it was
    // dropped without a word (audit of session 15).
    else this.afterCheck = ask;
    return true;
  }

  /** The check has passed: answers the edit ok; the computation asked meanwhile (undefined: none). */
  passed(): ComputeAsk | undefined {
    this.answer(null);
    const asked = this.afterCheck;
    this.afterCheck = undefined;
    return asked;
  }

  /**
   * The take-back's reply for an error met while checking: a later action the edit made invalid
   * (or a Zeno state before the old horizon), the edit refused as a synchronous apply would have
   * refused it. `actions`: the timeline's current action list (the engine's indices refer to it).
   */
  refusal(e: unknown, actions: readonly Action[]): ErrorInfo {
    const p = this.edit!;
    const info = beforeEdit(errorInfo(e), p, actions);
    const later = info.path?.startsWith("actions[") === true;
    return { message: later ? `${info.message}${p.suffix}` : info.message, path: info.path };
  }
}

/**
 * A refusal of a later action, named by its index in the action list before the edit (as a
 * synchronous apply names it, and as the editor explains it): the engine names it by its index in
 * the current list (`actions`), which holds the edit. An edit of its own leaves the other actions
 * the same objects in both lists; a merged one (host.ts mergeInto) puts copies in place, which are
 * matched by content, the k-th copy of an action to its k-th occurrence before the edit.
 */
export function beforeEdit(info: ErrorInfo, p: PendingEdit, actions: readonly Action[]): ErrorInfo {
  const m = info.path === null ? null : /^actions\[(\d+)\]/.exec(info.path);
  if (m === null || !("actions" in p.undo)) return info;
  const i = Number(m[1]);
  const j = sameIndex(p.undo.actions, actions, i);
  if (j < 0) return info;
  const was = m[0];
  const now = `actions[${j}]`;
  return { message: info.message.replace(was, now), path: (info.path as string).replace(was, now) };
}

/** The index in `before` of the action at `i` in `now`: the same object, else the same occurrence of
 *  the same content (actionDiff.ts actionKey); -1 when there is none. */
function sameIndex(before: readonly Action[], now: readonly Action[], i: number): number {
  const a = now[i] as Action;
  const same = before.indexOf(a);
  if (same >= 0) return same;
  const key = actionKey(a);
  let k = 0;
  for (let n = 0; n < i; n++) if (actionKey(now[n] as Action) === key) k++;
  for (let n = 0; n < before.length; n++) if (actionKey(before[n] as Action) === key && k-- === 0) return n;
  return -1;
}
