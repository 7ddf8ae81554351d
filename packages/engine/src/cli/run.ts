/**
 * runCli(argv, io): the `chapgame` command, with all input and output through `io` (so it can be
 * tested in-process and main.ts stays a thin wrapper). Returns the exit status: 0 success, 2 invalid
 * input (bad arguments, unreadable or invalid scene, a scene the exact model cannot continue), 1 an
 * internal error or a result that could not be written (OutputError). Errors are one line on
 * stderr, without a stack trace. A simulate run the engine cannot continue still prints the result
 * up to where it stopped, with "reason": "error" and the message in "error", then exits with 2.
 */
import { parseScene, printable } from "../scene/parse.js";
import type { Until } from "../scene/types.js";
import { ChapgameError, SimulationError } from "../sim/errors.js";
import { Timeline } from "../timeline/timeline.js";
import type { ProlongResult } from "../timeline/types.js";
import { type Command, parseArgs, USAGE, UsageError } from "./args.js";
import { writeResult } from "./output.js";

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
}

/** Events computed between two progress lines. */
const PROGRESS_EVERY_EVENTS = 200_000;

/** How progress is shown on stderr: one updating line (a terminal), one line each, or not at all. */
type ProgressMode = "terminal" | "lines" | "off";

/** Computes `until` from the horizon in slices of PROGRESS_EVERY_EVENTS events, reporting after each
 *  slice that does not finish the run; returns why it ended. */
function compute(tl: Timeline, until: Until, mode: ProgressMode, io: CliIO): ProlongResult["reason"] {
  if (mode === "off") return tl.prolong(until).reason;
  const goal = until.events === undefined ? "" : ` of ${until.events}`;
  let total = 0;
  let shown = false;
  try {
    for (;;) {
      const r = tl.prolongSlice(until, PROGRESS_EVERY_EVENTS);
      total += r.events;
      if (r.done) return r.reason ?? "idle";
      const line = `chapgame: t = ${r.horizon.toPrecision(6)}, ${total}${goal} events`;
      io.stderr(mode === "terminal" ? `\r${line}` : `${line}\n`);
      shown = true;
    }
  } finally {
    // clear the progress line, also when the run ends in an error (printed after this)
    if (shown && mode === "terminal") io.stderr("\r\x1b[K");
  }
}

/**
 * Runs `simulate`; returns the time to print the bodies at and why the run stopped: "idle" when
 * no event or action is left at all (checked exactly), else "time" or "events". With --until-time
 * T the time is T unless an event limit stopped the run earlier with more to come: a scene with
 * nothing left before T still moves (discs gliding for ever), and its state at T is exact. Without
 * it, an idle run stops at its last event or action.
 */
function simulate(
  tl: Timeline,
  cmd: Extract<Command, { command: "simulate" }>,
  mode: ProgressMode,
  io: CliIO,
): { time: number; reason: ProlongResult["reason"] } {
  const until: Until = {};
  if (cmd.untilTime !== undefined) until.time = cmd.untilTime;
  if (cmd.maxEvents !== undefined) until.events = cmd.maxEvents;
  const reason = compute(tl, until, mode, io);
  // "idle" exactly: the World's own reason can be "time" while only cell crossings are queued (a
  // glide with no event left), and an event limit can land on the last event.
  if (reason !== "idle" && !tl.nothingLeft()) return { time: tl.horizon, reason };
  const time = cmd.untilTime ?? tl.lastLoggedTime();
  if (tl.horizon < time) tl.prolong({ time }); // nothing happens on the way: the state at T is exact
  return { time, reason: "idle" };
}

/** Thrown by a CliIO.stdout that cannot write (a full disk, a closed file): not a bug of the run. */
export class OutputError extends Error {}

export function runCli(argv: readonly string[], io: CliIO): number {
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
    const scene = parseScene(text);
    const tl = Timeline.fromScene(scene, { history: cmd.events, compute: false });
    const mode: ProgressMode = io.progress ? "terminal" : cmd.progress === true ? "lines" : "off";
    const out = (text: string) => io.stdout(text);
    if (cmd.command === "state") {
      // from horizon 0 (nothing computed yet), `time: at` ahead is exactly up to at
      compute(tl, { time: cmd.at }, mode, io);
      writeResult(tl, cmd.at, out, { log: cmd.events, compact: cmd.compact });
    } else {
      let end: { time: number; reason: ProlongResult["reason"] };
      try {
        end = simulate(tl, cmd, mode, io);
      } catch (e) {
        // The engine cannot continue (a Zeno state): what was computed up to it is a result too.
        if (!(e instanceof SimulationError)) throw e;
        const error = printable(e.message);
        writeResult(tl, tl.horizon, out, {
          log: cmd.events,
          end: { reason: "error", error },
          compact: cmd.compact,
        });
        throw e;
      }
      writeResult(tl, end.time, out, { log: cmd.events, end: { reason: end.reason }, compact: cmd.compact });
    }
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
