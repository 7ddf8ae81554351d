/**
 * TimelineHost: owns the editor's Timeline (in the Web Worker) and answers the client's requests
 * (protocol.ts). Long computations run in slices of a few milliseconds (Timeline.prolongSlice), so
 * frame, scrub and edit requests are answered between slices and Cancel takes effect at once.
 * The host never throws: every request gets a reply, failed edits reply with the engine's message and
 * leave the timeline as it was, and a computation the engine refuses to continue (a Zeno state) ends
 * with the engine's message in `info.stopped`, the history computed so far kept.
 */
import type { Action, SceneFile, Until } from "../engineTypes";
import { errorInfo } from "./errors";
import { eventPage, eventTicks, lastEventTime } from "./eventQueries";
import { packFrame } from "./packFrame";
import {
  type ComputeStatus,
  type ErrorInfo,
  type HostMessage,
  type RequestMessage,
  restoreTarget,
  type TimelineInfo,
  UNDONE_DURING_CHECK,
} from "./protocol";
import { EXACT_MAX_BODIES, EXACT_MAX_EVENTS, exactSeries, SeriesRecorder } from "./series";
import type { TimelineFactory, TimelineLike } from "./timelineLike";
import { markValidity } from "./validity";

/**
 * Wall-clock milliseconds one round of slices may take before the host yields to messages (a frame
 * or scrub request waits at most about this long while computing).
 */
const ROUND_MS = 8;
/**
 * While computing, the host tells the client about progress at most this often (ms): each `info`
 * re-renders the panels that show counts and the horizon on the main thread, and rounds end 100
 * times a second. The revision moves only when info is sent, so frames and info always agree.
 */
const INFO_EVERY_MS = 50;
/** Wall-clock milliseconds one prolongSlice call should take (the event budget adapts to it). */
const SLICE_MS = 3;
/** While computing, energy/event samples are recorded at most this often (ms of wall-clock time). */
const RECORD_EVERY_MS = 100;

interface Job extends ComputeStatus {
  budget: number;
}

/**
 * An edit in the past, or a rewrite of the scene (a removed action), whose later actions the
 * running restore job is still checking: its reply waits until the history passes `checkTo` (ok)
 * or a later action is refused (the change is taken back, and the reply carries the refusal as a
 * synchronous apply would have).
 */
interface PendingEdit {
  /** The request to answer. */
  id: number;
  /** How to take the change back: the action list before an edit, or the timeline before a load. */
  undo: { actions: Action[] } | { timeline: TimelineLike };
  /** The last action's time, up to the old history's end: the check is done once the horizon passes it. */
  checkTo: number;
  /** The old history's end, recomputed again after a take-back. */
  horizon: number;
  /** Appended to a refusal of a later action (an edit: " (once this action is in place)"). */
  suffix: string;
}

/** run()'s value for a request answered later (an edit whose later actions are being checked). */
const DEFERRED = Symbol("deferred");

export interface HostEnv {
  post(message: HostMessage, transfer?: Transferable[]): void;
  /** Runs fn soon, after pending messages were handled (setTimeout 0 or a MessageChannel). */
  schedule(fn: () => void): void;
  now(): number;
}

export class TimelineHost {
  private tl: TimelineLike;
  private revision = 0;
  private docRevision = 0;
  private sentDocRevision = -1;
  private idle = false;
  private stopped: string | null = null;
  private job: Job | null = null;
  private pending: PendingEdit | null = null;
  /** A computation asked while an edit was being checked, to start once the check has passed. */
  private afterCheck: Until | null | undefined = undefined;
  private scheduled = false;
  private readonly series = new SeriesRecorder();
  private lastRecord = Number.NEGATIVE_INFINITY;
  private lastInfo = Number.NEGATIVE_INFINITY;
  /** Ids of the last frame sent (frames with the same ids are sent with `ids: null`). */
  private sentIds: string[] | null = null;
  /** Body index by id for `indexIds` (rebuilt when the ids change). */
  private index = new Map<string, number>();
  private indexIds: string[] | null = null;

  constructor(
    private readonly factory: TimelineFactory,
    private readonly env: HostEnv,
    initial: SceneFile,
  ) {
    this.tl = factory(initial);
  }

  handle(message: RequestMessage): void {
    try {
      const value = this.run(message);
      if (value === DEFERRED) return;
      if (value instanceof Float64Array) this.env.post({ type: "reply", id: message.id, ok: true, value });
      else if (value && typeof value === "object" && "data" in value && value.data instanceof Float64Array) {
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
        const tl = this.factory(r.scene);
        this.answerPending({
          message: "the scene was replaced before the edit's later actions were checked",
          path: null,
        });
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
          this.pending = { id: r.id, undo: { timeline: previous }, checkTo, horizon: oldEnd, suffix: "" };
          return DEFERRED;
        }
        return null;
      }
      case "apply":
        return this.applyAll(r.actions, r.id);
      case "compute":
        this.startJob(r.until, r.restore === true);
        return null;
      case "cancel":
        // Cancelling the check of an edit's later actions takes the edit back (it is not known
        // valid) and brings the old history back in slices (Cancel again stops that).
        if (this.pending) {
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
        if (!this.pending) return null;
        const scene = this.tl.toScene();
        this.takeBack(UNDONE_DURING_CHECK, null);
        return scene;
      }
      case "frame": {
        const h = this.tl.horizon;
        const t = Math.min(Math.max(r.t, 0), h);
        const f = packFrame(this.tl.stateAt(t), this.revision, this.sentIds);
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
   * reply then waits until the recomputation has passed them (PendingEdit).
   */
  private applyAll(actions: Action[], id: number): null | typeof DEFERRED {
    if (this.pending) throw new Error("an edit is still being checked: wait for it");
    const before = this.tl.actions.slice();
    // Where the user's history reaches: past the horizon while an earlier edit's history is still
    // being brought back (a second quick edit must not cut it to the part recomputed so far).
    const horizon = Math.max(this.tl.horizon, restoreTarget(this.job));
    this.job = null;
    let applied = 0;
    this.series.cut(Math.min(...actions.map((a) => a.time)));
    try {
      for (const a of actions) {
        this.tl.apply(a, { keepHorizon: false, checkLater: false });
        applied++;
      }
    } catch (e) {
      if (applied > 0) {
        // Undo the part that was applied: rebuild the old list and recompute the old horizon.
        this.tl.setActions(before);
        this.changed(true);
        this.restoreTo(horizon);
      }
      throw e;
    }
    this.changed(true);
    const last = this.tl.actions.at(-1)?.time ?? 0;
    const checkTo = Math.min(horizon, last);
    if (this.tl.horizon < checkTo) {
      this.pending = {
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
   * A refusal of a later action, named by its index in the action list before the edit (as a
   * synchronous apply names it, and as the editor explains it): the engine names it by its index in
   * the current list, which holds the edit. Actions are the same objects in both lists.
   */
  private beforeEdit(info: ErrorInfo, p: PendingEdit): ErrorInfo {
    const m = info.path === null ? null : /^actions\[(\d+)\]/.exec(info.path);
    if (m === null || !("actions" in p.undo)) return info;
    const j = p.undo.actions.indexOf(this.tl.actions[Number(m[1])] as Action);
    if (j < 0) return info;
    const was = m[0];
    const now = `actions[${j}]`;
    return { message: info.message.replace(was, now), path: (info.path as string).replace(was, now) };
  }

  /** Answers the pending edit (ok when `error` is null) and forgets it. */
  private answerPending(error: ErrorInfo | null): void {
    const p = this.pending;
    if (!p) return;
    this.pending = null;
    if (error === null) this.env.post({ type: "reply", id: p.id, ok: true, value: null });
    else this.env.post({ type: "reply", id: p.id, ok: false, error });
  }

  /**
   * Takes the pending change back (its later actions were refused, or their check was cancelled):
   * the old action list (the timeline computes lazily: setActions leaves it at its last keyframe
   * before the edit, or at 0) or the timeline before the load, then the old history recomputed in
   * slices.
   */
  private takeBack(message: string, path: string | null): void {
    const p = this.pending!;
    this.job = null;
    this.afterCheck = undefined; // asked for the scene with the change: it is not there any more
    if ("actions" in p.undo) this.tl.setActions(p.undo.actions);
    else {
      this.tl = p.undo.timeline;
      this.series.clear();
    }
    this.changed(true);
    if (this.tl.horizon < p.horizon) this.restoreTo(p.horizon);
    // Answered last: the info that takes the change back must reach the client first (the next
    // queued change reads the scene from it).
    this.answerPending({ message, path });
  }

  /** Starts a restore job up to the absolute time `end`, exactly (h + (end - h) may round below end). */
  private restoreTo(end: number): void {
    this.startJob({ time: end - this.tl.horizon }, true);
    if (this.job) this.job.targetTime = end;
  }

  private startJob(until: Until | null, restore = false): void {
    const h = this.tl.horizon;
    const running = this.job;
    // While an edit's later actions are being checked, its job runs on (a compute-ahead request
    // would otherwise replace it and the edit's reply would never come); a request for more time
    // extends it.
    if (this.pending && running && !restore) {
      if (until?.time !== undefined && until.events === undefined && running.targetTime !== null)
        running.targetTime = Math.max(running.targetTime, h + until.time);
      // Another kind (until idle, a count of events) runs once the check has passed: it was
      // dropped without a word (audit of session 15).
      else this.afterCheck = until;
      this.changed(false);
      return;
    }
    // A request for less than a running restore covers (the editor's "compute ahead" after an edit)
    // leaves it running: it would otherwise cut the recomputation of the user's history short.
    if (
      !restore &&
      running?.restore &&
      running.targetTime !== null &&
      until !== null &&
      until.events === undefined &&
      until.time !== undefined &&
      h + until.time <= running.targetTime
    ) {
      this.changed(false);
      return;
    }
    this.job = {
      restore,
      events: 0,
      targetEvents: until?.events ?? null,
      targetTime: until?.time === undefined ? null : h + until.time,
      startHorizon: h,
      budget: 256,
    };
    this.idle = false;
    this.stopped = null;
    this.changed(false);
    this.kick();
  }

  private kick(): void {
    if (this.scheduled) return;
    this.scheduled = true;
    this.env.schedule(() => {
      this.scheduled = false;
      this.round();
    });
  }

  /** One round of slices: computes for about ROUND_MS, reports, then yields to pending messages. */
  private round(): void {
    const job = this.job;
    if (!job) return;
    const start = this.env.now();
    while (this.job === job && this.env.now() - start < ROUND_MS) {
      const until: Until = {};
      if (job.targetTime !== null) until.time = job.targetTime - this.tl.horizon;
      if (job.targetEvents !== null) until.events = job.targetEvents - job.events;
      if (
        (until.time !== undefined && until.time <= 0) ||
        (until.events !== undefined && until.events <= 0)
      ) {
        this.job = null;
        break;
      }
      const t0 = this.env.now();
      let res: { done: boolean; events: number };
      const before = this.tl.horizon;
      try {
        res = this.tl.prolongSlice(until, job.budget);
      } catch (e) {
        if (this.pending) {
          // A later action the edit made invalid (or a Zeno state before the old horizon): the
          // edit is refused, as a synchronous apply would have refused it.
          const info = this.beforeEdit(errorInfo(e), this.pending);
          const later = info.path?.startsWith("actions[") === true;
          this.takeBack(later ? `${info.message}${this.pending.suffix}` : info.message, info.path);
          return;
        }
        // The engine refuses to go on (a Zeno state): the history up to the horizon stands.
        this.stopped = errorInfo(e).message;
        this.job = null;
        break;
      }
      // A time target reached only up to round-off (h + (T - h) < T): one more slice gets there
      // (T - h is then exact, so h + (T - h) = T). A slice that made no progress ends the job.
      const short =
        res.done &&
        job.targetTime !== null &&
        this.tl.horizon < job.targetTime &&
        job.targetEvents === null &&
        this.tl.horizon > before;
      if (short) res = { ...res, done: false };
      if (this.pending && (res.done || this.tl.horizon >= this.pending.checkTo)) {
        this.changed(false);
        this.answerPending(null);
        const asked = this.afterCheck;
        this.afterCheck = undefined;
        if (asked !== undefined) {
          this.startJob(asked);
          return;
        }
      }
      const took = this.env.now() - t0;
      job.events += res.events;
      job.budget = Math.max(16, Math.min(1 << 20, Math.round(job.budget * (took > 0 ? SLICE_MS / took : 2))));
      if (res.done) {
        const timeLeft = job.targetTime !== null && this.tl.horizon < job.targetTime;
        const eventsLeft = job.targetEvents !== null && job.events < job.targetEvents;
        const unlimited = job.targetTime === null && job.targetEvents === null;
        this.idle = unlimited || timeLeft || eventsLeft;
        this.job = null;
      }
    }
    if (!this.job || this.env.now() - this.lastInfo >= INFO_EVERY_MS) this.changed(false);
    if (this.job) this.kick();
  }

  private changed(docChanged: boolean): void {
    this.revision++;
    const now = this.env.now();
    if (docChanged || this.job === null || now - this.lastRecord >= RECORD_EVERY_MS) {
      this.lastRecord = now;
      this.series.record(this.tl);
    }
    if (docChanged) {
      this.docRevision++;
      this.idle = false;
      this.stopped = null;
    }
    this.lastInfo = now;
    this.env.post({ type: "info", info: this.info() });
  }

  info(): TimelineInfo {
    const tl = this.tl;
    const n = tl.eventCount;
    const sendDoc = this.sentDocRevision !== this.docRevision;
    this.sentDocRevision = this.docRevision;
    return {
      revision: this.revision,
      horizon: tl.horizon,
      eventCount: n,
      counts: tl.counts(),
      lastEventTime: lastEventTime(tl),
      idle: this.idle,
      doc: sendDoc ? tl.toScene() : null,
      docRevision: this.docRevision,
      computing: this.job ? { ...this.job } : null,
      stopped: this.stopped,
      historyBytes: tl.historyBytes(),
    };
  }
}
