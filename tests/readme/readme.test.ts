// The README's usage example is real: extract it, run it with plain Node against the built
// engine (npm test builds first), and check what it says it prints.
import { execFileSync, spawnSync } from "node:child_process";
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { join } from "node:path";
import { expect, it } from "vitest";

const root = join(import.meta.dirname, "..", "..");

it("the README usage example runs and prints the digits of pi it promises", () => {
  const readme = readFileSync(join(root, "README.md"), "utf8");
  const code = /```js\n([\s\S]*?)```/.exec(readme)?.[1];
  expect(code, "README has a ```js example").toBeDefined();
  // Inside the repository so that "@chapgame/engine" resolves through the workspace link.
  const dir = mkdtempSync(join(root, "tests", "readme", ".tmp-"));
  try {
    const file = join(dir, "example.mjs");
    writeFileSync(file, code as string);
    const out = execFileSync(process.execPath, [file], { encoding: "utf8" });
    const lines = out.split("\n");
    expect(lines[0]).toBe("3141");
    expect(out).toContain("time: 3,");
    expect(out).toContain("kind: 'bodyBody'");
    expect(out).toContain("px: 6,");
    expect(out).toContain("id: 'big'");
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

it("the README usage example type-checks as TypeScript (strict) with the two lines the README gives", () => {
  // Review of session 25: pasted into a .mts file, `const log = []` failed tsc --strict (TS7034).
  const readme = readFileSync(join(root, "README.md"), "utf8");
  const code = /```js\n([\s\S]*?)```/.exec(readme)?.[1] as string;
  const typed = /```ts\n([\s\S]*?)```/.exec(readme)?.[1] as string;
  const [importLine, logLine] = typed.trim().split("\n") as [string, string];
  expect(importLine).toMatch(/^import /);
  expect(logLine).toMatch(/^const log: /);
  const ts = code.replace(/^import .*$/m, importLine).replace(/^const log = \[\];$/m, logLine);
  expect(ts).toContain(logLine);
  const dir = mkdtempSync(join(root, "tests", "readme", ".tmp-"));
  const tsc = join(root, "node_modules", "typescript", "bin", "tsc");
  const strict = ["--noEmit", "--strict", "--noUncheckedIndexedAccess", "--exactOptionalPropertyTypes"];
  const target = ["--module", "nodenext", "--moduleResolution", "nodenext", "--target", "es2022"];
  const check = (source: string): string => {
    const file = join(dir, "example.mts");
    writeFileSync(file, source);
    try {
      execFileSync(
        process.execPath,
        [tsc, ...strict, ...target, "--lib", "es2022", "--types", "node", file],
        {
          encoding: "utf8",
        },
      );
      return "";
    } catch (e) {
      return String((e as { stdout?: string }).stdout ?? e);
    }
  };
  try {
    expect(check(code)).toContain("TS7034"); // what the README says the plain example gives
    expect(check(ts)).toBe("");
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

it("the engine package README's examples run and print what the text describes", () => {
  const readme = readFileSync(join(root, "packages", "engine", "README.md"), "utf8");
  const blocks = [...readme.matchAll(/```js\n([\s\S]*?)```/g)].map((m) => m[1] as string);
  expect(blocks.length).toBe(4);
  const dir = mkdtempSync(join(root, "tests", "readme", ".tmp-"));
  try {
    const run = (code: string, name: string): string => {
      const file = join(dir, name);
      writeFileSync(file, code);
      return execFileSync(process.execPath, [file], { encoding: "utf8" });
    };
    const world = run(blocks[0] as string, "world.mjs");
    expect(world).toMatch(/^bodyBody [\d.]+ ball cue$/m);
    expect(world).toMatch(/^stop [\d.]+ cue null$/m);
    expect(world).toMatch(/^bodyLine [\d.]+ ball cushion$/m);
    expect(world).toContain("id: 'cue'");
    // the game loop: 600 frames of 1/60 s, the player's inputs, collisions of the player seen
    expect(run(blocks[1] as string, "loop.mjs")).toBe("10 21 true\n");
    // a Timeline in a game loop that forgets all but its last seconds
    expect(run(blocks[2] as string, "forget.mjs")).toBe("8 20 true\n");
    const timeline = run(blocks[3] as string, "timeline.mjs");
    const lines = timeline.trim().split("\n");
    expect(Number(lines[0]?.split(" ")[0])).toBeGreaterThan(0);
    expect(timeline).toContain("id: 'a'");
    expect(lines.at(-1)).toMatch(/^20 \d+$/);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

it("the engine README's examples type-check as TypeScript against the built types (strict)", () => {
  // Audit of session 20: copied into a .ts file, its loops over arrays of tuples did not compile.
  // Checked with every strict option the repository uses. (The root README's example is plain
  // JavaScript: its `const log = []` has no type to infer; the test above checks its typed form.)
  const readme = readFileSync(join(root, "packages", "engine", "README.md"), "utf8");
  const blocks = [...readme.matchAll(/```js\n([\s\S]*?)```/g)].map((m) => m[1] as string);
  const dir = mkdtempSync(join(root, "tests", "readme", ".tmp-"));
  const tsc = join(root, "node_modules", "typescript", "bin", "tsc");
  const options = [
    "--noEmit",
    "--strict",
    "--noUncheckedIndexedAccess",
    "--exactOptionalPropertyTypes",
    "--module",
    "nodenext",
    "--moduleResolution",
    "nodenext",
    "--target",
    "es2022",
    "--lib",
    "es2022",
    "--types",
    "node",
  ];
  try {
    const files = blocks.map((code, i) => {
      const f = join(dir, `example${i}.mts`);
      writeFileSync(f, code);
      return f;
    });
    let errors = "";
    try {
      execFileSync(process.execPath, [tsc, ...options, ...files], { encoding: "utf8" });
    } catch (e) {
      errors = String((e as { stdout?: string }).stdout ?? e);
    }
    expect(errors).toBe("");
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

it("the engine README's TypeScript examples are whole programs: they type-check (strict) and print what they say", () => {
  // Review of session 29: its two TypeScript samples were fragments (no import, `tl.path("cue")` of
  // a timeline with no body "cue", an undefined `i`): pasted as written, tsc refused both.
  const readme = readFileSync(join(root, "packages", "engine", "README.md"), "utf8");
  const blocks = [...readme.matchAll(/```ts\n([\s\S]*?)```/g)].map((m) => m[1] as string);
  expect(blocks.length).toBe(1);
  const dir = mkdtempSync(join(root, "tests", "readme", ".tmp-"));
  const tsc = join(root, "node_modules", "typescript", "bin", "tsc");
  const strict = ["--strict", "--noUncheckedIndexedAccess", "--exactOptionalPropertyTypes"];
  const nodenext = ["--module", "nodenext", "--moduleResolution", "nodenext", "--target", "es2022"];
  const tscRun = (args: string[]): string => {
    try {
      execFileSync(process.execPath, [tsc, ...args], { encoding: "utf8" });
      return "";
    } catch (e) {
      return String((e as { stdout?: string }).stdout ?? e);
    }
  };
  try {
    const file = join(dir, "history.mts");
    writeFileSync(file, blocks[0] as string);
    // as the README says (tsc's defaults), and with every strict option the repository uses
    // (--types node: the repository's other @types, react-dom's, need more than tsc's default library)
    expect(tscRun(["--strict", "--noEmit", "--types", "node", file])).toBe("");
    expect(tscRun([...strict, ...nodenext, "--lib", "es2022", "--types", "node", "--noEmit", file])).toBe("");
    expect(tscRun([...nodenext, "--types", "node", "--outDir", join(dir, "out"), file])).toBe("");
    const out = execFileSync(process.execPath, [join(dir, "out", "history.mjs")], { encoding: "utf8" });
    const lines = out.trim().split("\n");
    expect(lines[0]).toBe("0 3 5 5");
    expect(lines[1]).toMatch(/^3 5 5 1\.0396/);
    expect(lines[2]).toMatch(/^3 bodyBody \[ \[ 'a', 0, -1\.98\d* \], \[ 'b', -1, -0\.98\d* \] \]$/);
    expect(lines.length).toBe(3);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

it("the engine README's one-liner writes a scene file the CLI takes (the sample scenes are not in the package)", () => {
  // Audit of session 21: the CLI examples read scene.json, and the samples are only in the repository.
  const readme = readFileSync(join(root, "packages", "engine", "README.md"), "utf8");
  const line = /^node --input-type=module -e '(.*)' > scene\.json$/m.exec(readme)?.[1];
  expect(line, "the README shows how to write scene.json from a preset").toBeDefined();
  const dir = mkdtempSync(join(root, "tests", "readme", ".tmp-"));
  try {
    const text = execFileSync(process.execPath, ["--input-type=module", "-e", line as string], {
      encoding: "utf8",
      cwd: dir,
    });
    writeFileSync(join(dir, "scene.json"), text);
    const bin = join(root, "packages", "engine", "src", "cli", "launcher.mjs");
    const out = execFileSync(process.execPath, [bin, "check", join(dir, "scene.json")], { encoding: "utf8" });
    expect(JSON.parse(out)).toMatchObject({ valid: true, actions: 6 });
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

it("the engine README's CLI examples, run on the scene its one-liner writes, each exit 0 with one JSON object", () => {
  // Audit of session 23: `path scene.json --id ball` named no body of that scene (Newton's cradle
  // has c1 to c5 and the striker) and exited 2.
  const readme = readFileSync(join(root, "packages", "engine", "README.md"), "utf8");
  const line = /^node --input-type=module -e '(.*)' > scene\.json$/m.exec(readme)?.[1] as string;
  const examples = [...readme.matchAll(/^npx chapgame (.+?)\s+#.*$/gm)].map((m) =>
    (m[1] as string).split(/\s+/),
  );
  expect(examples.map((args) => args[0])).toEqual(["simulate", "state", "path", "check", "simulate"]);
  const dir = mkdtempSync(join(root, "tests", "readme", ".tmp-"));
  try {
    const scene = join(dir, "scene.json");
    writeFileSync(
      scene,
      execFileSync(process.execPath, ["--input-type=module", "-e", line], { encoding: "utf8", cwd: dir }),
    );
    const bin = join(root, "packages", "engine", "src", "cli", "launcher.mjs");
    for (const args of examples) {
      const r = spawnSync(process.execPath, [bin, ...args.map((a) => (a === "scene.json" ? scene : a))], {
        encoding: "utf8",
      });
      // --progress may print its line (after half a second on a loaded host); anything else is an error.
      const stderr = args.includes("--progress")
        ? r.stderr.replace(/^chapgame: t = .* events.*\n/gm, "")
        : r.stderr;
      expect([r.status, stderr], args.join(" ")).toEqual([0, ""]);
      expect(typeof JSON.parse(r.stdout), args.join(" ")).toBe("object");
    }
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});
