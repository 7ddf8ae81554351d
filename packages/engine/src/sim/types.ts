/** Public data types of the World (see docs/architecture.md). */

/** A 2D vector `[x, y]`. */
export type Vec2 = readonly [number, number];

/**
 * Kind of a World event: a disc–disc collision, a disc against a line, ray or segment (its end
 * points included), a disc against a point, or a disc stopped by friction.
 */
export type EventKind = "bodyBody" | "bodyLine" | "bodyPoint" | "stop";

/**
 * A new disc for `World.addBody`, placed at the World's current time. Every number is checked
 * (ChapgameError naming the field, e.g. `r`); a key not listed here is refused (`vX`), except
 * the derived `id`, `ax`, `ay` of a BodyState, so a reported state can be passed back.
 */
export interface BodyInit {
  /** Centre x; finite, at most MAGNITUDE_MAX (1e30) in size. */
  x: number;
  /** Centre y; finite, at most MAGNITUDE_MAX (1e30) in size. */
  y: number;
  /** Radius, between RADIUS_MIN (1e-30) and MAGNITUDE_MAX (1e30). */
  r: number;
  /** Mass: between MASS_MIN (1e-40) and MASS_MAX (1e40), or Infinity (a body collisions cannot move). */
  m: number;
  /**
   * Friction coefficient (default 0): a moving disc decelerates at mu·g, g being the World's
   * friction field, and stops exactly. 0, or between FIELD_MIN (1e-30) and MAGNITUDE_MAX; must be
   * 0 while the gravity field is non-zero.
   */
  mu?: number | undefined;
  /** Velocity x (default 0): 0, or between SPEED_MIN (1e-30) and MAGNITUDE_MAX in size. */
  vx?: number | undefined;
  /** Velocity y (default 0): 0, or between SPEED_MIN (1e-30) and MAGNITUDE_MAX in size. */
  vy?: number | undefined;
}

/**
 * A body's exact current motion, as `World.motion(id)` reports it (a copy): p(t) = (x0, y0) +
 * (t - t0) ((vx, vy) + (t - t0) (ax, ay) / 2) for t0 <= t <= tStop, where (ax, ay) and tStop follow
 * from the velocity, mu and the World's globals.
 */
export interface BodyMotion {
  t0: number;
  x0: number;
  y0: number;
  vx: number;
  vy: number;
  ax: number;
  ay: number;
  tStop: number;
}

/**
 * A body given by an exact motion that started at t0 (at or before the World's time), as
 * `World.motion(id)` reports it: p(t) = (x0, y0) + (t - t0) (v + (t - t0) a / 2), where a (friction
 * or the gravity field) follows from v, mu and the World's globals exactly as for any motion.
 * `motion(id)`'s derived `ax`, `ay` and `tStop` may be passed back; given, each must equal what the
 * World derives (ChapgameError naming it otherwise: they are not settable).
 */
export interface BodyMotionInit {
  /** When the motion started: finite and at most the World's time (ChapgameError naming `t0`). */
  t0: number;
  /** Position x at t0 (finite; not held to MAGNITUDE_MAX, a computed motion may exceed it). */
  x0: number;
  /** Position y at t0 (finite). */
  y0: number;
  /** Velocity x at t0 (finite). */
  vx: number;
  /** Velocity y at t0 (finite). */
  vy: number;
  /** Radius, as in BodyInit. */
  r: number;
  /** Mass, as in BodyInit (1e-40 to 1e40, or Infinity). */
  m: number;
  /** Friction coefficient (default 0), as in BodyInit. */
  mu?: number | undefined;
}

/**
 * Changes for `World.updateBody`, made at the World's current time: a field left out keeps the
 * body's current value (its position and velocity now), and the body's motion restarts from there.
 * Each given field is checked as in BodyInit (ChapgameError naming it); a BodyState's `id`, `ax`,
 * `ay` are accepted and ignored.
 */
export interface BodyPatch {
  /** New centre x (the body must not overlap anything there). */
  x?: number | undefined;
  /** New centre y (the body must not overlap anything there). */
  y?: number | undefined;
  /** New velocity x. */
  vx?: number | undefined;
  /** New velocity y. */
  vy?: number | undefined;
  /** New radius (the grown body must not overlap anything). */
  r?: number | undefined;
  /** New mass (1e-40 to 1e40, or Infinity). */
  m?: number | undefined;
  /** New friction coefficient (must be 0 while the gravity field is non-zero). */
  mu?: number | undefined;
}

/** A disc at one instant. */
export interface BodyState {
  id: string;
  /** Centre x. */
  x: number;
  /** Centre y. */
  y: number;
  /** Velocity x (0 once friction has stopped the body). */
  vx: number;
  /** Velocity y (0 once friction has stopped the body). */
  vy: number;
  /** Acceleration x of the current motion: friction (−mu·g along the velocity; 0 once stopped) or the gravity field. */
  ax: number;
  /** Acceleration y of the current motion: friction (−mu·g along the velocity; 0 once stopped) or the gravity field. */
  ay: number;
  /** Radius. */
  r: number;
  /** Mass (Infinity: immovable by collisions). */
  m: number;
  /** Friction coefficient. */
  mu: number;
}

/** A line obstacle: infinite `line` through p1 and p2, `ray` from p1 through p2, or `segment` p1–p2. */
export interface LineState {
  id: string;
  p1: Vec2;
  p2: Vec2;
  kind: "line" | "ray" | "segment";
}

/** A point obstacle at `p`. */
export interface PointState {
  id: string;
  p: Vec2;
}

/**
 * One processed event: a collision (WorldCollision) or a stop (WorldStop), told apart by `kind`
 * (`if (e.kind !== "stop") e.b` is a string). The World reuses a single object for every event:
 * copy what you keep. For bodyBody, `a` < `b` in id order. The normal points from `a` towards `b`
 * (the obstacle).
 */
export type WorldEvent = WorldCollision | WorldStop;

/** The fields every WorldEvent has. */
interface WorldEventFields {
  time: number;
  /** The body (for bodyBody, the one first in id order). */
  a: string;
  /** Contact point; for a stop, where the body stopped. */
  px: number;
  py: number;
  /** Unit normal from a towards b at contact; (0, 0) for a stop. */
  nx: number;
  ny: number;
  /** Magnitude of the impulse (Infinity when both masses are infinite); 0 for a stop or a graze. */
  impulse: number;
}

/** A collision: `b` is the other body (bodyBody), the line (bodyLine) or the point (bodyPoint). */
export interface WorldCollision extends WorldEventFields {
  kind: "bodyBody" | "bodyLine" | "bodyPoint";
  b: string;
}

/** A friction stop of body `a`: `b` null, the normal (0, 0), the impulse 0. */
export interface WorldStop extends WorldEventFields {
  kind: "stop";
  b: null;
}

/** The World's one event object, written field by field (a WorldEvent once filled in). */
export interface WorldEventRecord extends WorldEventFields {
  kind: EventKind;
  b: string | null;
}

/** Switches for the optimisations, so the benchmark can show what each one buys. All default on. */
export interface Optimizations {
  /** Cell grid with crossing events; off = every body is tested against every body. */
  broadPhase?: boolean | undefined;
  /** Reject pairs whose whole remaining paths (friction: finite segments) cannot meet, before solving. */
  pathBounds?: boolean | undefined;
  /** Closed-form quadratic when the relative acceleration is zero; off = always the quartic solver
   *  (whose roots may differ from the closed form's in the last bits). */
  quadraticFastPath?: boolean | undefined;
  /** Skip pairs where both bodies rest; off = test them too. */
  restingSkip?: boolean | undefined;
  /**
   * Reject a pair that recedes (d . u >= 0) with no relative acceleration before any polynomial is
   * formed; off = such pairs go to the solver, which finds no contact either.
   */
  recedingReject?: boolean | undefined;
}

/**
 * Options of `new World(options)`. Each is checked (ChapgameError naming it: `g`, `gravity[1]`,
 * `time`); an unknown key is refused (`gx`).
 */
export interface WorldOptions {
  /**
   * Friction field (default 9.81): a moving disc with friction coefficient mu decelerates at mu·g.
   * 0 (no friction), or between FIELD_MIN (1e-30) and MAGNITUDE_MAX (1e30). It acts only on discs
   * with mu > 0 (mu defaults to 0).
   */
  g?: number | undefined;
  /**
   * Uniform acceleration field [gx, gy] acting on every disc (default [0, 0]); each component 0, or
   * between FIELD_MIN and MAGNITUDE_MAX in size. While it is non-zero, every disc's mu must be 0.
   */
  gravity?: Vec2 | undefined;
  /**
   * Starting time of the World's clock (default 0; at most TIME_MAX, 1e30, in size: the world may
   * then advance past it by events, not by an untilTime). It may be negative: the clock is a coordinate, and a scene started at
   * t0 runs as the one started at 0, shifted by t0 (a Timeline's clock starts at 0). Times are doubles: keep
   * them near 0 (seconds since the level started, not since 1970), since an event at time T is only
   * located to within ulp(T).
   */
  time?: number | undefined;
  /** Switches for the optimisations, each on by default (they exist for the benchmarks); each
   *  given switch must be true or false (ChapgameError `optimizations.broadPhase`). */
  optimizations?: Optimizations | undefined;
}

/**
 * Limits of `World.advance`: it stops at whichever comes first. Both left out = run until nothing
 * is queued (a scene that never comes to rest then runs for ever: give a bound).
 */
export interface AdvanceLimits {
  /**
   * An ABSOLUTE time on the World's clock (like `World.time`), not a duration: every event at or
   * before it is processed (events exactly at it included), then the World's time becomes
   * untilTime. Default +Infinity. Must be a number >= the World's current time, and at most
   * TIME_MAX (1e30) unless it is Infinity or that time (ChapgameError naming `untilTime`; past
   * TIME_MAX, bound a run by maxEvents); to advance by dt, pass `world.time + dt`. (Timeline.prolong's `time`, by
   * contrast, counts from the horizon; Timeline.prolongTo takes an absolute time.)
   */
  untilTime?: number | undefined;
  /**
   * Stop after this many collisions and stops (internal work such as cell crossings does not
   * count): a whole number >= 0, or Infinity (the default); ChapgameError naming `maxEvents`.
   */
  maxEvents?: number | undefined;
}

/** What `World.advance` did. */
export interface AdvanceResult {
  /** Collisions and stops processed (each reported to the callback). */
  events: number;
  /**
   * Why it stopped: "events" = maxEvents reached (the World's time is then the last event's);
   * "time" = untilTime reached with something still queued (with the broad-phase grid possibly only
   * cell crossings that lead to no event: `nextEventTime()` answers exactly); "idle" = nothing is
   * queued any more (with an untilTime, the World's time is untilTime; without one, the last event's,
   * or where the advance started when it processed none).
   */
  reason: "time" | "events" | "idle";
}

/**
 * Events a World has processed since it was made, by kind (`World.counts`: a live object, updated
 * as events are processed; a clone starts from a copy).
 */
export interface EventCounts {
  /** Disc–disc collisions. */
  bodyBody: number;
  /** Collisions of a disc with a line, ray or segment (its end points included). */
  bodyLine: number;
  /** Collisions of a disc with a point. */
  bodyPoint: number;
  /** Discs stopped by friction. */
  stop: number;
}
