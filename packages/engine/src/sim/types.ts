/** Public data types of the World (see docs/architecture.md). */

export type Vec2 = readonly [number, number];

export type EventKind = "bodyBody" | "bodyLine" | "bodyPoint" | "stop";

export interface BodyInit {
  x: number;
  y: number;
  r: number;
  m: number;
  mu?: number | undefined;
  vx?: number | undefined;
  vy?: number | undefined;
}

/**
 * A body given by an exact motion that started at t0 (at or before the World's time), as
 * `World.motion(id)` reports it: p(t) = (x0, y0) + (t - t0) (v + (t - t0) a / 2), where a (friction
 * or the gravity field) follows from v, mu and the World's globals exactly as for any motion.
 */
export interface BodyMotionInit {
  t0: number;
  x0: number;
  y0: number;
  vx: number;
  vy: number;
  r: number;
  m: number;
  mu?: number | undefined;
}

export interface BodyPatch {
  x?: number | undefined;
  y?: number | undefined;
  vx?: number | undefined;
  vy?: number | undefined;
  r?: number | undefined;
  m?: number | undefined;
  mu?: number | undefined;
}

/** A disc at one instant. */
export interface BodyState {
  id: string;
  x: number;
  y: number;
  vx: number;
  vy: number;
  ax: number;
  ay: number;
  r: number;
  m: number;
  mu: number;
}

export interface LineState {
  id: string;
  p1: Vec2;
  p2: Vec2;
  kind: "line" | "ray" | "segment";
}

export interface PointState {
  id: string;
  p: Vec2;
}

/**
 * One processed event. The World reuses a single object for every event: copy what you keep.
 * For bodyBody, `a` < `b` in id order. The normal points from `a` towards `b` (the obstacle).
 */
export interface WorldEvent {
  time: number;
  kind: EventKind;
  a: string;
  b: string | null;
  /** Contact point; for a stop, where the body stopped. */
  px: number;
  py: number;
  /** Unit normal from a towards b at contact; (0, 0) for a stop. */
  nx: number;
  ny: number;
  /** Magnitude of the impulse (Infinity when both masses are infinite); 0 for a stop or a graze. */
  impulse: number;
}

/** Switches for the optimisations, so the benchmark can show what each one buys. All default on. */
export interface Optimizations {
  /** Cell grid with crossing events; off = every body is tested against every body. */
  broadPhase?: boolean | undefined;
  /** Reject pairs whose whole remaining paths (friction: finite segments) cannot meet, before solving. */
  pathBounds?: boolean | undefined;
  /** Closed-form quadratic when the relative acceleration is zero; off = always the quartic solver. */
  quadraticFastPath?: boolean | undefined;
  /** Skip pairs where both bodies rest; off = test them too. */
  restingSkip?: boolean | undefined;
  /**
   * Reject a pair that recedes (d . u >= 0) with no relative acceleration before any polynomial is
   * formed; off = such pairs go to the solver, which finds no contact either.
   */
  recedingReject?: boolean | undefined;
}

export interface WorldOptions {
  g?: number | undefined;
  gravity?: Vec2 | undefined;
  time?: number | undefined;
  optimizations?: Optimizations | undefined;
}

export interface AdvanceLimits {
  untilTime?: number | undefined;
  maxEvents?: number | undefined;
}

export interface AdvanceResult {
  events: number;
  reason: "time" | "events" | "idle";
}

export interface EventCounts {
  bodyBody: number;
  bodyLine: number;
  bodyPoint: number;
  stop: number;
}
