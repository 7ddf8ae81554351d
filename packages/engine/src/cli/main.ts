#!/usr/bin/env node
/**
 * The `chapgame` bin: runs runCli with the real process (arguments, files, stdout, stderr).
 * The engine is built without Node's types (it must not depend on Node), so the few Node APIs used
 * here are typed locally and node:fs is loaded by a dynamic import.
 */
import { runCli } from "./run.js";

interface NodeProcess {
  argv: string[];
  stdout: { write(text: string): unknown };
  stderr: { write(text: string): unknown; isTTY?: boolean };
  exitCode?: number;
}
interface NodeFs {
  readFileSync(path: string | number, encoding: "utf8"): string;
}

const proc = (globalThis as unknown as { process: NodeProcess }).process;
const fsModule = "node:fs";
const fs = (await import(fsModule)) as NodeFs;

proc.exitCode = runCli(proc.argv.slice(2), {
  readFile: (path) => fs.readFileSync(path === "-" ? 0 : path, "utf8"),
  stdout: (text) => proc.stdout.write(text),
  stderr: (text) => proc.stderr.write(text),
  progress: proc.stderr.isTTY === true,
});
