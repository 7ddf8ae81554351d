/**
 * A game developer's first hour with @chapgame/engine, for real: the packed tarball is installed
 * with `npm install --offline` into a fresh project under the OS temporary directory (outside the
 * repository, so nothing resolves through the monorepo's node_modules), then used from plain Node
 * ESM (the README's first example, the API), from CommonJS (require on a Node with require(esm), and
 * the error and the import() fallback without it), from TypeScript under node16, nodenext and
 * bundler resolution (and a misuse that must not type-check), and through the installed `chapgame`
 * bin.
 */
import { readFileSync, rmSync, writeFileSync } from "node:fs";
import { join } from "node:path";
import { pathToFileURL } from "node:url";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import {
  apiScript,
  dynamicImportScript,
  headOnScene,
  misuse,
  requireScript,
  tsconfig,
  typedConsumer,
} from "./consumerFiles.js";
import {
  engineManifest,
  enginePkg,
  node,
  npm,
  type Packed,
  packEngine,
  type Run,
  repoRoot,
  run,
  tempDir,
  tscBin,
} from "./npmTools.js";

const version = engineManifest().version;
let packed: Packed;
let project: string;
let beforeInstall: Run;
let installed: Run;

const write = (name: string, text: string): void => writeFileSync(join(project, name), text);
const json = (r: Run): Record<string, unknown> => {
  expect(r.code, r.stderr).toBe(0);
  return JSON.parse(r.stdout) as Record<string, unknown>;
};

beforeAll(() => {
  packed = packEngine();
  project = tempDir("chapgame-consumer-");
  write("package.json", JSON.stringify({ name: "consumer", private: true, type: "module" }));
  beforeInstall = node(["--input-type=module", "-e", 'await import("@chapgame/engine")'], project);
  installed = npm(["install", "--offline", "--no-audit", "--no-fund", packed.tarball], project, packed.dir);
  if (installed.code !== 0) throw new Error(`npm install of the tarball failed: ${installed.stderr}`);
  write("scene.json", JSON.stringify(headOnScene));
});

afterAll(() => {
  if (project) rmSync(project, { recursive: true, force: true });
  if (packed) rmSync(packed.dir, { recursive: true, force: true });
});

describe("npm install of the packed tarball into a project outside the repository", () => {
  it("installs offline (zero runtime dependencies) into a project that could not see the engine before", () => {
    expect(beforeInstall.code).not.toBe(0);
    expect(beforeInstall.stderr).toContain("ERR_MODULE_NOT_FOUND");
    const deps = JSON.parse(readFileSync(join(project, "package.json"), "utf8")).dependencies;
    expect(Object.keys(deps)).toEqual(["@chapgame/engine"]);
    const lock = JSON.parse(readFileSync(join(project, "package-lock.json"), "utf8"));
    expect(Object.keys(lock.packages)).toEqual(["", "node_modules/@chapgame/engine"]);
  });
});

describe("plain Node ESM", () => {
  it("runs the installed README's first example: events in time order up to t = 10, then the cue", () => {
    const readme = readFileSync(join(project, "node_modules/@chapgame/engine/README.md"), "utf8");
    const example = /```js\n([\s\S]*?)```/.exec(readme)?.[1] ?? "";
    expect(example).toContain('from "@chapgame/engine"');
    write("readme.mjs", example);
    const out = node(["readme.mjs"], project);
    expect(out.code, out.stderr).toBe(0);
    const events = out.stdout
      .split("\n")
      .map((l) => /^(bodyBody|bodyLine|bodyPoint|stop) (\S+) (\S+) (\S+)$/.exec(l))
      .filter((m) => m !== null)
      .map((m) => ({ kind: m[1], time: Number(m[2]), a: m[3], b: m[4] }));
    expect(events.length).toBeGreaterThan(0);
    const times = events.map((e) => e.time);
    expect(times).toEqual([...times].sort((x, y) => x - y));
    expect(times.every((t) => t > 0 && t <= 10)).toBe(true);
    expect(events).toContainEqual({ kind: "bodyBody", time: expect.any(Number), a: "ball", b: "cue" });
    expect(events).toContainEqual({ kind: "bodyLine", time: expect.any(Number), a: "ball", b: "cushion" });
    expect(out.stdout).toContain("id: 'cue'");
    // The installed copy computes what the repository's own build computes, bit for bit.
    const repoIndex = pathToFileURL(join(enginePkg, "dist/index.js")).href;
    write("readme-repo.mjs", example.replace('"@chapgame/engine"', JSON.stringify(repoIndex)));
    expect(node(["readme-repo.mjs"], project).stdout).toBe(out.stdout);
  });

  it("imports World, Timeline, realRoots, parseScene and ChapgameError and gets the exact answers", () => {
    write("api.mjs", apiScript);
    const out = json(node(["api.mjs"], project));
    expect(out.quadratic).toEqual([2, 3]);
    const [sqrt2] = out.sqrt2 as number[];
    expect(Math.abs((sqrt2 as number) - Math.SQRT2)).toBeLessThanOrEqual(4 * Number.EPSILON);
    expect(out.prolonged).toEqual({ events: 1, reason: "idle" });
    const [a, b] = out.at5 as { id: string; x: number; vx: number }[];
    expect(a?.id).toBe("a");
    expect(a?.x).toBeCloseTo(3, 12);
    expect(a?.vx).toBeCloseTo(0, 12);
    expect(b?.x).toBeCloseTo(7, 12);
    expect(b?.vx).toBeCloseTo(1, 12);
    expect(out.refusal).toMatchObject({ isChapgameError: true, path: expect.stringMatching(/\br$/) });
  });
});

describe("CommonJS", () => {
  const requireEsm = (process.features as { require_module?: boolean }).require_module === true;

  it(`require("@chapgame/engine") ${requireEsm ? "loads the same module as import() (this Node has require(esm))" : "fails with ERR_REQUIRE_ESM (this Node has no require(esm))"}`, () => {
    write("require.cjs", requireScript);
    const r = node(["require.cjs"], project);
    if (requireEsm) {
      expect(json(r)).toEqual({ world: "function", sameClass: true, version });
    } else {
      expect(r.code).not.toBe(0);
      expect(r.stderr).toContain("ERR_REQUIRE_ESM");
    }
  });

  it("without require(esm) (Node before 20.19) require fails clearly and import() works", () => {
    write("require.cjs", requireScript);
    write("import.cjs", dynamicImportScript);
    const flag = requireEsm ? ["--no-experimental-require-module"] : [];
    const r = node([...flag, "require.cjs"], project);
    expect(r.code).not.toBe(0);
    expect(r.stderr).toContain("ERR_REQUIRE_ESM");
    expect(r.stderr).toContain("dynamic import()");
    expect(json(node([...flag, "import.cjs"], project))).toMatchObject({ id: "a", x: 3, vx: 2 });
  });
});

describe("TypeScript consumers (the repository's tsc, strict, library types checked)", () => {
  const tsc = (config: string): Run => node([tscBin, "-p", config], project);
  const modes: [string, string, string][] = [
    ["node16", "node16", "node16"],
    ["nodenext", "nodenext", "nodenext"],
    ["bundler", "esnext", "bundler"],
    ["preserve", "preserve", "bundler"],
  ];

  // One program per mode: the consumer must check clean and the misuse must be the only error, so a
  // package whose types did not resolve (everything any) fails here too.
  it.each(modes)(
    "under %s (module %s, moduleResolution %s) the consumer type-checks and a string radius is refused",
    (name, module, resolution) => {
      write("consumer.ts", typedConsumer);
      write("misuse.ts", misuse);
      write(`tsconfig.${name}.json`, tsconfig(module, resolution, ["consumer.ts", "misuse.ts"]));
      const r = tsc(`tsconfig.${name}.json`);
      expect(r.code).not.toBe(0);
      expect(r.stderr).toBe("");
      const errors = r.stdout.split("\n").filter((l) => /error TS\d+/.test(l));
      expect(errors).toHaveLength(1);
      expect(errors[0]).toMatch(
        /^misuse\.ts\(2,\d+\): error TS2322: Type 'string' is not assignable to type 'number'/,
      );
    },
  );

  it("a CommonJS TypeScript module (.cts) compiles under nodenext (TypeScript 5.8+), not under node16", () => {
    write("consumer.cts", typedConsumer);
    write("tsconfig.cts-nodenext.json", tsconfig("nodenext", "nodenext", ["consumer.cts"]));
    write("tsconfig.cts-node16.json", tsconfig("node16", "node16", ["consumer.cts"]));
    const next = tsc("tsconfig.cts-nodenext.json");
    expect(next.stdout + next.stderr).toBe("");
    expect(next.code).toBe(0);
    const old = tsc("tsconfig.cts-node16.json");
    expect(old.code).not.toBe(0);
    expect(old.stdout).toContain("error TS1479");
  });
});

describe("the repository README's TypeScript check, run as it is written", () => {
  it("its command gives TS7034 for the plain example, passes with the README's typed lines, writes no example.mjs", () => {
    // Review of session 26: the README said "checked with `tsc --strict`"; run as written, tsc's
    // defaults (CommonJS, ES5) met the package's Map types (10 errors, none of them TS7034) and
    // wrote example.mjs over the JavaScript example. Since session 27 the shipped types need no
    // Map, and the command is tsc's defaults with --strict and --noEmit.
    const readme = readFileSync(join(repoRoot, "README.md"), "utf8");
    const command = /`npx tsc ([^`]*) example\.mts`/.exec(readme)?.[1];
    expect(command, "the README gives the tsc command line").toBeDefined();
    const flags = (command as string).split(/\s+/);
    const code = /```js\n([\s\S]*?)```/.exec(readme)?.[1] as string;
    const typed = /```ts\n([\s\S]*?)```/.exec(readme)?.[1] as string;
    const [importLine, logLine] = typed.trim().split("\n") as [string, string];
    write("example.mjs", code);
    const check = (source: string): Run => {
      write("example.mts", source);
      return node([tscBin, ...flags, "example.mts"], project);
    };
    const plain = check(code);
    expect(plain.code).not.toBe(0);
    expect(plain.stdout.split("\n").filter((l) => /error TS/.test(l))[0]).toMatch(
      /^example\.mts\(\d+,\d+\): error TS7034: Variable 'log' implicitly has type/,
    );
    const ts = code.replace(/^import .*$/m, importLine).replace(/^const log = \[\];$/m, logLine);
    expect(ts).toContain(logLine);
    const r = check(ts);
    expect(r.stdout + r.stderr).toBe("");
    expect(r.code).toBe(0);
    expect(readFileSync(join(project, "example.mjs"), "utf8")).toBe(code);
    // The README says tsc's defaults (target ES5, module CommonJS) are enough: so what passed above
    // ran on them, its command choosing no target, module, resolution or library (es5Types.test.ts
    // checks the package's types on lib ES5 alone).
    expect(flags.filter((f) => /^--(target|module|moduleResolution|lib)\b/.test(f))).toEqual([]);
    expect(readme).toMatch(/tsc's defaults \(target ES5, module CommonJS\) are enough/);
  });
});

describe("the installed chapgame bin (node_modules/.bin/chapgame)", () => {
  const bin = (args: string[], input = ""): Run =>
    run(join(project, "node_modules/.bin/chapgame"), args, project, input);

  it("--help prints the usage, --version the package's version", () => {
    const help = bin(["--help"]);
    expect(help.code, help.stderr).toBe(0);
    expect(help.stdout).toMatch(/^Usage:\n {2}chapgame simulate SCENE/);
    const v = bin(["--version"]);
    expect(v.code).toBe(0);
    expect(v.stdout.trim()).toBe(`chapgame ${version}`);
  });

  it("simulate and state on a scene file print JSON: the run up to a time, the state at a time", () => {
    type Out = {
      time: number;
      reason?: string;
      events: number;
      bodies: { id: string; x: number; vx: number }[];
    };
    const sim = bin(["simulate", "scene.json", "--until-time", "5"]);
    expect(sim.stderr).toBe("");
    const done = json(sim) as Out;
    // After the hit at t = 3 no event is left, and the bodies are printed at t = 5 all the same.
    expect(done.time).toBe(5);
    expect(done.reason).toBe("idle");
    expect(done.events).toBe(1);
    expect(done.bodies.map((b) => b.id)).toEqual(["a", "b"]);
    expect(done.bodies[1]?.vx).toBeCloseTo(1, 12);
    expect(done.bodies[1]?.x).toBeCloseTo(7, 12);
    const state = bin(["state", "scene.json", "--at", "5"]);
    expect(state.stderr).toBe("");
    const at5 = json(state) as Out;
    expect(at5.time).toBe(5);
    expect(at5.bodies[0]?.x).toBeCloseTo(3, 12);
    expect(at5.bodies[1]?.x).toBeCloseTo(7, 12);
  });

  it("an invalid scene exits 2 with one line naming the field", () => {
    const bad = JSON.stringify({ ...headOnScene, actions: [{ ...headOnScene.actions[0], r: -1 }] });
    const r = bin(["simulate", "-"], bad);
    expect(r.code).toBe(2);
    expect(r.stdout).toBe("");
    expect(r.stderr).toMatch(/^chapgame: <stdin>: actions\[0\]\.r: .+\n$/);
  });
});
