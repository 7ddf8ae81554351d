/**
 * Helpers of the package tests: pack @chapgame/engine the way `npm publish` would (its built dist/,
 * scripts off: `npm test` has just built it; built here only when dist/ is missing), list the
 * tarball's real contents, and run npm and node in a clean environment.
 *
 * The environment is the caller's minus every npm_* variable: under `npm test` npm exports its
 * config (npm_config_local_prefix=<repo> among them), and a child `npm install` would obey it and
 * install into the repository instead of the temporary project. npm's cache and user config are
 * private temporary ones, so nothing depends on (or writes to) the machine's ~/.npm.
 */
import { execFileSync, spawnSync } from "node:child_process";
import { existsSync, mkdirSync, mkdtempSync, readFileSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";

export const repoRoot = resolve(import.meta.dirname, "../..");
export const enginePkg = join(repoRoot, "packages/engine");
export const tscBin = join(repoRoot, "node_modules/typescript/bin/tsc");

export interface Run {
  code: number | null;
  stdout: string;
  stderr: string;
}

/** process.env without npm's exported config, NODE_PATH or NODE_OPTIONS. */
export function cleanEnv(): NodeJS.ProcessEnv {
  const env: NodeJS.ProcessEnv = {};
  for (const [k, v] of Object.entries(process.env))
    if (!/^npm_/i.test(k) && k !== "NODE_PATH" && k !== "NODE_OPTIONS") env[k] = v;
  return env;
}

/** A new directory under the OS temporary directory (outside the repository). */
export function tempDir(prefix: string): string {
  return mkdtempSync(join(tmpdir(), prefix));
}

/** npm settings private to `dir`: an empty user config and a cache of its own. */
function npmIsolation(dir: string): string[] {
  const userconfig = join(dir, ".npmrc-empty");
  if (!existsSync(userconfig)) writeFileSync(userconfig, "");
  mkdirSync(join(dir, ".npm-cache"), { recursive: true });
  return ["--userconfig", userconfig, "--cache", join(dir, ".npm-cache")];
}

/** Runs a command to completion; never throws on a non-zero exit. */
export function run(cmd: string, args: string[], cwd: string, input = ""): Run {
  const r = spawnSync(cmd, args, { cwd, env: cleanEnv(), encoding: "utf8", input, timeout: 60_000 });
  return { code: r.status, stdout: r.stdout ?? "", stderr: r.stderr ?? String(r.error ?? "") };
}

/** Runs npm with private settings kept in `scratch`; never throws on a non-zero exit. */
export function npm(args: string[], cwd: string, scratch: string): Run {
  return run("npm", [...args, ...npmIsolation(scratch)], cwd);
}

/** Runs a node script file (or `-e` code) in `cwd` with extra flags. */
export function node(args: string[], cwd: string, input = ""): Run {
  return run(process.execPath, args, cwd, input);
}

export interface Packed {
  /** Where the tarball was written (a temporary directory). */
  dir: string;
  tarball: string;
  /** Every file in the tarball, relative to the package root (tar's `package/` prefix removed). */
  files: string[];
  /** The tarball unpacked: its package root. */
  unpacked: string;
  /** npm's own report of the pack: packed and unpacked size in bytes. */
  size: number;
  unpackedSize: number;
}

/** `npm pack --ignore-scripts` of the engine into a new temporary directory. */
export function packEngine(): Packed {
  if (!existsSync(join(enginePkg, "dist/index.js")))
    execFileSync("npm", ["run", "build"], { cwd: enginePkg, env: cleanEnv(), stdio: "ignore" });
  const dir = tempDir("chapgame-pack-");
  const r = npm(["pack", "--ignore-scripts", "--json", "--pack-destination", dir], enginePkg, dir);
  if (r.code !== 0) throw new Error(`npm pack failed (${r.code}): ${r.stderr}`);
  const report = (JSON.parse(r.stdout) as { filename: string; size: number; unpackedSize: number }[])[0];
  if (!report) throw new Error(`npm pack printed no report: ${r.stdout}`);
  const tarball = join(dir, report.filename);
  const list = run("tar", ["-tzf", tarball], dir);
  if (list.code !== 0) throw new Error(`tar -tzf failed: ${list.stderr}`);
  const files = list.stdout
    .split("\n")
    .filter((l) => l !== "" && !l.endsWith("/"))
    .map((l) => l.replace(/^package\//, ""))
    .sort();
  const out = join(dir, "unpacked");
  mkdirSync(out);
  const x = run("tar", ["-xzf", tarball, "-C", out], dir);
  if (x.code !== 0) throw new Error(`tar -xzf failed: ${x.stderr}`);
  const unpacked = join(out, "package");
  return { dir, tarball, files, unpacked, size: report.size, unpackedSize: report.unpackedSize };
}

/** One file of the tarball, as text. */
export function readPacked(packed: Packed, file: string): string {
  return readFileSync(join(packed.unpacked, file), "utf8");
}

/** The engine's package.json as committed. */
export function engineManifest(): Record<string, unknown> {
  return JSON.parse(readFileSync(join(enginePkg, "package.json"), "utf8")) as Record<string, unknown>;
}
