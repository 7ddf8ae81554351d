// The committed launcher of the `chapgame` bin (packages/engine/src/cli/launcher.mjs), run from a
// copy beside a dist/ of our making: with no dist/cli/main.js it says the engine is not built; with
// a main.js that imports a missing module it names that module (review of session 29: it said "not
// built yet" for a build stopped half-way); with a main.js that loads, it runs it.
import { spawnSync } from "node:child_process";
import { copyFileSync, mkdirSync, mkdtempSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { afterEach, describe, expect, it } from "vitest";

const launcher = join(import.meta.dirname, "..", "..", "packages", "engine", "src", "cli", "launcher.mjs");
const made: string[] = [];
afterEach(() => {
  for (const d of made.splice(0)) rmSync(d, { recursive: true, force: true });
});

/** Runs a copy of the launcher in a package folder whose dist/cli holds `files` (name → text). */
function launch(files: Record<string, string>): { status: number | null; stderr: string; stdout: string } {
  const root = mkdtempSync(join(tmpdir(), "chapgame-launcher-"));
  made.push(root);
  mkdirSync(join(root, "src", "cli"), { recursive: true });
  mkdirSync(join(root, "dist", "cli"), { recursive: true });
  copyFileSync(launcher, join(root, "src", "cli", "launcher.mjs"));
  writeFileSync(join(root, "package.json"), '{ "type": "module" }\n'); // as the engine's package.json says
  for (const [name, text] of Object.entries(files)) writeFileSync(join(root, "dist", "cli", name), text);
  const r = spawnSync(process.execPath, [join(root, "src", "cli", "launcher.mjs")], { encoding: "utf8" });
  return { status: r.status, stderr: r.stderr, stdout: r.stdout };
}

describe("the chapgame launcher", () => {
  it("says the engine is not built when dist/cli/main.js is missing", () => {
    expect(launch({})).toEqual({
      status: 1,
      stderr: "chapgame: the engine is not built yet: run `npm run build` first\n",
      stdout: "",
    });
  });

  it("names the missing module when main.js is there but one it imports is not", () => {
    const r = launch({ "main.js": 'import "./scene.js";\n' });
    expect(r.status).toBe(1);
    expect(r.stderr).toMatch(
      /^chapgame: the engine's build is incomplete or stale \(Cannot find module '.*scene\.js'/,
    );
    expect(r.stderr).toMatch(/run `npm run build` again\n$/);
  });

  it("runs main.js when it loads", () => {
    expect(launch({ "main.js": 'process.stdout.write("ran\\n");\n' })).toEqual({
      status: 0,
      stderr: "",
      stdout: "ran\n",
    });
  });

  it("lets other errors of main.js through (not taken for a missing build)", () => {
    const r = launch({ "main.js": 'throw new Error("boom");\n' });
    expect(r.status).not.toBe(0);
    expect(r.stderr).toContain("boom");
    expect(r.stderr).not.toContain("not built");
  });
});
