/**
 * TimelineClient: the main thread's handle on the Timeline that lives in the worker (host.ts).
 * - `getSnapshot()` / `subscribe()` expose the latest TimelineInfo (same object until it changes),
 *   for React's useSyncExternalStore.
 * - Requests return promises; failed edits reject with EditError (engine message + path).
 * - Frames: `wantFrame(t)` keeps at most one frame request in flight and always converges on the
 *   last wanted time (latest wins), so a 60 Hz canvas never queues work in the worker.
 */
import { drawStats } from "../canvas/drawStats";
import type { Action, LogEvent, SceneFile, Until } from "../engineTypes";
import { EditError } from "./errors";
import type { PathLine } from "./pathLine";
import type {
  EntryDetail,
  EventPage,
  EventRef,
  EventStep,
  Frame,
  HostMessage,
  Port,
  Request,
  RequestMessage,
  SeriesPoint,
  TimelineInfo,
} from "./protocol";

const EMPTY_DOC: SceneFile = { format: "chapgame", version: 1, g: 9.81, gravity: [0, 0], actions: [] };

export const EMPTY_INFO: TimelineInfo = {
  revision: -1,
  horizon: 0,
  eventCount: 0,
  counts: { bodyBody: 0, bodyLine: 0, bodyPoint: 0, stop: 0, action: 0 },
  lastEventTime: null,
  idle: false,
  doc: EMPTY_DOC,
  docRevision: -1,
  computing: null,
  stopped: null,
  stoppedPath: null,
  historyBytes: 0,
};

export class TimelineClient {
  private info: TimelineInfo = EMPTY_INFO;
  private nextId = 1;
  /** When the host's last message arrived (performance.now()). */
  private lastHeard = Number.NEGATIVE_INFINITY;
  private readonly pending = new Map<
    number,
    { resolve: (v: unknown) => void; reject: (e: Error) => void; sent: number }
  >();
  private readonly listeners = new Set<() => void>();
  private readonly frameListeners = new Set<(f: Frame) => void>();
  private frameInFlight = false;
  private wantedT: number | null = null;
  private wantedWindow = 0;
  latestFrame: Frame | null = null;
  private frameIds: string[] = [];
  /** The time the latest frame was asked for (the host clamps it to [0, horizon]). */
  private latestAsked = Number.NaN;
  /** The motion-law window the latest frame was asked with. */
  private latestWindow = 0;

  constructor(private port: Port) {
    port.onmessage = (e) => this.receive(e.data as HostMessage);
  }

  /**
   * Switches to a new host (after the old worker stopped answering): pending requests reject, the
   * frame feed restarts. The caller loads the scene into the new host.
   */
  replacePort(port: Port): void {
    this.port.onmessage = null;
    this.port = port;
    port.onmessage = (e) => this.receive(e.data as HostMessage);
    for (const p of this.pending.values()) p.reject(new Error("engine restarted"));
    this.pending.clear();
    this.frameInFlight = false;
    this.latestAsked = Number.NaN;
  }

  /**
   * Milliseconds the host has been silent while a request waits: since the oldest unanswered
   * request was sent or the host's last message, whichever is later (0 when none waits). A host
   * that reports progress is not stalled, also while a request waits for its computation (an edit
   * in the past is answered once its later actions are checked, in slices).
   */
  stalledFor(now: number = performance.now()): number {
    if (this.pending.size === 0) return 0;
    let oldest = now;
    for (const p of this.pending.values()) oldest = Math.min(oldest, p.sent);
    return now - Math.max(oldest, this.lastHeard);
  }

  /** Requests sent and not answered yet. */
  get waiting(): number {
    return this.pending.size;
  }

  getSnapshot = (): TimelineInfo => this.info;

  subscribe = (listener: () => void): (() => void) => {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  };

  onFrame(listener: (f: Frame) => void): () => void {
    this.frameListeners.add(listener);
    return () => this.frameListeners.delete(listener);
  }

  private receive(m: HostMessage): void {
    this.lastHeard = performance.now();
    if (m.type === "info") {
      const doc = m.info.doc ?? this.info.doc;
      this.info = { ...m.info, doc };
      for (const l of this.listeners) l();
      return;
    }
    const p = this.pending.get(m.id);
    if (!p) return;
    this.pending.delete(m.id);
    if (m.ok) p.resolve(m.value);
    else p.reject(new EditError(m.error));
  }

  private request<T>(r: Request): Promise<T> {
    const id = this.nextId++;
    const msg: RequestMessage = { ...r, id };
    return new Promise<T>((resolve, reject) => {
      this.pending.set(id, { resolve: resolve as (v: unknown) => void, reject, sent: performance.now() });
      this.port.postMessage(msg);
    });
  }

  /** Replaces the scene; with `keepTo`, the host recomputes the history the user had, and with
   *  `check` answers once the scene's actions are checked (protocol.ts). */
  load(scene: SceneFile, keepTo?: number, check = false): Promise<void> {
    if (keepTo === undefined) return this.request({ op: "load", scene });
    return this.request(check ? { op: "load", scene, keepTo, check } : { op: "load", scene, keepTo });
  }
  /** Applies edits; `merge`: each merges into the action of its object right before it at its time (protocol.ts). */
  apply(actions: Action[], merge = false): Promise<void> {
    return this.request(merge ? { op: "apply", actions, merge } : { op: "apply", actions });
  }
  /**
   * Computes further from the horizon; `restore`: it brings back history the user had; `from`: the
   * time limit counts from that time instead (protocol.ts ComputeAsk).
   */
  compute(until: Until | null, restore = false, from?: number): Promise<void> {
    if (from === undefined) return this.request({ op: "compute", until, restore });
    return this.request({ op: "compute", until, restore, from });
  }
  /** Replaces the scene's meta (null: none) and nothing else: nothing is recomputed (protocol.ts `meta`). */
  setMeta(meta: Record<string, unknown> | null): Promise<void> {
    return this.request({ op: "meta", meta });
  }
  cancel(): Promise<void> {
    return this.request({ op: "cancel" });
  }
  /**
   * Takes back the change whose later actions are being checked (an Undo during the check): the
   * scene that held it, or null when no change was being checked (protocol.ts `takeBack`).
   */
  takeBack(): Promise<SceneFile | null> {
    return this.request({ op: "takeBack" });
  }
  /**
   * The frame at t, with motion-law intervals reaching up to `window` seconds around t (protocol.ts).
   * Only this client may ask for frames: the host leaves out ids it already sent.
   */
  async frame(t: number, window = 0): Promise<Frame> {
    const f = await this.request<Frame & { ids: string[] | null }>({ op: "frame", t, window });
    if (f.ids === null) f.ids = this.frameIds;
    this.frameIds = f.ids;
    return f;
  }
  nextEvent(t: number): Promise<number | null> {
    return this.request({ op: "nextEvent", t });
  }
  prevEvent(t: number): Promise<number | null> {
    return this.request({ op: "prevEvent", t });
  }
  events(t: number, before: number, after: number, body: string | null): Promise<EventPage> {
    return this.request({ op: "events", t, before, after, body });
  }
  /** The first event of each of n bins of [lo, hi] (by default the whole history [0, horizon]). */
  ticks(n: number, lo?: number, hi?: number): Promise<number[]> {
    return this.request({
      op: "ticks",
      n,
      ...(lo === undefined ? {} : { lo }),
      ...(hi === undefined ? {} : { hi }),
    });
  }
  /** The detail of the log entry `ref` names (before/after states of its bodies), or null when the
   *  current history holds no such entry (protocol.ts `eventDetail`). */
  eventDetail(ref: EventRef): Promise<EntryDetail | null> {
    return this.request({ op: "eventDetail", ref });
  }
  /** The entry logged just before (−1) or after (+1) the one `ref` names, with its detail and a ref
   *  naming it; null at an end of the log or when no entry is named (protocol.ts `eventStep`). */
  eventStep(ref: EventRef, step: 1 | -1): Promise<EventStep | null> {
    return this.request({ op: "eventStep", ref, step });
  }
  /** Body `id`'s whole computed path as a polyline (protocol.ts `path`), or null for no such body. */
  path(id: string, maxPoints: number): Promise<PathLine | null> {
    return this.request({ op: "path", body: id, maxPoints });
  }
  series(n: number): Promise<SeriesPoint[]> {
    return this.request({ op: "series", n });
  }

  /**
   * True when the latest frame shows time t at the current revision (with motion-law intervals of at
   * least `window` seconds).
   */
  hasFrame(t: number, window = 0): boolean {
    const f = this.latestFrame;
    return (
      f !== null && this.latestAsked === t && this.latestWindow >= window && f.revision === this.info.revision
    );
  }

  /** Asks for the frame at t unless it is already shown or on its way (latest wins). */
  wantFrame(t: number, window = 0): void {
    this.wantedT = t;
    this.wantedWindow = window;
    if (this.frameInFlight || this.hasFrame(t, window)) return;
    this.frameInFlight = true;
    const asked = t;
    const started = performance.now();
    this.frame(asked, window).then(
      (f) => {
        const latency = performance.now() - started;
        drawStats.frames++;
        drawStats.frameLatencyMs += latency;
        if (latency > drawStats.maxFrameLatencyMs) drawStats.maxFrameLatencyMs = latency;
        this.frameInFlight = false;
        this.latestFrame = f;
        this.latestAsked = asked;
        this.latestWindow = window;
        for (const l of this.frameListeners) l(f);
        const t = this.wantedT;
        if (t !== null && !this.hasFrame(t, this.wantedWindow)) this.wantFrame(t, this.wantedWindow);
      },
      () => {
        this.frameInFlight = false;
      },
    );
  }
}

export type { LogEvent };
