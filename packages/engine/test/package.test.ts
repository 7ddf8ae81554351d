/**
 * What `npm pack` would publish (`npm pack --dry-run --json`, scripts off so it lists the dist/ that
 * is there): no file in dist/ that no source produces any more (a stale module from a removed source
 * shipped dead code), and type declarations older compilers read. The tarball's contents and a real
 * install (ESM, CommonJS, TypeScript, the bin) are tested in tests/package/.
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
