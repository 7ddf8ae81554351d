/**
 * Progress of the CLI's computation on stderr (never on stdout): one updating line on a terminal
 * ("terminal": each line starts with \r, and the line is cleared when the run ends), one line each
 * with --progress when stderr is not a terminal ("lines"), or nothing ("off"). compute(tl, until,
 * mode, io) computes `until` from the horizon in slices (slices.ts) with those lines and returns why
 * it ended.
 */
import type { Until } from "../scene/types.js";
import type { Timeline } from "../timeline/timeline.js";
import type { ProlongResult } from "../timeline/types.js";
import type { CliIO } from "./io.js";
import { computeSlices, type Progress } from "./slices.js";

/** How progress is shown on stderr: one updating line (a terminal), one line each, or not at all. */
export type ProgressMode = "terminal" | "lines" | "off";

/** The mode for a command: a terminal shows progress by itself, else only --progress does. */
export function progressMode(io: CliIO, cmd: { progress?: boolean }): ProgressMode {
  return io.progress ? "terminal" : cmd.progress === true ? "lines" : "off";
}

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
export function compute(
  tl: Timeline,
  until: Until,
  mode: ProgressMode,
  io: CliIO,
): Generator<void, ProlongResult["reason"], void> {
  return computeSlices(tl, until, progressLines(until, mode, io));
}
