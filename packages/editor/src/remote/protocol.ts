/**
 * Messages between the editor's main thread (TimelineClient) and the worker that owns the Timeline
 * (TimelineHost). Every request carries an `id`; the host answers each with exactly one `reply`.
 * The host also pushes `info` (after every change of the timeline) unasked.
 *
 * Bodies in a frame are packed, FRAME_STRIDE numbers per body, in the order of `ids` (sorted by id).
 * Each body also carries the interval [F_FROM, F_UNTIL] around the frame's time over which its motion
 * law (position, velocity and acceleration at the frame's time) holds: no event or action involves it
 * strictly inside. The main thread evaluates positions at other times of that interval itself
 * (canvas/frameAt.ts), so playback draws the exact time of every animation frame without waiting for
 * a round trip to the worker.
 */
import type {
  Action,
  Counts,
  EventDetail,
  LineState,
  LogEvent,
  PointState,
  SceneFile,
  Until,
  Vec2,
} from "../engineTypes";

export const FRAME_STRIDE = 11;
export const F_X = 0;
export const F_Y = 1;
export const F_VX = 2;
export const F_VY = 3;
export const F_AX = 4;
export const F_AY = 5;
export const F_R = 6;
export const F_M = 7;
export const F_MU = 8;
/** Start of the interval over which the body's motion law holds (<= the frame's time). */
export const F_FROM = 9;
/** End of that interval (>= the frame's time). */
export const F_UNTIL = 10;

/** The state of the scene at one time, as the canvas and the tables read it. */
export interface Frame {
  t: number;
  /** The timeline revision this frame was computed at. */
  revision: number;
  g: number;
  gravity: Vec2;
  ids: string[];
  data: Float64Array;
  lines: LineState[];
  points: PointState[];
}

/** What the host computes or was asked to compute. */
export interface ComputeStatus {
  /** Events computed since this computation started. */
  events: number;
  /** Target in events (null: none). */
  targetEvents: number | null;
  /** Target horizon in seconds (null: none). */
  targetTime: number | null;
  startHorizon: number;
  /**
   * True when this computation brings back history the user already had (after an edit in the past,
   * an undo, a redo or a rename): its targetTime is where the user's history reaches, although the
   * horizon is still short of it.
   */
  restore: boolean;
}

/** The time a running restore computation brings the history back to (-Infinity when none runs). */
export function restoreTarget(job: ComputeStatus | null): number {
  return job?.restore && job.targetTime !== null ? job.targetTime : Number.NEGATIVE_INFINITY;
}

export interface TimelineInfo {
  revision: number;
  horizon: number;
  eventCount: number;
  counts: Counts;
  lastEventTime: number | null;
  /** True when the last computation stopped because no event is left. */
  idle: boolean;
  /** The scene as a file; null in a message when unchanged since the last one (docRevision). */
  doc: SceneFile | null;
  /** Changes only when the action list or the globals change (not on prolong). */
  docRevision: number;
  computing: ComputeStatus | null;
  /**
   * Why the last computation stopped before its target, when the engine refused to go on (a Zeno
   * state met while computing); null otherwise. Cleared by the next computation or edit.
   */
  stopped: string | null;
  /**
   * The engine's path of the refusal that stopped the computation (`actions[3]`, `actions[3].x`:
   * an action of the scene refused when the history reached it), null when none or when the stop
   * names no field (a Zeno state, the history's size). With `doc`, it says which action is refused
   * (doc/refusedAction.ts).
   */
  stoppedPath: string | null;
  historyBytes: number;
}

export interface ErrorInfo {
  message: string;
  path: string | null;
}

export interface SeriesPoint {
  t: number;
  energy: number;
  collisions: number;
}

/**
 * A computation asked: up to `until` (null: until idle). Its `time` counts from the horizon, or from
 * the absolute time `from` when given: "10 s past the current time" asked after an edit in the past
 * must not count from the old history, which may be back by the time the request is met (every edit
 * pushed the horizon 10 s further). Reached already (from + time ≤ horizon, no events), it does nothing.
 */
export interface ComputeAsk {
  until: Until | null;
  from?: number;
}

export type Request =
  /**
   * Replaces the scene. `keepTo` keeps the history the user had (an undo, a redo, a rename at the
   * current time): the host then recomputes, as a restore, up to the later of `keepTo` and where
   * the history reached before the load (its horizon, or the target of a restore still running).
   * `check` (a rewrite of the current scene, e.g. a removed action; with keepTo): the reply waits
   * until the actions are checked up to where the old history reached, and a refused scene is
   * taken back, the previous one kept as it was.
   */
  | { op: "load"; scene: SceneFile; keepTo?: number; check?: boolean }
  /**
   * Applies edits at their times. `merge`: an edit of the object the action right before its place
   * edits at the same time (doc/mergeEdit.ts) replaces that action with both merged, rather than
   * adding one of its own.
   */
  | { op: "apply"; actions: Action[]; merge?: boolean }
  /**
   * Replaces the scene's `meta` (free data for tools: the title; null: none) and nothing else: the
   * history does not depend on it, so nothing is recomputed (a title set, or its undo, in a scene of
   * thousands of discs recomputed their whole history). Answered once `info` holds the new scene.
   */
  | { op: "meta"; meta: Record<string, unknown> | null }
  /**
   * `restore`: the computation brings back history the user had (see ComputeStatus.restore).
   * `from`: `until.time` counts from this time, not from the horizon (ComputeAsk).
   */
  | { op: "compute"; until: Until | null; restore?: boolean; from?: number }
  | { op: "cancel" }
  /**
   * Undo of the change whose later actions are being checked (an `apply` or a checked `load` not
   * answered yet): takes it back as Cancel does (its reply: refused, `UNDONE_DURING_CHECK`) and
   * answers with the scene that held it; with no change being checked it does nothing (answers
   * null) and, unlike Cancel, leaves any computation running.
   */
  | { op: "takeBack" }
  /** The frame at t; `window` > 0 asks for motion-law intervals reaching up to window seconds around t. */
  | { op: "frame"; t: number; window: number }
  | { op: "nextEvent"; t: number }
  | { op: "prevEvent"; t: number }
  | { op: "events"; t: number; before: number; after: number; body: string | null }
  /** Event ticks over n bins of [lo, hi] (by default [0, horizon]; eventQueries.ts eventTicks). */
  | { op: "ticks"; n: number; lo?: number; hi?: number }
  | { op: "series"; n: number }
  /** The detail of the log entry `ref` names (eventDetail.ts): an EventDetail, or null when the
   *  current history holds no such entry (an edit recomputed it away). */
  | { op: "eventDetail"; ref: EventRef }
  /** The entry logged just before (step −1) or after (+1) the one `ref` names, with its detail
   *  (eventDetail.ts stepEventDetail): an EventStep, or null at either end of the log or when the
   *  history holds no entry `ref` names. */
  | { op: "eventStep"; ref: EventRef; step: 1 | -1 }
  /** Body `body`'s whole computed path as a polyline of at most maxPoints points (pathLine.ts): a
   *  PathLine, or null when no body of the timeline has that id. */
  | { op: "path"; body: string; maxPoints: number };

export type RequestMessage = Request & { id: number };

/** The refusal a change taken back by `takeBack` (an Undo during its check) is answered with. */
export const UNDONE_DURING_CHECK = "Undone while the actions after it were being checked.";

/**
 * A log entry as an event page carries it: an action entry also says which action it is, by its
 * index in the timeline's action list (the scene's `actions`, in time order) when the page was read.
 */
export type PageEvent = LogEvent & { actionIndex?: number };

/**
 * A log entry named by what it shows (the Event log's rows carry no index, and an index would name
 * another entry once an edit recomputes the history): its time, kind, participants and, for an
 * action entry, the action's type. Entries alike in all of these at one time have the same detail
 * (an action's before/after spans its instant's whole group of actions); `nth` tells them apart
 * where it matters (stepping from entry to entry), and a ref without it names the first.
 */
export interface EventRef {
  time: number;
  type: LogEvent["type"];
  ids: string[];
  /** An action entry's action type; absent for a collision or a stop. */
  action?: NonNullable<LogEvent["action"]>;
  /** How many entries alike (same time, kind, participants, action) come before it in the log;
   *  absent for 0. */
  nth?: number;
}

/** An entry reached by stepping through the log (op `eventStep`): its ref and its detail. */
export interface EventStep {
  ref: EventRef;
  detail: EntryDetail;
}

/** An entry's detail and whether it is the first or the last entry of the log (computed so far). */
export type EntryDetail = EventDetail & { first: boolean; last: boolean };

export interface EventPage {
  /** Index of the first returned event in the log, or -1 when not known (the log is read by time). */
  first: number;
  /** Number of events in the whole log. */
  total: number;
  events: PageEvent[];
}

export type HostMessage =
  | { type: "reply"; id: number; ok: true; value: unknown }
  | { type: "reply"; id: number; ok: false; error: ErrorInfo }
  | { type: "info"; info: TimelineInfo };

/** A two-way message channel: a Worker, or an in-process pair for tests. */
export interface Port {
  postMessage(message: unknown, transfer?: Transferable[]): void;
  onmessage: ((event: { data: unknown }) => void) | null;
}
