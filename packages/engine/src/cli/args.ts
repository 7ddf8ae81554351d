/**
 * Command-line arguments of the `chapgame` bin, parsed into a Command (pure; no process access).
 *   chapgame simulate SCENE [--until-time T] [--max-events N] [--events] [--compact] [--progress]
 *   chapgame state SCENE --at T [--events] [--compact] [--progress]
 *   chapgame path SCENE --id ID --to T [--from T] [--compact] [--progress]
 *   chapgame check SCENE [--compact] [--progress]
 * (USAGE, the --help text in usage.ts, describes them, the result, how a run ends and the exit statuses.)
 *   chapgame --help | help
 *   chapgame --version
 * Options take their value as the next argument or after "=". Any other argument that starts with
 * "-" (except "-" itself, standard input) is an unknown option, never a file name, unless it comes
 * after "--" (the end of options). Invalid arguments throw UsageError with a one-line message; a
 * time past TIME_MAX is one (sim/timeLimit.ts). A time typed with more digits than a double holds
 * that reads as a double printed differently gets a note (Command.notes: rounding.ts).
 */

import { BEYOND_TIME_MAX_WHY } from "../sim/timeLimit.js";
import { TIME_MAX } from "../tolerances.js";
import { roundingNote } from "./rounding.js";

export { USAGE } from "./usage.js";

export class UsageError extends Error {
  /** The arguments do not fit the scene file's contents (a `path --id` no body of it has): the
   *  message is shown after the file's name, as the errors about its contents are. */
  readonly aboutScene: boolean;
  constructor(message: string, aboutScene = false) {
    super(message);
    this.name = "UsageError";
    this.aboutScene = aboutScene;
  }
}

/** A command and its options; `notes`, when some time given reads as a different double than it
 *  was typed (rounding.ts), the lines to say so on stderr. */
export type Command = (
  | { command: "help" }
  | { command: "version" }
  | {
      command: "simulate";
      scene: string;
      untilTime?: number;
      maxEvents?: number;
      events: boolean;
      compact?: boolean;
      progress?: boolean;
    }
  | { command: "state"; scene: string; at: number; events: boolean; compact?: boolean; progress?: boolean }
  | {
      command: "path";
      scene: string;
      id: string;
      from: number;
      to: number;
      compact?: boolean;
      progress?: boolean;
    }
  | { command: "check"; scene: string; compact?: boolean; progress?: boolean }
) & { notes?: string[] };

/** A value typed on the command line as a refusal names it: quoted with JSON escapes, as the
 *  editor names what was typed (`(got "abc")`; the engine's form, sim/refusalText.ts). */
function typed(v: string): string {
  return JSON.stringify(v.length > 40 ? `${v.slice(0, 40)}…` : v);
}

/** A time as written in decimal (12.5, .5, 3., 1e-3); Number() alone also takes 0x10 and 0b11. */
const DECIMAL_TIME = /^[+-]?(\d+\.?\d*|\.\d+)(e[+-]?\d+)?$/i;

/** For a bound that may be left out (--until-time), an infinite value's refusal says so, as
 *  --max-events's does: a user asking for no limit learns how to get one. */
const NO_LIMIT_HINT = ": for no limit, leave it out";

function time(name: string, v: string, hint = ""): number {
  const t = Number(v);
  if (/^[+-]?infinity$/i.test(v.trim()))
    throw new UsageError(`${name}: must be a finite number (got ${typed(v)})${hint}`);
  if (!DECIMAL_TIME.test(v.trim()) && /^\+?\d/.test(v.trim()) && t >= 0)
    // 0x10, 0b11, 1_000: a number to Number() or to a reader, but not a time as the CLI reads one
    // (review of session 26: "must be a non-negative number" did not say what was wrong with 0x10)
    throw new UsageError(`${name}: must be a number written in decimal (12.5, 1e-3) (got ${typed(v)})`);
  if (!DECIMAL_TIME.test(v.trim()) || t < 0)
    throw new UsageError(`${name}: must be a non-negative number (got ${typed(v)})`);
  if (!Number.isFinite(t)) throw new UsageError(`${name}: must be a finite number (got ${typed(v)})${hint}`);
  if (t > TIME_MAX)
    // review of session 31: under gravity 1e30, --until-time 1e200 printed y = -Infinity (sim/timeLimit.ts)
    throw new UsageError(
      `${name}: must be at most ${TIME_MAX} (TIME_MAX) (got ${typed(v)}): ${BEYOND_TIME_MAX_WHY}${hint === "" ? "" : `;${hint.slice(1)}, and bound a longer run with --max-events`}`,
    );
  if (t === 0 && /[1-9]/.test(v.trim().split(/e/i)[0] as string))
    // 1e-400 reads as 0 to Number(), as to JSON.parse: the user asked for a time after 0, not 0
    // (review of session 29: `--at 1e-400` printed the state at 0 without a word)
    throw new UsageError(
      `${name}: is below the smallest double (about 5e-324) and would read as 0 (got ${typed(v)}): write 0 for 0`,
    );
  return t;
}

/** Decimal digits, optionally with a + sign (as a time may have), a fraction and an exponent (+5,
 *  1e6, 2.5e3): the forms a count may be written in; whether the value is an integer is checked on the number. */
const DECIMAL = /^\+?\d+(\.\d+)?(e\+?\d+)?$/i;

function count(name: string, v: string): number {
  const n = Number(v);
  if (!DECIMAL.test(v.trim()) && /^\+?\d/.test(v.trim()) && Number.isInteger(n) && n >= 0)
    throw new UsageError(`${name}: must be a whole number written in decimal (1000, 1e6) (got ${typed(v)})`);
  if (!DECIMAL.test(v.trim()) || !Number.isInteger(n))
    throw new UsageError(`${name}: must be a non-negative integer (got ${typed(v)})`);
  if (!Number.isSafeInteger(n))
    throw new UsageError(
      `${name}: must be an integer from 0 to ${Number.MAX_SAFE_INTEGER} (got ${typed(v)}): for no limit, leave it out`,
    );
  return n;
}

/** The options that take a value (the next argument, or after "="). */
const VALUED = new Set(["--until-time", "--max-events", "--at", "--id", "--from", "--to"]);

/** Whether the options (the arguments before "--") ask for the help: --help anywhere, -h unless it
 *  is an option's value (--id -h names a body "-h", as --id=-h does). */
function asksHelp(options: readonly string[]): boolean {
  return options.some(
    (a, i) => a === "--help" || (a === "-h" && !(i > 0 && VALUED.has(options[i - 1] as string))),
  );
}

export function parseArgs(argv: readonly string[]): Command {
  const c = parseCommand(argv);
  // notes on the times typed with more digits than a double holds (rounding.ts)
  const notes: string[] = [];
  for (const [name, value] of timesOf(c)) {
    const typedAs = typedValue(argv, name);
    const note = typedAs === undefined ? null : roundingNote(name, typedAs, value);
    if (note !== null) notes.push(note);
  }
  return notes.length === 0 ? c : { ...c, notes };
}

/** The times a command was given, by option name. */
function timesOf(c: Command): [string, number][] {
  if (c.command === "state") return [["--at", c.at]];
  if (c.command === "path")
    return [
      ["--from", c.from],
      ["--to", c.to],
    ];
  if (c.command === "simulate" && c.untilTime !== undefined) return [["--until-time", c.untilTime]];
  return [];
}

/** The value typed for option `name` (after "=" or as the next argument), before any "--". */
function typedValue(argv: readonly string[], name: string): string | undefined {
  for (let i = 0; i < argv.length && argv[i] !== "--"; i++) {
    const a = argv[i] as string;
    if (a === name) return argv[i + 1];
    if (a.startsWith(`${name}=`)) return a.slice(name.length + 1);
  }
  return undefined;
}

function parseCommand(argv: readonly string[]): Command {
  if (argv.length === 0) throw new UsageError("missing command (try chapgame --help)");
  // --help anywhere before "--" (after it, "--help" is a file name, as the help says)
  const endOfOptions = argv.indexOf("--");
  const options = endOfOptions < 0 ? argv : argv.slice(0, endOfOptions);
  if (asksHelp(options) || argv[0] === "help") return { command: "help" };
  if (argv[0] === "--version" || argv[0] === "-V") {
    if (argv.length > 1)
      throw new UsageError(`${argv[0]}: takes no arguments (got ${typed(argv[1] as string)})`);
    return { command: "version" };
  }
  const [cmd, ...rest] = argv;
  if (cmd !== "simulate" && cmd !== "state" && cmd !== "path" && cmd !== "check")
    throw new UsageError(
      cmd?.startsWith("-")
        ? `unknown option ${cmd} before a command: the command comes first (simulate, state, path or check; try chapgame --help)`
        : `unknown command "${cmd}" (commands: simulate, state, path, check; try chapgame --help)`,
    );
  const positional: string[] = [];
  const opts = new Map<string, string | true>();
  const valued = VALUED;
  const allowed =
    cmd === "simulate"
      ? ["--until-time", "--max-events", "--events", "--compact", "--progress"]
      : cmd === "state"
        ? ["--at", "--events", "--compact", "--progress"]
        : cmd === "path"
          ? ["--id", "--from", "--to", "--compact", "--progress"]
          : ["--compact", "--progress"];
  let optionsEnd = false;
  for (let i = 0; i < rest.length; i++) {
    const arg = rest[i] as string;
    if (arg === "--" && !optionsEnd) {
      optionsEnd = true; // what follows is a file name, even one that starts with "-"
      continue;
    }
    if (optionsEnd || !arg.startsWith("-") || arg === "-") {
      // After "--" every argument is a file name, "-" too (a file named "-", not standard input).
      positional.push(optionsEnd && arg === "-" ? "./-" : arg);
      continue;
    }
    const eq = arg.indexOf("=");
    const name = eq >= 0 ? arg.slice(0, eq) : arg;
    if (!allowed.includes(name))
      throw new UsageError(`unknown option ${name} for ${cmd} (options: ${allowed.join(", ")})`);
    if (opts.has(name)) throw new UsageError(`${name} given twice`);
    if (valued.has(name)) {
      const v = eq >= 0 ? arg.slice(eq + 1) : rest[++i];
      // A value cannot be another option ("--until-time --events"); negative numbers are refused
      // by their own check anyway.
      if (v === undefined || (eq < 0 && v.startsWith("--"))) throw new UsageError(`${name} needs a value`);
      opts.set(name, v);
    } else {
      if (eq >= 0) throw new UsageError(`${name} takes no value`);
      opts.set(name, true);
    }
  }
  if (positional.length === 0)
    throw new UsageError(`${cmd}: missing SCENE file (a scene file's name, or - to read standard input)`);
  if (positional.length > 1)
    throw new UsageError(`${cmd}: takes one SCENE file (got ${positional.length} arguments)`);
  const scene = positional[0] as string;
  const events = opts.has("--events");
  const progress = opts.has("--progress");
  const compact = opts.has("--compact");
  if (cmd === "check") {
    const c: Command = { command: "check", scene };
    if (compact) c.compact = true;
    if (progress) c.progress = true;
    return c;
  }
  if (cmd === "path") {
    const id = opts.get("--id");
    if (id === undefined) throw new UsageError("path: --id ID is required");
    if (id === "") throw new UsageError('--id: must be a body\'s id (got "")');
    const to = opts.get("--to");
    if (to === undefined) throw new UsageError("path: --to T is required");
    const from = opts.get("--from");
    const c: Command = {
      command: "path",
      scene,
      id: id as string,
      from: from === undefined ? 0 : time("--from", from as string),
      to: time("--to", to as string),
    };
    if (c.from > c.to) throw new UsageError(`--from: must not be after --to (${c.to}) (got ${c.from})`);
    if (compact) c.compact = true;
    if (progress) c.progress = true;
    return c;
  }
  if (cmd === "state") {
    const at = opts.get("--at");
    if (at === undefined) throw new UsageError("state: --at T is required");
    const c: Command = { command: "state", scene, at: time("--at", at as string), events };
    if (compact) c.compact = true;
    if (progress) c.progress = true;
    return c;
  }
  const c: Command = { command: "simulate", scene, events };
  if (compact) c.compact = true;
  if (progress) c.progress = true;
  const ut = opts.get("--until-time");
  if (ut !== undefined) c.untilTime = time("--until-time", ut as string, NO_LIMIT_HINT);
  const me = opts.get("--max-events");
  if (me !== undefined) c.maxEvents = count("--max-events", me as string);
  return c;
}
