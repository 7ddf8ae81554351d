/** Public data types of the Timeline (see docs/architecture.md). */
import type { ActionType, Vec2 } from "../scene/types.js";
import type { BodyState, EventKind, LineState, PointState } from "../sim/types.js";

/** Kind of a logged event: a collision, a stop, or an action. */
export type LogKind = EventKind | "action";

/**
 * One logged entry: a collision, a friction stop or an action, told apart by `type` (TypeScript
 * narrows on it: `if (e.type === "bodyBody")` gives `ids: [string, string]`, a `point` and a `normal`).
 * For an action: ids = [the action's id] ([] for setGlobal), point/normal/impulse null, and `action` =
 * the action's type (the whole action: Timeline.eventAction(i)). For a stop: point = where the body
 * stopped, normal null, impulse 0. Every member has every field (null where it does not apply), so
 * the fields can be read without narrowing too; the JSON is the same.
 */
export type LogEvent = CollisionLogEvent | StopLogEvent | ActionLogEvent;

/** A collision entry: [body, body] in id order, [body, line] or [body, point]. */
export interface CollisionLogEvent {
  /** Absolute time of the entry. */
  time: number;
  type: "bodyBody" | "bodyLine" | "bodyPoint";
  /** The participants: [body, body] in id order, [body, line], [body, point]. */
  ids: [string, string];
  /** Contact point. */
  point: Vec2;
  /** Unit normal at contact from the first id towards the second. */
  normal: Vec2;
  /** Magnitude of the impulse (Infinity when both masses are infinite; 0 for a graze). */
  impulse: number;
  action?: never;
}

/** A friction stop of one body. */
export interface StopLogEvent {
  time: number;
  type: "stop";
  /** [the body] */
  ids: [string];
  /** Where the body stopped. */
  point: Vec2;
  normal: null;
  /** 0 */
  impulse: number;
  action?: never;
}

/** An action applied at `time` (Timeline.eventAction(i) gives the whole action). */
export interface ActionLogEvent {
  time: number;
  type: "action";
  /** [the action's id], [] for setGlobal (an array, not a tuple type, so that `ids.includes(id)`
   *  type-checks on any entry). */
  ids: string[];
  point: null;
  normal: null;
  impulse: null;
  /** What the action did (addBody, giveVelocity, removeLine, …). */
  action: ActionType;
}

/** One body taking part in a log entry (`EventDetail.bodies`): its exact state just before and
 *  just after the entry, as the engine computed them (not sampled at t ± ε). */
export interface EventBody {
  /** The body's id. */
  id: string;
  /** Its state just before the entry (velocity as it arrived: the motion before the entry evaluated
   *  at its time); null when the body did not exist yet (an addBody entry, or a body added earlier
   *  at the same instant). For an action entry, before and after span the whole group of actions at
   *  that instant: a body removed and added again under the same id there shows the old body before
   *  and the new one after, on both entries. */
  before: BodyState | null;
  /** Its state just after the entry (for a collision or a stop: the new velocity; the position is
   *  unchanged); null when the entry removed it (removeBody). */
  after: BodyState | null;
}

/**
 * A log entry with its participants' states (`Timeline.eventDetail(i)`): the LogEvent's fields plus,
 * for each participating body, its state just before and just after.
 * - bodyBody: both bodies, in the order of `ids`; bodyLine, bodyPoint, stop: the body only. Several
 *   events at one instant (a Newton's cradle) each get their own before/after: an event's "before"
 *   is after the events logged before it at that instant.
 * - action: the body an addBody, giveVelocity, updateBody or removeBody names; "before" is before
 *   that instant's group of actions and "after" after the whole group (several actions at one
 *   instant on the same body show their combined effect: the engine keeps no state in between).
 *   Obstacle actions and setGlobal: no bodies ([]).
 */
export type EventDetail = LogEvent & {
  /** The participating bodies (see above). */
  bodies: EventBody[];
};

/** The exact state of the scene at one time; every list sorted by id. */
export interface SceneState {
  /** The absolute time of this state. */
  time: number;
  /** The friction field at that time. */
  g: number;
  /** The gravity field at that time. */
  gravity: Vec2;
  /** Every disc, sorted by id. */
  bodies: BodyState[];
  /** Every line, ray and segment, sorted by id. */
  lines: LineState[];
  /** Every point obstacle, sorted by id. */
  points: PointState[];
}

/** Entries of the computed history by kind (`Timeline.counts()`; counted also without history). */
export interface TimelineCounts {
  /** Disc–disc collisions. */
  bodyBody: number;
  /** Collisions of a disc with a line, ray or segment. */
  bodyLine: number;
  /** Collisions of a disc with a point. */
  bodyPoint: number;
  /** Discs stopped by friction. */
  stop: number;
  /** Actions applied. */
  action: number;
}

/**
 * Options of `new Timeline(options)` (and, without g and gravity, of `Timeline.fromScene`). Each is
 * checked (SceneError naming it); an unknown key is refused.
 */
export interface TimelineOptions {
  /** Friction field (default 9.81): a disc with friction coefficient mu decelerates at mu·g. 0, or
   *  between FIELD_MIN (1e-30) and MAGNITUDE_MAX (1e30). */
  g?: number | undefined;
  /** Uniform acceleration field (default [0, 0]); each component 0, or between 1e-30 and 1e30 in size. */
  gravity?: Vec2 | undefined;
  /** false = headless: no event log, no keyframes, no time travel (stateAt only from the last
   *  event or action to the horizon). Default true. */
  history?: boolean | undefined;
  /** false = actions given to fromScene/setActions are only scheduled (applied when a prolong passes
   *  their time) and their `until`s are ignored; the caller drives with prolong/prolongSlice.
   *  setActions then leaves the horizon at the keyframe it restarted from (or 0).
   *  Default true. */
  compute?: boolean | undefined;
  /**
   * @internal With `compute: false`: each action's `until` becomes a goal when a prolong,
   * prolongTo or prolongSlice applies the action, and the computation goes on until it is met, as
   * with `compute: true` (for the CLI, which computes a scene's own bound in slices). Default false.
   */
  untils?: boolean | undefined;
}

/** Options of `Timeline.apply`. */
export interface ApplyOptions {
  /**
   * What an action before the horizon recomputes. true (the default): the whole history up to the
   * old horizon, in this call. false: only up to the last action's time (every action is still
   * validated, so a refusal comes from this call as before), and the horizon moves back there; the
   * rest is computed by a later prolong, prolongTo or prolongSlice (a UI's sliced computation with
   * progress and cancel), which gives the same history bit for bit.
   */
  keepHorizon?: boolean | undefined;
  /**
   * With keepHorizon false: whether this call also validates the actions after this one, up to the
   * old horizon. true (the default): it does, recomputing up to the last of them. false: it
   * recomputes only up to this action's own time; the later actions are validated when a prolong,
   * prolongTo or prolongSlice reaches them, and one made invalid is refused there (SceneError
   * naming it as `actions[i]`, its index in `actions`, this action included; the history up to it
   * kept), this action staying applied: the caller takes it back with setActions. For a UI that
   * computes in slices with progress and Cancel (an edit before a later action at t = 100 of a
   * 20,000-disc scene blocked for 3.5 s). Only with keepHorizon: false, and only a timeline made
   * with `compute: false` defers them: with `compute: true` every action is applied at once anyway.
   */
  checkLater?: boolean | undefined;
}

/** What a prolong did. */
export interface ProlongResult {
  /** Collisions and stops computed by this call (actions not counted). */
  events: number;
  /**
   * Why it stopped: "time" = the target time was reached; "events" = `until.events` was reached;
   * "idle" = nothing is left to happen (no event and no action to come; said
   * rather than "time" when both hold).
   */
  reason: "time" | "events" | "idle";
}
