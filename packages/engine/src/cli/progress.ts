/**
 * Progress of the CLI's work on stderr (never on stdout): one updating line on a terminal
 * ("terminal": each line starts with \r, ends with an erase when it is shorter than the one it
 * replaces, and the line is erased before anything else is written), one line each with --progress
 * when stderr is not a terminal ("lines"), or nothing ("off").
 * While computing, about once a second (cadence.ts: the first line half a second into the
 * computation, then one a second, on the clock CliIO.now; without a clock every 200,000 events):
 *   chapgame: t = <horizon>[ of <time goal>], <events>[ of <event goal>] events[, <k> of <n> actions applied]
 * the time goal being the absolute time the run computes to (--until-time, --at, --to, check's last
 * action), the event goal --max-events, and the actions part shown while some action of the scene is
 * still to come. A long scene (LONG_SCENE_CHARS or more) also says what it does before the
 * computation (reading and checking the file, building the scene at t = 0: seconds for a million
 * bodies), then shows the line above once at the start. A long read (a big file, a slow pipe, a
 * device) shows the bytes read so far on the same cadence (without a clock, every READ_REPORT_BYTES):
 *   chapgame: reading the scene: <megabytes> MB so far ProgressLine.io is the command's CliIO with
 * that erase in front of every write.
 */
import type { SceneFile, Until } from "../scene/types.js";
import type { Timeline } from "../timeline/timeline.js";
import type { ProlongResult } from "../timeline/types.js";
import { type Cadence, clockCadence, eventCadence } from "./cadence.js";
import type { CliIO } from "./io.js";
import { computeSlices, type Progress } from "./slices.js";

/** How progress is shown on stderr: one updating line (a terminal), one line each, or not at all. */
export type ProgressMode = "terminal" | "lines" | "off";

/** The mode for a command: a terminal shows progress by itself, else only --progress does. */
export function progressMode(io: CliIO, cmd: { progress?: boolean }): ProgressMode {
  return io.progress ? "terminal" : cmd.progress === true ? "lines" : "off";
}

/** A scene text at least this long (about 65,000 bodies, a second or more to read and build) has
 *  its steps before the computation announced. */
export const LONG_SCENE_CHARS = 10_000_000;

/** Bytes read between two lines on a long read when no clock is given. */
export const READ_REPORT_BYTES = 100_000_000;

/** What a progress line names as the run's goal: an absolute time, a number of events. */
export interface ShownGoal {
  time?: number | undefined;
  events?: number | undefined;
}

/** How many of the sorted `times` are <= t. */
function countUpTo(times: Float64Array, t: number): number {
  let lo = 0;
  let hi = times.length;
  while (lo < hi) {
    const mid = (lo + hi) >>> 1;
    if ((times[mid] as number) <= t) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}

/** A line each READ_REPORT_BYTES bytes read (readingBytes without a clock). */
function bytesCadence(): Cadence {
  let next = READ_REPORT_BYTES;
  return {
    due: (bytes) => {
      if (bytes < next) return false;
      while (next <= bytes) next += READ_REPORT_BYTES;
      return true;
    },
  };
}

/** The progress line of one command (see the header). */
export class ProgressLine {
  /** The command's CliIO: stdout and stderr erase a progress line first (on a terminal). */
  readonly io: CliIO;
  private mode: ProgressMode = "off";
  private long = false;
  private scene: SceneFile | null = null;
  /** the scene's action times, sorted (made at the first line that counts them) */
  private times: Float64Array | null = null;
  /** length of the text on the terminal's line (0: none) */
  private shown = 0;
  /** the read's cadence and when it started (readingBytes), once it has begun */
  private read: { cadence: Cadence; start: number } | null = null;

  constructor(private readonly raw: CliIO) {
    const io: CliIO = {
      readFile: (path, progress) => raw.readFile(path, progress),
      stdout: (text) => {
        this.erase();
        raw.stdout(text);
      },
      stderr: (text) => {
        this.erase();
        raw.stderr(text);
      },
      progress: raw.progress,
    };
    if (raw.version !== undefined) io.version = raw.version;
    if (raw.computing !== undefined) io.computing = raw.computing;
    if (raw.computed !== undefined) io.computed = raw.computed;
    if (raw.now !== undefined) io.now = raw.now;
    this.io = io;
  }

  /** Shows progress the command's way (progressMode), once its arguments are known. */
  start(mode: ProgressMode): void {
    this.mode = mode;
  }

  /** `bytes` of the scene are read so far: a line when one is due (see the header). */
  readingBytes(bytes: number): void {
    if (this.mode === "off") return;
    const clock = this.raw.now;
    this.read ??= {
      cadence: clock === undefined ? bytesCadence() : clockCadence(),
      start: clock === undefined ? Number.NaN : clock(),
    };
    const elapsed = clock === undefined ? Number.NaN : clock() - this.read.start;
    if (this.read.cadence.due(bytes, elapsed))
      this.write(`chapgame: reading the scene: ${(bytes / 1e6).toFixed(1)} MB so far`);
  }

  /** The scene's text is read: a long one says it is being checked. */
  reading(text: string): void {
    this.long = text.length >= LONG_SCENE_CHARS;
    if (this.long)
      this.write(`chapgame: reading the scene (${(text.length / 1e6).toFixed(1)} million characters)`);
  }

  /** The scene is parsed and checked: a long one says its actions at t = 0 are being applied. */
  building(scene: SceneFile): void {
    this.scene = scene;
    this.times = null;
    if (this.long) this.write(`chapgame: building the scene at t = 0 (${scene.actions.length} actions)`);
  }

  /** Computes `until` from the horizon in slices (slices.ts) with progress lines naming `goal`
   *  (until by default); returns why the run ended. */
  compute(
    tl: Timeline,
    until: Until,
    goal: ShownGoal = until,
  ): Generator<void, ProlongResult["reason"], void> {
    const clock = this.raw.now;
    if (this.mode === "off") return computeSlices(tl, until, null, clock);
    if (this.long) this.write(this.line(tl.horizon, 0, goal));
    const cadence = clock === undefined ? eventCadence() : clockCadence();
    const progress: Progress = {
      due: (events, elapsed) => cadence.due(events, elapsed),
      report: (horizon, events) => this.write(this.line(horizon, events, goal)),
      // erase the line, also when the run ends in an error or an interrupt (printed after this)
      end: () => this.erase(),
    };
    return computeSlices(tl, until, progress, clock);
  }

  /** The line at `horizon` after `events` events (see the header). */
  private line(horizon: number, events: number, goal: ShownGoal): string {
    const time = goal.time === undefined ? "" : ` of ${goal.time}`;
    const count = goal.events === undefined ? "" : ` of ${goal.events}`;
    return `chapgame: t = ${horizon.toPrecision(6)}${time}, ${events}${count} events${this.actionsPart(horizon)}`;
  }

  /** ", k of n actions applied" while an action of the scene comes after `horizon`, else "". */
  private actionsPart(horizon: number): string {
    if (this.scene === null) return "";
    this.times ??= Float64Array.from(this.scene.actions, (a) => a.time).sort();
    const n = this.times.length;
    const k = countUpTo(this.times, horizon);
    return k < n ? `, ${k} of ${n} actions applied` : "";
  }

  /** Shows `line`: in place of the last one on a terminal, else on a line of its own. */
  private write(line: string): void {
    if (this.mode === "off") return;
    if (this.mode === "lines") {
      this.raw.stderr(`${line}\n`);
      return;
    }
    this.raw.stderr(`\r${line}${line.length < this.shown ? "\x1b[K" : ""}`);
    this.shown = line.length;
  }

  /** Erases the terminal's progress line, if one is shown. */
  private erase(): void {
    if (this.shown === 0) return;
    this.shown = 0;
    this.raw.stderr("\r\x1b[K");
  }
}
