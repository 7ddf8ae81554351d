/**
 * CliIO: all the input and output of the `chapgame` command (the scene file, stdout, stderr, whether
 * stderr is a terminal, the version, the interrupt hooks, the clock that paces progress lines), so
 * runCli can be tested in-process and main.ts stays a thin wrapper. OutputError: what a CliIO.stdout throws when it cannot write the
 * result (exit status 1, "cannot write the result"), not a bug of the run.
 */

export interface CliIO {
  /** Contents of a file ("-" = standard input); throws when it cannot be read (the bin: code
   *  ERR_STRING_TOO_LONG, as soon as the text read passes what a string holds: readBounded.ts).
   *  `progress`, when given, is told the bytes read so far, now and then during a long read. */
  readFile(path: string, progress?: (bytes: number) => void): string;
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
  /** Called once the computation is over, before the result is written (the bin keeps catching
   *  interrupts while it writes: writing.ts says what one does then). */
  computed?: () => void;
  /** A monotonic clock in milliseconds (the bin: performance.now) that paces the computation
   *  (cadence.ts): progress lines half a second into it, then one a second, and slices of about a
   *  tenth of a second (at most 10,000 events). Without it, a line every 200,000 events and slices
   *  of 10,000. Only when lines are written and where the run can be interrupted depend on it,
   *  never a result. */
  now?: () => number;
}

/** Thrown by a CliIO.stdout that cannot write (a full disk, a closed file): not a bug of the run. */
export class OutputError extends Error {}
