/**
 * HostCompute: the base of TimelineHost (host.ts) that owns the Timeline and computes it. Long
 * computations run in slices of a few milliseconds (Timeline.prolongSlice), rounds of ROUND_MS, so
 * frame, scrub and edit requests are answered between rounds and Cancel takes effect at once. Every
 * change of the timeline posts `info` (at most every INFO_EVERY_MS while computing; the revision
 * moves only then, so frames and info always agree). A computation the engine refuses to continue
 * (a Zeno state, a later action refused) ends with the engine's message in `info.stopped` and its
 * path in `info.stoppedPath`, the history computed so far kept; so does one whose history grows
 * past HISTORY_MAX_BYTES. While a change's later actions are checked (pendingEdit.ts) its restore
 * job runs on: a refusal takes the change back (takeBack; a load taken back brings back the stop
 * its timeline had), and once the history passes the check the change is answered; a computation
 * asked meanwhile starts once the old history is back (afterRestore). How a request becomes a job
 * (or leaves the running one alone) and the slices' budget: computeJob.ts; the limits in time and
 * memory: computeLimits.ts; the meta kept per timeline: timelineMeta.ts.
 */
import type { SceneFile, Until } from "../engineTypes";
import { type Job, nextBudget, planJob, targetOf } from "./computeJob";
import { CAP_CHECK_MS, HISTORY_MAX_BYTES, INFO_EVERY_MS, RECORD_EVERY_MS, ROUND_MS } from "./computeLimits";
import { errorInfo } from "./errors";
import { lastEventTime } from "./eventQueries";
import { PendingEdits } from "./pendingEdit";
import type { ComputeAsk, ErrorInfo, HostMessage, TimelineInfo } from "./protocol";
import { SeriesRecorder } from "./series";
import type { TimelineLike } from "./timelineLike";
import { TimelineMetas } from "./timelineMeta";

export { HISTORY_MAX_BYTES } from "./computeLimits";

export interface HostEnv {
  post(message: HostMessage, transfer?: Transferable[]): void;
  /** Runs fn soon, after pending messages were handled (setTimeout 0 or a MessageChannel). */
  schedule(fn: () => void): void;
  now(): number;
}

export class HostCompute {
  protected revision = 0;
  private docRevision = 0;
  /** The meta set on each timeline since it was made (timelineMeta.ts). */
  private readonly metas = new TimelineMetas();
  private sentDocRevision = -1;
  private idle = false;
  private stopped: string | null = null;
  /** The engine's path of the refusal in `stopped` (an action refused when the history reached it), or null. */
  private stoppedPath: string | null = null;
  protected job: Job | null = null;
  protected readonly pending: PendingEdits;
  private scheduled = false;
  protected readonly series = new SeriesRecorder();
  private lastRecord = Number.NEGATIVE_INFINITY;
  private lastInfo = Number.NEGATIVE_INFINITY;
  /** When the history's size was last compared with HISTORY_MAX_BYTES. */
  private capChecked = Number.NEGATIVE_INFINITY;

  /** Whether the history is past HISTORY_MAX_BYTES (read at `now`). */
  private overCap(now: number): boolean {
    this.capChecked = now;
    return this.tl.historyBytes() > HISTORY_MAX_BYTES;
  }
  /** A computation asked during a check that passed before its restore job had brought the old
   *  history back: it starts when that job ends, or the job that replaced it (not after a Cancel,
   *  an edit or a load, which drop it). */
  private afterRestore: { job: Job; ask: ComputeAsk } | null = null;

  constructor(
    protected readonly env: HostEnv,
    protected tl: TimelineLike,
  ) {
    this.pending = new PendingEdits((message) => this.env.post(message));
  }

  /**
   * Takes the pending change back (its later actions were refused, or their check was cancelled):
   * the old action list (the timeline computes lazily: setActions keeps the history before the
   * first changed action and goes back to its last keyframe before it, or to 0; a change after the
   * horizon keeps all of it) or the timeline before the load, then the old history recomputed in
   * slices up to the horizon it had.
   */
  protected takeBack(message: string, path: string | null): void {
    const p = this.pending.edit!;
    this.job = null;
    this.pending.afterCheck = undefined; // asked for the scene with the change: it is not there any more
    if ("actions" in p.undo) this.tl.setActions(p.undo.actions);
    else {
      this.tl = p.undo.timeline;
      this.series.clear();
    }
    this.changed(true);
    const stopped = "timeline" in p.undo ? (p.stoppedBefore ?? null) : null;
    if (stopped !== null) this.setStopped(stopped);
    if (this.tl.horizon < p.horizon) this.restoreTo(p.horizon);
    // Answered last: the info that takes the change back must reach the client first (the next
    // queued change reads the scene from it).
    this.pending.answer({ message, path });
  }

  /** Why the last computation stopped (message and path), or null. */
  protected stoppedNow(): ErrorInfo | null {
    return this.stopped === null ? null : { message: this.stopped, path: this.stoppedPath };
  }

  /** Says again why the timeline's computation stopped (a take-back gave back a stopped timeline). */
  private setStopped(s: ErrorInfo): void {
    this.stopped = s.message;
    this.stoppedPath = s.path;
    this.changed(false);
  }

  /** Starts a restore job up to the absolute time `end`, exactly (h + (end - h) may round below end). */
  protected restoreTo(end: number): void {
    this.startJob({ until: { time: end - this.tl.horizon } }, true);
    if (this.job) this.job.targetTime = end;
  }

  protected startJob(ask: ComputeAsk, restore = false): void {
    this.capChecked = Number.NEGATIVE_INFINITY; // a new job compares the history's size at once
    const h = this.tl.horizon;
    const running = this.job;
    // While an edit's later actions are being checked, its job runs on (PendingEdits.hold).
    if (this.pending.hold(running, targetOf(ask, h), ask, restore)) {
      this.changed(false);
      return;
    }
    // A time reached already, or less than a running restore brings back (the editor's "compute
    // ahead" after an edit): the running computation goes on (computeJob.ts).
    const plan = planJob(ask, restore, running, h);
    if (plan === "reached") return;
    if (plan === "covered") {
      this.changed(false);
      return;
    }
    const after = this.afterRestore;
    this.job = plan;
    // A computation asked during a check waits for the job that took the restore's place.
    if (after !== null && after.job === running) after.job = this.job;
    this.idle = false;
    this.stopped = null;
    this.stoppedPath = null;
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
    // historyBytes walks the keyframes (a quarter of a millisecond near the cap): read it at most
    // every CAP_CHECK_MS, not every round
    if (!job.restore && start - this.capChecked >= CAP_CHECK_MS && this.overCap(start)) {
      const mib = Math.round(this.tl.historyBytes() / 2 ** 20);
      this.stopped = `the history holds ${mib} MiB (${this.tl.eventCount} entries), more than the ${HISTORY_MAX_BYTES / 2 ** 20} MiB the editor keeps: computing further could run the browser tab out of memory`;
      this.job = null;
      this.changed(false);
      return;
    }
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
        if (this.pending.edit) {
          // A later action the edit made invalid (or a Zeno state before the old horizon): the
          // edit is refused, as a synchronous apply would have refused it.
          const refusal = this.pending.refusal(e, this.tl.actions);
          this.takeBack(refusal.message, refusal.path);
          return;
        }
        // The engine refuses to go on (a Zeno state): the history up to the horizon stands.
        const refusal = errorInfo(e);
        this.stopped = refusal.message;
        this.stoppedPath = refusal.path;
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
      const p = this.pending.edit;
      if (p && (res.done || this.tl.horizon >= p.checkTo)) {
        this.changed(false);
        const asked = this.pending.passed();
        if (asked !== undefined) {
          // The user's history comes back first: a count of events asked meanwhile counts from
          // its end, not from the edit's check (which would leave the rest of it uncomputed).
          if (job.restore && job.targetTime !== null && this.tl.horizon < job.targetTime)
            this.afterRestore = { job, ask: asked };
          else {
            this.startJob(asked);
            return;
          }
        }
      }
      const took = this.env.now() - t0;
      job.events += res.events;
      job.budget = nextBudget(job.budget, took);
      if (res.done) {
        const timeLeft = job.targetTime !== null && this.tl.horizon < job.targetTime;
        const eventsLeft = job.targetEvents !== null && job.events < job.targetEvents;
        const unlimited = job.targetTime === null && job.targetEvents === null;
        this.idle = unlimited || timeLeft || eventsLeft;
        this.job = null;
      }
    }
    const next = this.afterRestore;
    if (next !== null && next.job === job && this.job === null) {
      this.afterRestore = null;
      if (this.stopped === null) {
        this.startJob(next.ask);
        return;
      }
    }
    if (!this.job || this.env.now() - this.lastInfo >= INFO_EVERY_MS) this.changed(false);
    if (this.job) this.kick();
  }

  /** The scene of timeline `tl`, with the meta set on it since (timelineMeta.ts). */
  protected sceneOf(tl: TimelineLike): SceneFile {
    return this.metas.sceneOf(tl);
  }

  /** Sets the current scene's meta (op `meta`): nothing is recomputed; the scene is sent again. */
  protected setMeta(meta: Record<string, unknown> | null): void {
    this.metas.set(this.tl, meta);
    this.docRevision++;
    this.env.post({ type: "info", info: this.info() });
  }

  protected changed(docChanged: boolean): void {
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
      this.stoppedPath = null;
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
      doc: sendDoc ? this.sceneOf(tl) : null,
      docRevision: this.docRevision,
      computing: this.job ? { ...this.job } : null,
      stopped: this.stopped,
      stoppedPath: this.stoppedPath,
      historyBytes: tl.historyBytes(),
    };
  }
}
