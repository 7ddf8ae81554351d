#!/usr/bin/env node
/**
 * The `chapgame` bin: runs runCli with the real process (arguments, files, stdout, stderr).
 * A reader that closes standard output early (`chapgame ... | head`) ends the output quietly: the
 * broken pipe is not an error of the run (no stack trace, the run's exit status).
 * The engine is built without Node's types (it must not depend on Node), so the few Node APIs used
 * here are typed locally and node:fs is loaded by a dynamic import.
 */
import { runCli } from "./run.js";

interface NodeStream {
  write(text: string): unknown;
  on(event: "error", listener: (e: { code?: string; message?: string }) => void): unknown;
}
interface NodeProcess {
  argv: string[];
  stdout: NodeStream;
  stderr: { write(text: string): unknown; isTTY?: boolean };
  exitCode?: number;
}
interface NodeFs {
  readFileSync(path: string | number | object, encoding: "utf8"): string;
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

let stdoutClosed = false;
proc.stdout.on("error", (e) => {
  if (e.code === "EPIPE") {
    stdoutClosed = true;
    return;
  }
  proc.stderr.write(`chapgame: cannot write the output: ${e.message ?? String(e)}\n`);
  proc.exitCode = 1;
});

proc.exitCode = runCli(proc.argv.slice(2), {
  readFile: (path) => fs.readFileSync(path === "-" ? 0 : path, "utf8"),
  stdout: (text) => {
    if (!stdoutClosed) proc.stdout.write(text);
  },
  stderr: (text) => proc.stderr.write(text),
  progress: proc.stderr.isTTY === true,
  ...versionField(),
});

function versionField(): { version?: string } {
  const version = packageVersion();
  return version === undefined ? {} : { version };
}
