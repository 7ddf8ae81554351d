/**
 * For tests that run the built engine (dist/) in a child process: `buildEngineIfStale(file)` runs the
 * engine's `npm run build` when `file` (a path under packages/engine/dist) is missing or older than
 * the newest file of packages/engine/src, so such a test never runs stale code. tsc writes dist/
 * even when a type error elsewhere fails the build: the build's failure is thrown only when `file`
 * is still missing after it.
 */
import { execFileSync } from "node:child_process";
import { existsSync, readdirSync, statSync } from "node:fs";
import { join, resolve } from "node:path";

/** packages/engine. */
export const enginePackage = resolve(import.meta.dirname, "..");

/** Newest modification time of the files under `dir`. */
function newest(dir: string): number {
  let t = 0;
  for (const e of readdirSync(dir, { withFileTypes: true })) {
    const p = join(dir, e.name);
    t = Math.max(t, e.isDirectory() ? newest(p) : statSync(p).mtimeMs);
  }
  return t;
}

export function buildEngineIfStale(file: string): void {
  if (existsSync(file) && statSync(file).mtimeMs >= newest(join(enginePackage, "src"))) return;
  try {
    execFileSync("npm", ["run", "build"], { cwd: enginePackage, stdio: "ignore" });
  } catch (e) {
    if (!existsSync(file)) throw e;
  }
}
