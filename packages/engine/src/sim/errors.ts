/**
 * Errors the engine throws on bad input or on a state it cannot simulate.
 * ChapgameError (bad input) names the field (`path`) and the reason, and is thrown before anything
 * changes; SimulationError (a state the model cannot continue from) gives the time it was met.
 */

/** Invalid input: `path` names the field (e.g. `bodies.a.r`), `reason` says what is wrong with it. */
export class ChapgameError extends Error {
  readonly path: string;
  readonly reason: string;
  constructor(path: string, reason: string) {
    super(`${path}: ${reason}`);
    this.name = "ChapgameError";
    this.path = path;
    this.reason = reason;
  }
}

/**
 * A state the exact model cannot continue from (for example a disc resting on a line under gravity:
 * infinitely many zero-length bounces). The World's motions are left as they were before the failing
 * event and its time is that event's `time`, so the states up to that instant can still be read; a
 * Timeline keeps what it computed up to there.
 */
export class SimulationError extends Error {
  readonly time: number;
  /** What the failing event involved, when one contact is to blame: the body (or the two bodies, in
   *  id order), then the line or point. For a Zeno state, who it caught (zenoAdvice.ts): the bodies,
   *  then the lines and points they touch (a crush: the crushed discs, the crusher, then the sides);
   *  [] only when the watch was not told (a ZenoWatch used alone). */
  readonly ids: readonly string[];
  constructor(message: string, time: number, ids: readonly string[] = []) {
    super(message);
    this.name = "SimulationError";
    this.time = time;
    this.ids = Object.freeze([...ids]);
  }
}
