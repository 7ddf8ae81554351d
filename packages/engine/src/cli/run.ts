/**
 * runCli(argv, io): the `chapgame` command, with all input and output through `io` (so it can be
 * tested in-process and main.ts stays a thin wrapper). Returns the exit status: 0 success, 2 invalid
 * input (bad arguments, unreadable or invalid scene, a scene the exact model cannot continue), 1 an
 * internal error or a result that could not be written (OutputError). Errors are one line on
 * stderr, without a stack trace. A simulate run the engine cannot continue still prints the result
 * up to where it stopped, with "reason": "error" and the message in "error", then exits with 2.
 * runCliInterruptible(argv, io, control): the same, computing in slices with a pause between them
 * (slices.ts); an interrupt (SIGINT, SIGTERM) stops the computation and prints the result up to
 * there with "reason": "interrupted" (simulate and state alike), then exits with 130 or 143.
 * Without --until-time and --max-events, simulate computes a scene whose actions carry an `until`
 * as far as they say (every action applied and each until met: what Timeline.fromScene computes),
 * with "reason": "until" (or "idle"); options given on the command line win over the scene's.
 * `path` computes up to --to and prints body --id's pieces (Timeline.path) over [--from, --to]; an
 * id no addBody of the scene names is refused (status 2) before anything is computed. After an
 * error or an interrupt it prints the pieces up to where the run stopped.
 * `check` validates a scene whole (checkScene): its fields, then every action against the
 * simulation, computed exactly up to the last action; it prints {"valid": …} either way.
 */
import { parseScene, printable } from "../scene/parse.js";
import type { SceneFile, Until } from "../scene/types.js";
import { ChapgameError, SimulationError } from "../sim/errors.js";
import type { PathPiece } from "../timeline/path.js";
import { Timeline } from "../timeline/timeline.js";
import type { ProlongResult } from "../timeline/types.js";
import { type Command, parseArgs, USAGE, UsageError } from "./args.js";
import { type PathResult, type RunEnd, writePath, writeResult } from "./output.js";
import {
  computeSlices,
  type InterruptControl,
  Interrupted,
  type Progress,
  runInterruptible,
  runToEnd,
} from "./slices.js";

export interface CliIO {
  /** Contents of a file ("-" = standard input); throws when it cannot be read. */
  readFile(path: string): string;
  stdout(text: string): void;
  stderr(text: string): void;
  /** stderr is a terminal: show progress there on one updating line (without it, only --progress
   *  shows progress, one line each) */
  progress: boolean;
  /** the package's version, for --version (the bin reads it from package.json) */
  version?: string;
  /** Called when the computation starts, after the scene is read and checked (the bin catches
   *  interrupts from then on: while it reads or parses, a Ctrl-C ends the process at once). */
  computing?: () => void;
  /** Called once the computation is over, before the result is written (the bin stops catching
   *  interrupts then: a Ctrl-C while a long result is written ends the process at once). */
  computed?: () => void;
}

/** How progress is shown on stderr: one updating line (a terminal), one line each, or not at all. */
type ProgressMode = "terminal" | "lines" | "off";

/** Progress lines on stderr for a run toward `until`, or null when they are off. */
function progressLines(until: Until, mode: ProgressMode, io: CliIO): Progress | null {
  if (mode === "off") return null;
  const goal = until.events === undefined ? "" : ` of ${until.events}`;
  return {
    report(horizon, events) {
      const line = `chapgame: t = ${horizon.toPrecision(6)}, ${events}${goal} events`;
      io.stderr(mode === "terminal" ? `\r${line}` : `${line}\n`);
    },
    // clear the progress line, also when the run ends in an error or an interrupt (printed after this)
    end() {
      if (mode === "terminal") io.stderr("\r\x1b[K");
    },
  };
}

/** Computes `until` from the horizon in slices (slices.ts), with progress; returns why it ended. */
function compute(
  tl: Timeline,
  until: Until,
  mode: ProgressMode,
  io: CliIO,
): Generator<void, ProlongResult["reason"], void> {
  return computeSlices(tl, until, progressLines(until, mode, io));
}

/**
 * The scene's own bound, when one of its actions has an `until`: up to its last action's time,
 * counted from horizon 0 (a Timeline made with the untils option goes on until every until is met).
 * Null when no action has one.
 */
function sceneBound(scene: SceneFile): Until | null {
  let last = 0;
  let any = false;
  for (const a of scene.actions) {
    if (a.time > last) last = a.time;
    if (a.until !== undefined) any = true;
  }
  return any ? { time: last } : null;
}

/** Why a simulate run stopped (without an error or an interrupt) and the time to print the bodies at. */
type SimulateEnd = { time: number; reason: ProlongResult["reason"] | "until" };

/**
 * Runs `simulate`; returns the time to print the bodies at and why the run stopped: "idle" when
 * no event or action is left at all (checked exactly), else "time" or "events", or "until" when the
 * scene's own bound (`bound`: its actions' untils) stopped it. With --until-time T the time is T
 * unless an event limit stopped the run earlier with more to come: a scene with nothing left before
 * T still moves (discs gliding for ever), and its state at T is exact. With the scene's bound the
 * time is where it ended (the bodies may glide on). Otherwise an idle run stops at its last event or
 * action.
 */
function* simulate(
  tl: Timeline,
  cmd: Extract<Command, { command: "simulate" }>,
  bound: Until | null,
  mode: ProgressMode,
  io: CliIO,
): Generator<void, SimulateEnd, void> {
  if (bound !== null) {
    yield* compute(tl, bound, mode, io);
    return { time: tl.horizon, reason: tl.nothingLeft() ? "idle" : "until" };
  }
  const until: Until = {};
  if (cmd.untilTime !== undefined) until.time = cmd.untilTime;
  if (cmd.maxEvents !== undefined) until.events = cmd.maxEvents;
  const reason = yield* compute(tl, until, mode, io);
  // "idle" exactly: the World's own reason can be "time" while only cell crossings are queued (a
  // glide with no event left), and an event limit can land on the last event.
  if (reason !== "idle" && !tl.nothingLeft()) return { time: tl.horizon, reason };
  const time = cmd.untilTime ?? tl.lastLoggedTime();
  if (tl.horizon < time) tl.prolong({ time }); // nothing happens on the way: the state at T is exact
  return { time, reason: "idle" };
}

/**
 * The time of the first addBody of `id` in the scene; refuses a `path --id` that no addBody action
 * names (a typo would else print nothing).
 */
function firstAdded(scene: SceneFile, id: string): number {
  const ids = new Set<string>();
  let first = Infinity;
  for (const a of scene.actions) {
    if (a.type !== "addBody") continue;
    ids.add(a.id);
    if (a.id === id && a.time < first) first = a.time;
  }
  if (ids.has(id)) return first;
  const known = [...ids].sort();
  const list =
    known.length <= 10 ? known.join(", ") : `${known.slice(0, 10).join(", ")}, … (${known.length} in all)`;
  throw new UsageError(
    `--id: no body ${JSON.stringify(id)} in the scene (${known.length === 0 ? "it adds no body" : `bodies: ${list}`})`,
  );
}

type PathCommand = Extract<Command, { command: "path" }>;

/**
 * The body's pieces over [from, to]: none when the body is first added (at `added`) after `to`, or
 * exactly at `to` without the addition having taken place there (Timeline.path refuses an id the
 * history has not met yet; for the command, a body that does not exist yet has no piece).
 */
function piecesUpTo(tl: Timeline, cmd: PathCommand, added: number, to: number): PathPiece[] {
  const exists = added < to || (added === to && tl.stateAt(to).bodies.some((b) => b.id === cmd.id));
  return to >= cmd.from && exists ? tl.path(cmd.id, cmd.from, to) : [];
}

/**
 * The pieces of the path command's body over [from, to], or, after a run that stopped early (`end`),
 * up to where it stopped: none when that is before `from` or before the body was first added (at
 * `added`; added exactly where the run stopped, it counts when the addition took place).
 */
function pathResult(tl: Timeline, cmd: PathCommand, added: number, end?: RunEnd): PathResult {
  if (end === undefined)
    return { id: cmd.id, from: cmd.from, to: cmd.to, pieces: piecesUpTo(tl, cmd, added, cmd.to) };
  const to = tl.horizon;
  const early =
    end.reason === "error"
      ? { reason: "error" as const, error: end.error }
      : { reason: "interrupted" as const };
  return { id: cmd.id, from: cmd.from, to, end: early, pieces: piecesUpTo(tl, cmd, added, to) };
}

/**
 * `check`: the scene's fields (parseScene), then every action applied to the simulation computed up
 * to the last action's time (a headless Timeline: no log kept), which ends for any scene. Prints
 * {"valid": true, "actions", "checkedTo", "events"} and returns 0, or {"valid": false, "error",
 * "path"} (the message on stderr too, after the file's name) and returns 2; a Zeno state before the
 * last action is invalid too (path null). An interrupt prints nothing on stdout and returns 130 / 143.
 */
function* checkScene(
  text: string,
  file: string,
  cmd: Extract<Command, { command: "check" }>,
  io: CliIO,
): Generator<void, number, void> {
  const write = (result: object) => io.stdout(`${JSON.stringify(result, null, 2)}\n`);
  const invalid = (e: Error, path: string | null) => {
    const error = printable(e.message);
    write({ valid: false, error, path });
    io.stderr(
      `chapgame: ${file}: ${e instanceof SimulationError ? "cannot simulate this scene: " : ""}${error}\n`,
    );
    return 2;
  };
  let tl: Timeline;
  let last = 0;
  let count = 0;
  try {
    const scene = parseScene(text);
    for (const a of scene.actions) if (a.time > last) last = a.time;
    count = scene.actions.length;
    tl = Timeline.fromParsedScene(scene, { history: false, compute: false });
  } catch (e) {
    if (e instanceof ChapgameError) return invalid(e, e.path);
    if (e instanceof SimulationError) return invalid(e, null);
    throw e;
  }
  const mode: ProgressMode = io.progress ? "terminal" : cmd.progress === true ? "lines" : "off";
  io.computing?.();
  try {
    yield* compute(tl, { time: last }, mode, io);
  } catch (e) {
    io.computed?.();
    if (e instanceof Interrupted) {
      io.stderr(
        `chapgame: ${file}: interrupted by ${e.signal} at t = ${tl.horizon}: the check did not finish\n`,
      );
      return e.status;
    }
    if (e instanceof ChapgameError) return invalid(e, e.path);
    if (e instanceof SimulationError) return invalid(e, null);
    throw e;
  }
  io.computed?.();
  const c = tl.counts();
  write({
    valid: true,
    actions: count,
    checkedTo: last,
    events: c.bodyBody + c.bodyLine + c.bodyPoint + c.stop,
  });
  return 0;
}

/** Thrown by a CliIO.stdout that cannot write (a full disk, a closed file): not a bug of the run. */
export class OutputError extends Error {}

/** Runs the command through, without interrupts (see the header). */
export function runCli(argv: readonly string[], io: CliIO): number {
  return runToEnd(command(argv, io));
}

/** Runs the command in slices with a pause between them; an interrupt prints the result so far
 *  (see the header). */
export function runCliInterruptible(
  argv: readonly string[],
  io: CliIO,
  control: InterruptControl,
): Promise<number> {
  return runInterruptible(command(argv, io), control);
}

/** The command as a generator that yields between slices of the computation (slices.ts). */
function* command(argv: readonly string[], io: CliIO): Generator<void, number, void> {
  let source: string | null = null; // the scene's name, once it is read
  try {
    const cmd = parseArgs(argv);
    if (cmd.command === "help") {
      io.stdout(`${USAGE}\n`);
      return 0;
    }
    if (cmd.command === "version") {
      io.stdout(`chapgame ${io.version ?? "(version unknown)"}\n`);
      return 0;
    }
    let text: string;
    try {
      text = io.readFile(cmd.scene);
    } catch (e) {
      throw new UsageError(`cannot read ${cmd.scene}: ${(e as Error).message.split("\n")[0]}`);
    }
    source = cmd.scene === "-" ? "<stdin>" : cmd.scene;
    if (cmd.command === "check") return yield* checkScene(text, printable(source), cmd, io);
    const scene = parseScene(text);
    // the scene's own bound only when the command line gives none
    const bound =
      cmd.command === "simulate" && cmd.untilTime === undefined && cmd.maxEvents === undefined
        ? sceneBound(scene)
        : null;
    const added = cmd.command === "path" ? firstAdded(scene, cmd.id) : 0;
    const history = cmd.command === "path" || cmd.events;
    const tl = Timeline.fromParsedScene(scene, { history, compute: false, untils: bound !== null });
    const mode: ProgressMode = io.progress ? "terminal" : cmd.progress === true ? "lines" : "off";
    const out = (text: string) => io.stdout(text);
    /** Writes the result up to where the computation stopped, with why. */
    const partial = (end: RunEnd) => {
      io.computed?.();
      if (cmd.command === "path") writePath(pathResult(tl, cmd, added, end), out, cmd.compact);
      else writeResult(tl, tl.horizon, out, { log: cmd.events, end, compact: cmd.compact });
    };
    let time: number;
    let end: RunEnd | undefined;
    io.computing?.();
    try {
      if (cmd.command === "path") {
        yield* compute(tl, { time: cmd.to }, mode, io);
        io.computed?.();
        writePath(pathResult(tl, cmd, added), out, cmd.compact);
        return 0;
      }
      if (cmd.command === "state") {
        // from horizon 0 (nothing computed yet), `time: at` ahead is exactly up to at
        yield* compute(tl, { time: cmd.at }, mode, io);
        time = cmd.at;
      } else {
        const r = yield* simulate(tl, cmd, bound, mode, io);
        time = r.time;
        end = { reason: r.reason };
      }
    } catch (e) {
      if (e instanceof Interrupted) {
        // What was computed up to the interrupt is a result too (simulate and state alike).
        partial({ reason: "interrupted" });
        const c = tl.counts();
        const n = c.bodyBody + c.bodyLine + c.bodyPoint + c.stop;
        io.stderr(
          `chapgame: ${printable(source)}: interrupted by ${e.signal} at t = ${tl.horizon} after ${n} events: the result up to there is printed\n`,
        );
        return e.status;
      }
      // The engine cannot continue (a Zeno state): what was computed up to it is a result too
      // (simulate and state alike: `state --at T` then prints the bodies where it stopped, before T).
      if (e instanceof SimulationError) partial({ reason: "error", error: printable(e.message) });
      throw e;
    }
    io.computed?.();
    writeResult(tl, time, out, { log: cmd.events, compact: cmd.compact, end });
    return 0;
  } catch (e) {
    // Errors about the scene's content name the scene file first (a batch over many files); a
    // key, id or file name may hold control characters, which must not reach the terminal raw.
    const file = source === null ? "" : `${printable(source)}: `;
    if (e instanceof Error) e.message = printable(e.message);
    if (e instanceof OutputError) {
      io.stderr(`chapgame: cannot write the result: ${e.message}\n`);
      return 1;
    }
    if (e instanceof UsageError) {
      io.stderr(`chapgame: ${e.message}\n`);
      return 2;
    }
    if (e instanceof ChapgameError) {
      io.stderr(`chapgame: ${file}${e.message}\n`);
      return 2;
    }
    if (e instanceof SimulationError) {
      io.stderr(`chapgame: ${file}cannot simulate this scene: ${e.message}\n`);
      return 2;
    }
    io.stderr(`chapgame: internal error: ${e instanceof Error ? e.message : String(e)}\n`);
    return 1;
  }
}
