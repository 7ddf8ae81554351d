#!/usr/bin/env node
import { readBounded } from "./readBounded.js";
/**
 * The `chapgame` bin: runs runCli with the real process (arguments, files, stdout, stderr).
 * The scene is read in chunks (readBounded.ts), so a source that never ends (/dev/zero, a fifo) is
 * refused once it gives more than a string holds, and a long read shows its progress.
 * Standard output is written with blocking writes (fs.writeSync), so a slow reader (`| gzip`) makes
 * the bin wait instead of queueing the whole output in memory (a 2M-event log held 2 GB). A reader
 * that closes it early (`chapgame ... | head`) ends the output quietly: the broken pipe is not an
 * error of the run (no stack trace, the run's exit status).
 * SIGINT (Ctrl-C) and SIGTERM during the computation stop it: the run computes in slices with a
 * setImmediate pause between them (runCliInterruptible), so the handler runs, and the result up to
 * there is printed with "reason": "interrupted"; the exit status is 130 (SIGINT) or 143 (SIGTERM).
 * The handlers are installed when the computation starts and stay until the bin ends: the result is
 * written in pieces with the same pause between them, so a signal while it is written finishes it
 * (a second one stops it at once; writing.ts). Before the computation (reading standard input,
 * parsing) a signal ends the process at once, as without them (a handler cannot run while a
 * synchronous read waits, so one installed then swallowed the signal). Each signal is reported
 * once, in the order received.
 * The computation is paced by performance.now, a monotonic clock read between two slices of it
 * (cadence.ts: a progress line about once a second, slices of about 0.1 s): a timer (setInterval)
 * could not fire while a slice runs synchronously, and would only set a flag read at the same place.
 * The clock is the CLI's: the engine's own code reads none (test/exactArithmetic.test.ts allows host
 * objects in src/cli alone), and what is computed does not depend on it, only when a line is written
 * to stderr does.
 * The engine is built without Node's types (it must not depend on Node), so the few Node APIs used
 * here are typed locally and node:fs is loaded by a dynamic import.
 */
import { OutputError, runCliInterruptible } from "./run.js";
import type { InterruptSignal } from "./slices.js";
import { decodeUtf8 } from "./utf8.js";

interface NodeProcess {
  argv: string[];
  stderr: { write(text: string): unknown; isTTY?: boolean };
  exitCode?: number;
  on(signal: InterruptSignal, listener: () => void): unknown;
  removeListener(signal: InterruptSignal, listener: () => void): unknown;
}
interface NodeFs {
  readFileSync(path: string | number | object, encoding: "utf8"): string;
  readFileSync(path: string | number): Uint8Array;
  writeSync(fd: number, data: Uint8Array, offset: number, length: number): number;
  openSync(path: string, flags: "r"): number;
  readSync(fd: number, buffer: Uint8Array, offset: number, length: number, position: null): number;
  closeSync(fd: number): void;
}
interface NodeError {
  code?: string;
}
interface NodeBuffer {
  from(text: string, encoding: "utf8"): Uint8Array;
}

const proc = (globalThis as unknown as { process: NodeProcess }).process;
const fsModule = "node:fs";
const fs = (await import(fsModule)) as NodeFs;

/** The package's version from its package.json (two folders up from dist/cli), or undefined. */
function packageVersion(): string | undefined {
  try {
    const { URL } = globalThis as unknown as { URL: new (path: string, base: string) => object };
    const url = new URL("../../package.json", (import.meta as unknown as { url: string }).url);
    const v = (JSON.parse(fs.readFileSync(url, "utf8")) as { version?: unknown }).version;
    return typeof v === "string" ? v : undefined;
  } catch {
    return undefined;
  }
}

/** The bytes of the scene file `path` ("-": standard input), read in chunks and refused as soon as
 *  they pass what a string holds (readBounded.ts: a device such as /dev/zero never ends). */
function readSource(path: string, progress?: (bytes: number) => void): Uint8Array {
  const fd = path === "-" ? 0 : fs.openSync(path, "r");
  try {
    return readBounded((buffer) => fs.readSync(fd, buffer, 0, buffer.length, null), progress);
  } finally {
    if (fd !== 0) fs.closeSync(fd);
  }
}

const { Buffer } = globalThis as unknown as { Buffer: NodeBuffer };
let stdoutClosed = false;

/** Writes all of `text` to standard output, waiting while a non-blocking pipe is full (EAGAIN); after
 *  EPIPE (the reader is gone) it writes nothing more. Any other error (a full disk) is thrown as an
 *  OutputError (exit 1, "cannot write the result"). */
function writeOut(text: string): void {
  const bytes = Buffer.from(text, "utf8");
  let done = 0;
  while (!stdoutClosed && done < bytes.length) {
    try {
      done += fs.writeSync(1, bytes, done, bytes.length - done);
    } catch (e) {
      const code = (e as NodeError).code;
      if (code === "EPIPE") stdoutClosed = true;
      else if (code !== "EAGAIN") throw new OutputError((e as Error).message);
    }
  }
}

/** The interrupting signals received and not yet reported to the run, oldest first. */
const received: InterruptSignal[] = [];
const onSignal = {
  SIGINT: () => {
    received.push("SIGINT");
  },
  SIGTERM: () => {
    received.push("SIGTERM");
  },
};
const signals = ["SIGINT", "SIGTERM"] as const;
let catching = false;
/** Catch the signals (the computation starts). */
function startCatching(): void {
  if (catching) return;
  catching = true;
  for (const s of signals) proc.on(s, onSignal[s]);
}
/** Back to the default action of the signals (end the process at once). */
function stopCatching(): void {
  if (!catching) return;
  catching = false;
  for (const s of signals) proc.removeListener(s, onSignal[s]);
}

const { setImmediate, performance } = globalThis as unknown as {
  setImmediate: (callback: () => void) => unknown;
  performance: { now(): number };
};
try {
  proc.exitCode = await runCliInterruptible(
    proc.argv.slice(2),
    {
      // bytes that are not UTF-8 are refused, not replaced by U+FFFD (utf8.ts)
      readFile: (path, progress) => decodeUtf8(readSource(path, progress)),
      stdout: writeOut,
      stderr: (text) => proc.stderr.write(text),
      progress: proc.stderr.isTTY === true,
      computing: startCatching,
      now: () => performance.now(),
      ...versionField(),
    },
    {
      pause: () => new Promise<void>((resume) => setImmediate(resume)),
      interrupted: () => received.shift() ?? null,
    },
  );
} finally {
  stopCatching();
}

function versionField(): { version?: string } {
  const version = packageVersion();
  return version === undefined ? {} : { version };
}
