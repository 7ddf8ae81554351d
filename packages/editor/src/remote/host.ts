/**
 * TimelineHost: owns the editor's Timeline (in the Web Worker) and answers the client's requests
 * (protocol.ts). Long computations run in slices of a few milliseconds (hostCompute.ts), so frame,
 * scrub and edit requests are answered between slices and Cancel takes effect at once.
 * The host never throws: every request gets a reply, failed edits reply with the engine's message and
 * leave the timeline as it was, and a computation the engine refuses to continue (a Zeno state) ends
 * with the engine's message in `info.stopped`, the history computed so far kept. An edit in the past,
 * or a rewrite of the scene, is answered once its later actions are checked (pendingEdit.ts).
 */
import { checkAction } from "@chapgame/engine";
import { changesNothing, mergedEdit } from "../doc/mergeEdit";
import type { Action, PathPiece, SceneFile } from "../engineTypes";
import { inApplyingOrder } from "./actionIndices";
import { errorInfo } from "./errors";
import { findEventDetail, stepEventDetail } from "./eventDetail";
import { eventPage, eventTicks } from "./eventQueries";
import { FrameReader } from "./frameReader";
import { HostCompute, type HostEnv } from "./hostCompute";
import { type PathLine, pathLine } from "./pathLine";
import { DEFERRED } from "./pendingEdit";
import { type RequestMessage, restoreTarget, UNDONE_DURING_CHECK } from "./protocol";
import { EXACT_MAX_BODIES, EXACT_MAX_EVENTS, exactSeries } from "./series";
import type { TimelineFactory } from "./timelineLike";
import { markValidity } from "./validity";

export type { HostEnv } from "./hostCompute";

export class TimelineHost extends HostCompute {
  /** Reads frames: the bodies as arrays, without an object per body (frameReader.ts). */
  private readonly frames = new FrameReader();
  /** Ids of the last frame sent (frames with the same ids are sent with `ids: null`). */
  private sentIds: string[] | null = null;
  /** Body index by id for `indexIds` (rebuilt when the ids change). */
  private index = new Map<string, number>();
  private indexIds: string[] | null = null;

  constructor(
    private readonly factory: TimelineFactory,
    env: HostEnv,
    initial: SceneFile,
  ) {
    super(env, factory(inApplyingOrder(initial)));
  }

  handle(message: RequestMessage): void {
    try {
      const value = this.run(message);
      if (value === DEFERRED) return;
      if (value && typeof value === "object" && "data" in value && value.data instanceof Float64Array) {
        this.env.post({ type: "reply", id: message.id, ok: true, value }, [value.data.buffer]);
      } else this.env.post({ type: "reply", id: message.id, ok: true, value });
    } catch (e) {
      this.env.post({ type: "reply", id: message.id, ok: false, error: errorInfo(e) });
    }
  }

  private run(r: RequestMessage): unknown {
    switch (r.op) {
      case "load": {
        // Where the user's history reached, read before the load replaces it (a second undo while
        // the first one's history is recomputed must not cut it to the part recomputed so far).
        const oldEnd = Math.max(this.tl.horizon, restoreTarget(this.job));
        const keep = r.keepTo === undefined ? null : Math.max(r.keepTo, oldEnd);
        // in applying order: the engine's `actions[i]` then names the action of the scene shown
        const tl = this.factory(inApplyingOrder(r.scene));
        const stoppedBefore = this.stoppedNow();
        this.pending.answer({
          message: "the scene was replaced before the edit's later actions were checked",
          path: null,
        });
        this.pending.afterCheck = undefined; // asked for the scene this load replaces
        const previous = this.tl;
        this.job = null;
        this.tl = tl;
        this.series.clear();
        this.changed(true);
        if (keep !== null && keep > tl.horizon) this.restoreTo(keep);
        // A rewrite of the scene (a removed action) is answered once its actions are checked up to
        // the old history's end; a refused one gives the previous timeline back as it was.
        // Checked only up to where the old history reached: an action beyond it was never checked
        // before, and a refusal there would be blamed on this change.
        const checkTo = Math.min(keep === null ? 0 : oldEnd, tl.actions.at(-1)?.time ?? 0);
        if (r.check === true && tl.horizon < checkTo) {
          this.pending.edit = {
            id: r.id,
            undo: { timeline: previous },
            stoppedBefore,
            checkTo,
            horizon: oldEnd,
            suffix: "",
          };
          return DEFERRED;
        }
        return null;
      }
      case "apply":
        return this.applyAll(r.actions, r.id, r.merge === true);
      case "meta":
        this.setMeta(r.meta);
        return null;
      case "compute":
        this.startJob(
          r.from === undefined ? { until: r.until } : { until: r.until, from: r.from },
          r.restore === true,
        );
        return null;
      case "cancel":
        // Cancelling the check of an edit's later actions takes the edit back (it is not known
        // valid) and brings the old history back in slices (Cancel again stops that).
        if (this.pending.edit) {
          this.takeBack(
            "Cancelled: the change was taken back (the actions after it were still being checked).",
            null,
          );
          return null;
        }
        this.job = null;
        this.changed(false);
        return null;
      case "takeBack": {
        // An Undo pressed during the check: the change goes, nothing else (no pending change: the
        // Undo will undo what was answered, and the computation running is left alone).
        if (!this.pending.edit) return null;
        const scene = this.sceneOf(this.tl);
        this.takeBack(UNDONE_DURING_CHECK, null);
        return scene;
      }
      case "frame": {
        const h = this.tl.horizon;
        const t = Math.min(Math.max(r.t, 0), h);
        const f = this.frames.frame(this.tl, t, this.revision, this.sentIds);
        const w = r.window ?? 0;
        if (w > 0 && f.ids.length > 0) {
          const events = this.tl.eventsBetween(Math.max(0, t - w), Math.min(h, t + w));
          markValidity(f.data, this.indexOf(f.ids), events, t, w, h);
        }
        const unchanged = f.ids === this.sentIds;
        this.sentIds = f.ids;
        return unchanged ? { ...f, ids: null } : f;
      }
      case "nextEvent":
        return this.tl.nextEventTime(r.t);
      case "prevEvent":
        return this.tl.prevEventTime(r.t);
      case "events":
        return eventPage(this.tl, r.t, r.before, r.after, r.body);
      case "ticks":
        return eventTicks(this.tl, r.n, r.lo, r.hi);
      case "eventDetail":
        return findEventDetail(this.tl, r.ref);
      case "eventStep":
        return stepEventDetail(this.tl, r.ref, r.step);
      case "path":
        return this.pathOf(r.body, r.maxPoints);
      case "series": {
        const tl = this.tl;
        const small =
          tl.horizon > 0 &&
          tl.eventCount <= EXACT_MAX_EVENTS &&
          tl.stateAt(tl.horizon).bodies.length <= EXACT_MAX_BODIES;
        return small ? exactSeries(tl, r.n) : this.series.points(r.n);
      }
    }
  }

  /** Body id's path (pathLine.ts), or null when the history has no body of that id (the engine's
   *  RangeError: not added yet, or a selection the worker's scene does not hold). */
  private pathOf(id: string, maxPoints: number): PathLine | null {
    let pieces: PathPiece[];
    try {
      pieces = this.tl.path(id);
    } catch (e) {
      if (e instanceof RangeError) return null;
      throw e;
    }
    return pathLine(pieces, maxPoints);
  }

  private indexOf(ids: string[]): Map<string, number> {
    if (ids !== this.indexIds) {
      this.index = new Map(ids.map((id, i) => [id, i]));
      this.indexIds = ids;
    }
    return this.index;
  }

  /**
   * Applies an edit. An edit in the past recomputes only up to its own time (checkLater: false) and
   * the rest in slices, with progress and Cancel: an edit before a later action at t = 100 of a
   * 20,000-disc scene blocked the worker for 3.5 s while the engine checked the later actions. The
   * reply then waits until the recomputation has passed them (PendingEdit). With `merge`, an edit
   * that merges into the action before it (doc/mergeEdit.ts) takes that action's place (mergeInto),
   * or, when the merged action changes nothing, that action goes.
   */
  private applyAll(actions: Action[], id: number, merge = false): null | typeof DEFERRED {
    if (this.pending.edit) throw new Error("an edit is still being checked: wait for it");
    if (actions.length === 0) return null; // nothing changes (Math.min of no times is Infinity)
    const before = this.tl.actions.slice();
    // Where the user's history reaches: past the horizon while an earlier edit's history is still
    // being brought back (a second quick edit must not cut it to the part recomputed so far).
    const horizon = Math.max(this.tl.horizon, restoreTarget(this.job));
    // A refused edit changes nothing: the computation it met runs on (dropped without an info, it
    // left the client showing it computing forever: editorUndoSequences, seed 704378602).
    const running = this.job;
    this.job = null;
    let changed = false;
    try {
      for (const a of actions) {
        const merged = merge ? mergedEdit(this.tl.actions, a) : null;
        if (merged === null) this.tl.apply(a, { keepHorizon: false, checkLater: false });
        else {
          checkAction(a, "action"); // a refused field changes nothing, as apply's check does
          changed = true;
          this.mergeInto(merged.index, merged.action, a);
        }
        changed = true;
      }
    } catch (e) {
      if (changed) {
        // Undo the part that was applied: rebuild the old list and recompute the old horizon.
        this.series.cut(Math.min(...actions.map((a) => a.time)));
        this.tl.setActions(before);
        this.changed(true);
        this.restoreTo(horizon);
      } else this.job = running;
      throw e;
    }
    this.series.cut(Math.min(...actions.map((a) => a.time)));
    this.changed(true);
    const last = this.tl.actions.at(-1)?.time ?? 0;
    const checkTo = Math.min(horizon, last);
    if (this.tl.horizon < checkTo) {
      this.pending.edit = {
        id,
        undo: { actions: before },
        checkTo,
        horizon,
        suffix: " (once this action is in place)",
      };
      this.restoreTo(horizon);
      return DEFERRED;
    }
    if (this.tl.horizon < horizon) this.restoreTo(horizon);
    return null;
  }

  /**
   * An edit that merges into actions[index] (doc/mergeEdit.ts): that action is taken out, which
   * brings the history back to the keyframe before its time (setActions on this compute: false
   * timeline computes nothing), the history is computed up to that instant again (its other actions
   * applied: the action merged into is the instant's last), and the merged action is applied there
   * and checked as any edit, unless it changes nothing (changesNothing), when it is left out. The
   * history from the keyframe before the instant up to it is computed once, here, as for an edit
   * of its own in the past, and the reply waits only for a check of later actions, as its does (applying the edit and then replacing the
   * two with setActions cost the same computation, in slices, with the reply waiting for them, and
   * could not tell a merged action that changes nothing); at the horizon the engine has no point to
   * restart from between the instant's actions, so that one computation stays where an edit of its
   * own computes nothing. A refused merged action is refused as the edit `next` on its own would
   * be: the same final place, but the engine names the first field that changed, which may be the
   * earlier edit's, so the edit is applied after the action again for its message. The caller takes
   * the list back on an error.
   */
  private mergeInto(index: number, action: Action, next: Action): void {
    const list = this.tl.actions.slice();
    const [earlier] = list.splice(index, 1);
    this.tl.setActions(list);
    this.tl.prolongTo(action.time);
    if (changesNothing(action, this.tl.stateAt(action.time))) return;
    try {
      this.tl.apply(action, { keepHorizon: false, checkLater: false });
    } catch (e) {
      this.tl.apply(earlier as Action, { keepHorizon: false, checkLater: false });
      this.tl.apply(next, { keepHorizon: false, checkLater: false });
      throw e;
    }
  }
}
