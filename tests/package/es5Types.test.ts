/**
 * The package's type declarations on the oldest library TypeScript has: the packed tarball is
 * installed offline into a fresh CommonJS project outside the repository (as install.test.ts does)
 * and a consumer of World and Timeline is compiled, strict and with the library's declarations
 * checked, on tsc's defaults (target ES5, module CommonJS, node10 resolution) and with `lib` ES5
 * alone. Review of session 26: the declarations of internals that World and Timeline pulled in
 * (a protected Map, and modules reached through timeline/path.ts) gave 10 errors "Cannot find name
 * 'Map'" (TS2583) there, so the README had to ask for `--module nodenext`.
 */
import { rmSync, writeFileSync } from "node:fs";
import { join } from "node:path";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { es5Consumer, misuse } from "./consumerFiles.js";
import { node, npm, type Packed, packEngine, tempDir, tscBin } from "./npmTools.js";

let packed: Packed;
let project: string;

const write = (name: string, text: string): void => writeFileSync(join(project, name), text);

beforeAll(() => {
  packed = packEngine();
  project = tempDir("chapgame-es5-consumer-");
  write("package.json", JSON.stringify({ name: "es5-consumer", private: true }));
  const installed = npm(
    ["install", "--offline", "--no-audit", "--no-fund", packed.tarball],
    project,
    packed.dir,
  );
  if (installed.code !== 0) throw new Error(`npm install of the tarball failed: ${installed.stderr}`);
  write("consumer.ts", es5Consumer);
  write("misuse.ts", misuse);
});

afterAll(() => {
  if (project) rmSync(project, { recursive: true, force: true });
  if (packed) rmSync(packed.dir, { recursive: true, force: true });
});

describe("a TypeScript consumer on an ES5 library (strict, the package's declarations checked)", () => {
  const configs: [string, string, Record<string, unknown>][] = [
    ["tsc's defaults (target ES5, module CommonJS, node10 resolution)", "defaults", {}],
    ["lib es5 alone, node10 resolution", "es5-node10", { lib: ["es5"], moduleResolution: "node10" }],
    [
      "lib es5 alone, bundler resolution",
      "es5-bundler",
      { lib: ["es5"], module: "esnext", moduleResolution: "bundler" },
    ],
    [
      "lib es5 alone, nodenext",
      "es5-nodenext",
      { lib: ["es5"], module: "nodenext", moduleResolution: "nodenext" },
    ],
  ];

  // One program per configuration: the consumer must check clean and the misuse must be the only
  // error, so declarations that did not resolve (everything any) fail here too.
  it.each(configs)(
    "under %s the consumer type-checks and a string radius is refused",
    (_name, file, options) => {
      const config = `tsconfig.${file}.json`;
      const compilerOptions = { ...options, strict: true, noEmit: true, skipLibCheck: false, types: [] };
      write(config, JSON.stringify({ compilerOptions, files: ["consumer.ts", "misuse.ts"] }));
      const r = node([tscBin, "-p", config], project);
      expect(r.stderr).toBe("");
      const errors = r.stdout.split("\n").filter((l) => /error TS\d+/.test(l));
      expect(errors, r.stdout).toHaveLength(1);
      expect(errors[0]).toMatch(
        /^misuse\.ts\(2,\d+\): error TS2322: Type 'string' is not assignable to type 'number'/,
      );
      expect(r.code).not.toBe(0);
    },
  );
});
