/**
 * writeResult(tl, time, write, format): the CLI's JSON result (time, why the run stopped when
 * `format.end` is given, events, counts, the bodies at `time`, and with `format.log` the event
 * log up to `time`), pretty-printed exactly as
 * JSON.stringify(result, …, 2) would, but written in pieces: the log goes out `chunk` events at a
 * time (Timeline.eventRange), so a long log is never one string (V8 caps a string at about 2^29
 * characters: a 1.7M-event log) nor one array of objects. With `compact`, the same object without
 * indentation, the log one event per line (about half the size, and a reader can take it line by
 * line). Infinite numbers are written "Infinity"
 * as in scene files, and "-Infinity" and NaN likewise, should one come (a position overflowed to
 * -Infinity after a long fall before times past TIME_MAX were refused: sim/timeLimit.ts).
 * writePath(result, write, compact): the `path` command's JSON, the same way (see there).
 * resultSteps and pathSteps are the same writers as generators that yield after each piece of the
 * log (each LOG_CHUNK_EVENTS events or path pieces): the CLI pauses there (slices.ts), so a signal
 * handler can run while a long result is written (writing.ts decides what a signal then does).
 */

import type { PathPiece } from "../timeline/path.js";
import type { Timeline } from "../timeline/timeline.js";
import type { LogEvent, ProlongResult } from "../timeline/types.js";
import { runToEnd } from "./slices.js";

/** Log events per written piece. */
const LOG_CHUNK_EVENTS = 4096;

/** JSON has no infinities or NaN (JSON.stringify writes null): they are written as strings. */
function nonFinite(_key: string, v: unknown): unknown {
  if (typeof v !== "number" || Number.isFinite(v)) return v;
  return Number.isNaN(v) ? "NaN" : v > 0 ? "Infinity" : "-Infinity";
}

function toJson(value: unknown, compact = false): string {
  return compact ? JSON.stringify(value, nonFinite) : JSON.stringify(value, nonFinite, 2);
}

/** `json` (a pretty-printed value) indented by `pad` more spaces on every line after the first. */
function indent(json: string, pad: string): string {
  return json.replaceAll("\n", `\n${pad}`);
}

/**
 * Why a run stopped: the Timeline's reason ("time", "events", "idle"), "until" when the scene's own
 * bound (its actions' untils) stopped it, "interrupted" by a signal, or "error" when the engine
 * could not continue (a Zeno state); `error` then says why. After an interrupt or an error the
 * result is the history up to where it stopped.
 */
export type RunEnd =
  | { reason: ProlongResult["reason"] | "until" | "interrupted" }
  | { reason: "error"; error: string };

/** How writeResult writes: with the log, why the run ended, without indentation, log piece size. */
export interface ResultFormat {
  log: boolean;
  end?: RunEnd | undefined;
  compact?: boolean | undefined;
  chunk?: number | undefined;
}

export function writeResult(
  tl: Timeline,
  time: number,
  write: (text: string) => void,
  format: ResultFormat,
): void {
  runToEnd(resultSteps(tl, time, write, format));
}

/** writeResult as a generator that yields after each written piece of the log (see the header). */
export function* resultSteps(
  tl: Timeline,
  time: number,
  write: (text: string) => void,
  format: ResultFormat,
): Generator<void, void, void> {
  const { log: withLog, end, compact = false, chunk = LOG_CHUNK_EVENTS } = format;
  const c = tl.counts();
  const head = {
    time,
    ...end,
    events: c.bodyBody + c.bodyLine + c.bodyPoint + c.stop,
    counts: { bodyBody: c.bodyBody, bodyLine: c.bodyLine, bodyPoint: c.bodyPoint, stop: c.stop },
    bodies: tl
      .stateAt(time)
      .bodies.map((b) => ({ id: b.id, x: b.x, y: b.y, vx: b.vx, vy: b.vy, r: b.r, m: b.m, mu: b.mu })),
  };
  const text = toJson(head, compact);
  if (!withLog) {
    write(`${text}\n`);
    return;
  }
  // Pretty: the log indented like JSON.stringify(…, 2). Compact: one event per line.
  const pad = compact ? "" : "    ";
  write(compact ? `${text.slice(0, -1)},"log":[` : `${text.slice(0, -2)},\n  "log": [`); // without the closing "}"
  let first = true;
  for (let i = 0; i < tl.eventCount; i += chunk) {
    const events: LogEvent[] = tl.eventRange(i, i + chunk);
    const kept = events.filter((e) => e.time <= time); // the log is in time order
    if (kept.length > 0) {
      const lead = first ? `\n${pad}` : `,\n${pad}`;
      write(lead + kept.map((e) => indent(toJson(e, compact), pad)).join(`,\n${pad}`));
      first = false;
    }
    if (kept.length < events.length) break;
    yield;
  }
  if (compact) write(first ? "]}\n" : "\n]}\n");
  else write(first ? "]\n}\n" : "\n  ]\n}\n");
}

/** What writePath writes: body `id`'s pieces over [from, to], and why the run stopped early if it did. */
export interface PathResult {
  id: string;
  from: number;
  to: number;
  end?: { reason: "interrupted" } | { reason: "error"; error: string } | undefined;
  pieces: readonly PathPiece[];
}

/**
 * The `path` command's JSON: id, from, to (and reason, error after an early stop), then "pieces",
 * written one piece at a time (a long path is never one string). Pretty-printed as
 * JSON.stringify(result, …, 2) would; with `compact`, without indentation and one piece per line.
 * Each piece's keys in a fixed order: from, until, t0, x0, y0, vx, vy, ax, ay, tStop.
 */
export function writePath(r: PathResult, write: (text: string) => void, compact = false): void {
  runToEnd(pathSteps(r, write, compact));
}

/** writePath as a generator that yields after each LOG_CHUNK_EVENTS pieces (see the header). */
export function* pathSteps(
  r: PathResult,
  write: (text: string) => void,
  compact = false,
): Generator<void, void, void> {
  const text = toJson({ id: r.id, from: r.from, to: r.to, ...r.end }, compact);
  const pad = compact ? "" : "    ";
  write(compact ? `${text.slice(0, -1)},"pieces":[` : `${text.slice(0, -2)},\n  "pieces": [`);
  for (let i = 0; i < r.pieces.length; i++) {
    const p = r.pieces[i] as PathPiece;
    const piece = {
      from: p.from,
      until: p.until,
      t0: p.t0,
      x0: p.x0,
      y0: p.y0,
      vx: p.vx,
      vy: p.vy,
      ax: p.ax,
      ay: p.ay,
      tStop: p.tStop,
    };
    write(`${i === 0 ? "\n" : ",\n"}${pad}${indent(toJson(piece, compact), pad)}`);
    if ((i + 1) % LOG_CHUNK_EVENTS === 0) yield;
  }
  const empty = r.pieces.length === 0;
  if (compact) write(empty ? "]}\n" : "\n]}\n");
  else write(empty ? "]\n}\n" : "\n  ]\n}\n");
}
