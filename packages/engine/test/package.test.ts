/**
 * What `npm pack` would publish (`npm pack --dry-run --json`, scripts off so it lists the dist/ that
 * is there): the built code and its types, the bin's launcher, the README and the LICENSE; no tests, and no file
 * in dist/ that no source produces any more (a stale module from a removed source shipped dead code).
 */
import { execFileSync } from "node:child_process";
import { existsSync, readFileSync } from "node:fs";
import { join, resolve } from "node:path";
import { beforeAll, describe, expect, it } from "vitest";

const pkg = resolve(import.meta.dirname, "..");
let files: string[] = [];

beforeAll(() => {
  if (!existsSync(join(pkg, "dist/index.js")))
    execFileSync("npm", ["run", "build"], { cwd: pkg, stdio: "ignore" });
  const out = execFileSync("npm", ["pack", "--dry-run", "--json", "--ignore-scripts"], {
    cwd: pkg,
    encoding: "utf8",
    stdio: ["ignore", "pipe", "ignore"],
  });
  files = (JSON.parse(out) as { files: { path: string }[] }[])[0]?.files.map((f) => f.path) ?? [];
});

describe("the published package", () => {
  it("has the entry point, its types, the bin, the README and the licence", () => {
    const manifest = JSON.parse(readFileSync(join(pkg, "package.json"), "utf8"));
    for (const f of [
      "dist/index.js",
      "dist/index.d.ts",
      "dist/cli/main.js",
      "README.md",
      "LICENSE",
      manifest.bin.chapgame,
    ])
      expect(files, f).toContain(f.replace(/^\.\//, ""));
  });

  it("resolves for require() too: Node's own error (or the module), not 'No \"exports\" main defined'", () => {
    const probe = `try { require("@chapgame/engine"); console.log("loaded") } catch (e) { console.log(e.code) }`;
    const out = execFileSync(process.execPath, ["-e", probe], { cwd: pkg, encoding: "utf8" }).trim();
    expect(["loaded", "ERR_REQUIRE_ESM"]).toContain(out);
    const version = `console.log(require("@chapgame/engine/package.json").version)`;
    expect(execFileSync(process.execPath, ["-e", version], { cwd: pkg, encoding: "utf8" }).trim()).toBe(
      JSON.parse(readFileSync(join(pkg, "package.json"), "utf8")).version,
    );
  });

  it("has no tests and no test helpers", () => {
    expect(files.filter((f) => /\.test\.|testSupport|^test\//.test(f))).toEqual([]);
  });

  it("has no file in dist/ without its source in src/ (a stale build output)", () => {
    const stale = files.filter((f) => {
      if (!f.startsWith("dist/")) return false;
      const src = `src/${f.slice(5)}`.replace(/(\.d\.ts\.map|\.d\.ts|\.js\.map|\.js)$/, ".ts");
      return !existsSync(join(pkg, src));
    });
    expect(stale).toEqual([]);
  });

  it("declares its typed arrays without the TypeScript 5.7 generic (Float64Array<ArrayBuffer>), so older compilers read the types", () => {
    const generic = files
      .filter((f) => f.endsWith(".d.ts"))
      .filter((f) =>
        /(Int32|Float64|Uint8|Uint32)Array<|ArrayBuffer>/.test(readFileSync(join(pkg, f), "utf8")),
      );
    expect(generic).toEqual([]);
  });
});
