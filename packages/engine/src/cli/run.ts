/**
 * runCli(argv, io): the `chapgame` command, with all input and output through `io` (io.ts: so it can
 * be tested in-process and main.ts stays a thin wrapper). Returns the exit status: 0 success, 2
 * invalid input (bad arguments, unreadable or invalid scene, a scene the exact model cannot continue),
 * 1 an internal error or a result that could not be written (OutputError). Errors are one line on
 * stderr, without a stack trace. A simulate run the engine cannot continue still prints the result
 * up to where it stopped, with "reason": "error" and the message in "error", then exits with 2.
 * runCliInterruptible(argv, io, control): the same, computing in slices with a pause between them
 * (slices.ts); an interrupt (SIGINT, SIGTERM) stops the computation and prints the result up to
 * there with "reason": "interrupted" (simulate and state alike), then exits with 130 or 143; the
 * result is written in pieces with a pause between them too, and an interrupt then finishes it or,
 * after an earlier one, stops it at once (writing.ts).
 * The commands: simulate (simulate.ts: how far it computes, the scene's own untils), state, path
 * (pathCommand.ts: an id no addBody names is refused before anything is computed; after an error or
 * an interrupt it prints the pieces up to where the run stopped) and check (check.ts: prints
 * {"valid": …} either way); progress on stderr: progress.ts.
 */
import { parseSceneFrom, printable } from "../scene/parse.js";
import { ChapgameError, SimulationError } from "../sim/errors.js";
import { Timeline } from "../timeline/timeline.js";
import { parseArgs, USAGE, UsageError } from "./args.js";
import { checkScene } from "./check.js";
import { type CliIO, OutputError } from "./io.js";
import { pathSteps, type RunEnd, resultSteps } from "./output.js";
import { firstAdded, pathResult } from "./pathCommand.js";
import { ProgressLine, progressMode } from "./progress.js";
import { sceneBound, simulate } from "./simulate.js";
import {
  type InterruptControl,
  Interrupted,
  type InterruptSignal,
  runInterruptible,
  runToEnd,
} from "./slices.js";
import { finishWriting, statusAfterWriting, WritingAborted } from "./writing.js";

export { type CliIO, OutputError } from "./io.js";

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
function* command(argv: readonly string[], given: CliIO): Generator<void, number, void> {
  const line = new ProgressLine(given);
  const io = line.io; // erases a progress line before writing
  let source: string | null = null; // the scene's name, once the command names it
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
    for (const note of cmd.notes ?? []) io.stderr(`chapgame: note: ${note}\n`);
    line.start(progressMode(io, cmd));
    source = cmd.scene === "-" ? "<stdin>" : cmd.scene;
    // the text is read where it is parsed, and not kept (150 MB for a million bodies)
    const read = () => readText(io, cmd.scene, line);
    if (cmd.command === "check") return yield* checkScene(read, printable(source), line, cmd.compact);
    const scene = parseSceneFrom(read);
    // the scene's own bound only when the command line gives none
    const bound =
      cmd.command === "simulate" && cmd.untilTime === undefined && cmd.maxEvents === undefined
        ? sceneBound(scene)
        : null;
    const added = cmd.command === "path" ? firstAdded(scene, cmd.id) : 0;
    const history = cmd.command === "path" || cmd.events;
    line.building(scene);
    const tl = Timeline.fromParsedScene(scene, { history, compute: false, untils: bound !== null });
    const out = (text: string) => io.stdout(text);
    const notice = (text: string) => io.stderr(`chapgame: ${printable(source ?? "")}: ${text}\n`);
    /** Writes with `steps`, an interrupt finishing it or stopping it (writing.ts); returns the run's
     *  interrupt, `earlier` or one received while writing. */
    const written = (steps: Generator<void, void, void>, earlier: InterruptSignal | null) => {
      io.computed?.();
      return finishWriting(steps, earlier, notice);
    };
    /** Writes the result up to where the computation stopped, with why. */
    const partial = (end: RunEnd, earlier: InterruptSignal | null) =>
      written(
        cmd.command === "path"
          ? pathSteps(pathResult(tl, cmd, added, end), out, cmd.compact)
          : resultSteps(tl, tl.horizon, out, { log: cmd.events, end, compact: cmd.compact }),
        earlier,
      );
    let time: number;
    let end: RunEnd | undefined;
    io.computing?.();
    try {
      if (cmd.command === "path") {
        yield* line.compute(tl, { time: cmd.to });
        const late = yield* written(pathSteps(pathResult(tl, cmd, added), out, cmd.compact), null);
        return statusAfterWriting(0, late);
      }
      if (cmd.command === "state") {
        // from horizon 0 (nothing computed yet), `time: at` ahead is exactly up to at
        yield* line.compute(tl, { time: cmd.at });
        time = cmd.at;
      } else {
        const r = yield* simulate(tl, cmd, bound, line);
        time = r.time;
        end = { reason: r.reason };
      }
    } catch (e) {
      if (e instanceof Interrupted) {
        // What was computed up to the interrupt is a result too (simulate and state alike).
        yield* partial({ reason: "interrupted" }, e.signal);
        const c = tl.counts();
        const n = c.bodyBody + c.bodyLine + c.bodyPoint + c.stop;
        io.stderr(
          `chapgame: ${printable(source)}: interrupted by ${e.signal} at t = ${tl.horizon} after ${n} events: the result up to there is printed\n`,
        );
        return e.status;
      }
      // The engine cannot continue (a Zeno state): what was computed up to it is a result too
      // (simulate and state alike: `state --at T` then prints the bodies where it stopped, before T).
      if (e instanceof SimulationError)
        yield* partial({ reason: "error", error: printable(e.message) }, null);
      throw e;
    }
    const format = { log: cmd.events, compact: cmd.compact, end };
    return statusAfterWriting(0, yield* written(resultSteps(tl, time, out, format), null));
  } catch (e) {
    // Errors about the scene's content name the scene file first (a batch over many files); a
    // key, id or file name may hold control characters, which must not reach the terminal raw.
    const file = source === null ? "" : `${printable(source)}: `;
    if (e instanceof Error) e.message = printable(e.message);
    if (e instanceof WritingAborted) {
      io.stderr(`chapgame: ${file}${e.message}\n`);
      return e.status;
    }
    if (e instanceof OutputError) {
      io.stderr(`chapgame: cannot write the result: ${e.message}\n`);
      return 1;
    }
    if (e instanceof UsageError) {
      io.stderr(`chapgame: ${e.aboutScene ? file : ""}${e.message}\n`);
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

/** Why a file could not be read, in words, for the system errors a user meets (Node's own message,
 *  "ENOENT: no such file or directory, open 'x.json'", repeats the name); others as Node says. */
const READ_ERRORS: Readonly<Record<string, string>> = {
  ENOENT: "no such file",
  EISDIR: "it is a folder, not a file",
  EACCES: "permission denied",
  EPERM: "permission denied",
  ENOTDIR: "a part of the path is not a folder",
  // Node's "Cannot create a string longer than 0x1fffffe8 characters" did not say it was the file's size
  // (a device or fifo that never ends, /dev/zero, is refused so too, once that much is read: readBounded.ts)
  ERR_STRING_TOO_LONG:
    "it gives more text than a JavaScript string can hold (0x1fffffe8, about 537 million characters), so no scene that large can be read: reading stopped there",
};

/** The scene file's text (a UsageError when it cannot be read); a long read shows its progress and
 *  a long text is announced. */
function readText(io: CliIO, path: string, line: ProgressLine): string {
  let text: string;
  try {
    text = io.readFile(path, (bytes) => line.readingBytes(bytes));
  } catch (e) {
    const code = (e as { code?: unknown }).code;
    const known = typeof code === "string" && Object.hasOwn(READ_ERRORS, code);
    const why = known ? `${READ_ERRORS[code]} (${code})` : (e as Error).message.split("\n")[0];
    throw new UsageError(`cannot read ${path === "-" ? "standard input" : path}: ${why}`);
  }
  line.reading(text);
  return text;
}
