/**
 * Command-line arguments of the `chapgame` bin, parsed into a Command (pure; no process access).
 *   chapgame simulate SCENE [--until-time T] [--max-events N] [--events]
 *   chapgame state SCENE --at T [--events]
 *   chapgame --help
 * Options take their value as the next argument or after "=". Invalid arguments throw UsageError
 * with a one-line message.
 */

export class UsageError extends Error {
  constructor(message: string) {
    super(message);
    this.name = "UsageError";
  }
}

export type Command =
  | { command: "help" }
  | { command: "simulate"; scene: string; untilTime?: number; maxEvents?: number; events: boolean }
  | { command: "state"; scene: string; at: number; events: boolean };

export const USAGE = `Usage:
  chapgame simulate SCENE [--until-time T] [--max-events N] [--events]
      Run the scene's actions and simulate until time T, N events (collisions and stops), or no
      event is left, whichever comes first; print the bodies then as JSON.
  chapgame state SCENE --at T [--events]
      Print the bodies at time T as JSON.
  chapgame --help

SCENE is a scene file (format "chapgame", version 1), or - for standard input.
--events adds the event log. Exit status: 0 success, 2 invalid input, 1 internal error.`;

function time(name: string, v: string): number {
  const t = Number(v);
  if (v.trim() === "" || !Number.isFinite(t) || t < 0)
    throw new UsageError(`${name}: must be a non-negative number, got "${v}"`);
  return t;
}

function count(name: string, v: string): number {
  const n = Number(v);
  if (!/^\d+$/.test(v.trim()) || !Number.isSafeInteger(n))
    throw new UsageError(`${name}: must be a non-negative integer, got "${v}"`);
  return n;
}

export function parseArgs(argv: readonly string[]): Command {
  if (argv.length === 0) throw new UsageError("missing command (try chapgame --help)");
  if (argv.includes("--help") || argv.includes("-h")) return { command: "help" };
  const [cmd, ...rest] = argv;
  if (cmd !== "simulate" && cmd !== "state")
    throw new UsageError(`unknown command "${cmd}" (try chapgame --help)`);
  const positional: string[] = [];
  const opts = new Map<string, string | true>();
  const valued = new Set(["--until-time", "--max-events", "--at"]);
  const allowed = cmd === "simulate" ? ["--until-time", "--max-events", "--events"] : ["--at", "--events"];
  for (let i = 0; i < rest.length; i++) {
    const arg = rest[i] as string;
    if (!arg.startsWith("--")) {
      positional.push(arg);
      continue;
    }
    const eq = arg.indexOf("=");
    const name = eq >= 0 ? arg.slice(0, eq) : arg;
    if (!allowed.includes(name)) throw new UsageError(`unknown option ${name} for ${cmd}`);
    if (opts.has(name)) throw new UsageError(`${name} given twice`);
    if (valued.has(name)) {
      const v = eq >= 0 ? arg.slice(eq + 1) : rest[++i];
      if (v === undefined) throw new UsageError(`${name} needs a value`);
      opts.set(name, v);
    } else {
      if (eq >= 0) throw new UsageError(`${name} takes no value`);
      opts.set(name, true);
    }
  }
  if (positional.length === 0) throw new UsageError(`${cmd}: missing SCENE file`);
  if (positional.length > 1)
    throw new UsageError(`${cmd}: one SCENE file expected, got ${positional.length} arguments`);
  const scene = positional[0] as string;
  const events = opts.has("--events");
  if (cmd === "state") {
    const at = opts.get("--at");
    if (at === undefined) throw new UsageError("state: --at T is required");
    return { command: "state", scene, at: time("--at", at as string), events };
  }
  const c: Command = { command: "simulate", scene, events };
  const ut = opts.get("--until-time");
  if (ut !== undefined) c.untilTime = time("--until-time", ut as string);
  const me = opts.get("--max-events");
  if (me !== undefined) c.maxEvents = count("--max-events", me as string);
  return c;
}
