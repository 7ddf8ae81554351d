/**
 * runCli(argv, io): the `chapgame` command, with all input and output through `io` (so it can be
 * tested in-process and main.ts stays a thin wrapper). Returns the exit status: 0 success, 2 invalid
 * input (bad arguments, unreadable or invalid scene, a scene the exact model cannot continue), 1 an
 * internal error. Errors are one line on stderr, without a stack trace.
 */
import { SceneError } from "../scene/errors.js";
import { parseScene } from "../scene/parse.js";
import { ChapgameError, SimulationError } from "../sim/errors.js";
import { Timeline } from "../timeline/timeline.js";
import type { ProlongResult } from "../timeline/types.js";
import { type Command, parseArgs, USAGE, UsageError } from "./args.js";

export interface CliIO {
  /** Contents of a file ("-" = standard input); throws when it cannot be read. */
  readFile(path: string): string;
  stdout(text: string): void;
  stderr(text: string): void;
  /** show progress on stderr (when stderr is a terminal) */
  progress: boolean;
}

/** Events computed between two progress lines. */
const PROGRESS_EVERY_EVENTS = 200_000;

/** JSON with infinite values written "Infinity" (as in scene files). */
function toJson(value: unknown): string {
  return JSON.stringify(value, (_k, v) => (v === Number.POSITIVE_INFINITY ? "Infinity" : v), 2);
}

function result(tl: Timeline, time: number, withLog: boolean): Record<string, unknown> {
  const c = tl.counts();
  const out: Record<string, unknown> = {
    time,
    events: c.bodyBody + c.bodyLine + c.bodyPoint + c.stop,
    counts: { bodyBody: c.bodyBody, bodyLine: c.bodyLine, bodyPoint: c.bodyPoint, stop: c.stop },
    bodies: tl
      .stateAt(time)
      .bodies.map((b) => ({ id: b.id, x: b.x, y: b.y, vx: b.vx, vy: b.vy, r: b.r, m: b.m, mu: b.mu })),
  };
  if (withLog) out.log = tl.eventsBetween(0, time);
  return out;
}

function simulate(tl: Timeline, cmd: Extract<Command, { command: "simulate" }>, io: CliIO): number {
  const until: { time?: number; events?: number } = {};
  if (cmd.untilTime !== undefined) until.time = cmd.untilTime;
  if (cmd.maxEvents !== undefined) until.events = cmd.maxEvents;
  let reason: ProlongResult["reason"];
  if (io.progress) {
    let total = 0;
    for (;;) {
      const r = tl.prolongSlice(until, PROGRESS_EVERY_EVENTS);
      total += r.events;
      if (r.done) {
        reason = r.reason ?? "idle";
        break;
      }
      io.stderr(`\rchapgame: t = ${r.horizon.toPrecision(6)}, ${total} events`);
    }
    io.stderr("\r\x1b[K");
  } else reason = tl.prolong(until).reason;
  return reason === "idle" ? tl.lastLoggedTime() : tl.horizon;
}

export function runCli(argv: readonly string[], io: CliIO): number {
  try {
    const cmd = parseArgs(argv);
    if (cmd.command === "help") {
      io.stdout(`${USAGE}\n`);
      return 0;
    }
    let text: string;
    try {
      text = io.readFile(cmd.scene);
    } catch (e) {
      throw new UsageError(`cannot read ${cmd.scene}: ${(e as Error).message.split("\n")[0]}`);
    }
    const scene = parseScene(text);
    const tl = Timeline.fromScene(scene, { history: cmd.events, compute: false });
    let time: number;
    if (cmd.command === "state") {
      tl.prolongTo(cmd.at);
      time = cmd.at;
    } else time = simulate(tl, cmd, io);
    io.stdout(`${toJson(result(tl, time, cmd.events))}\n`);
    return 0;
  } catch (e) {
    if (e instanceof UsageError || e instanceof SceneError || e instanceof ChapgameError) {
      io.stderr(`chapgame: ${e.message}\n`);
      return 2;
    }
    if (e instanceof SimulationError) {
      io.stderr(`chapgame: cannot simulate this scene: ${e.message}\n`);
      return 2;
    }
    io.stderr(`chapgame: internal error: ${e instanceof Error ? e.message : String(e)}\n`);
    return 1;
  }
}
