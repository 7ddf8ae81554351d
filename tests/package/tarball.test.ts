/**
 * What a game developer downloads: the real tarball of `npm pack` (scripts off, so it packs the
 * dist/ that `npm test` built), unpacked and read file by file. It holds the entry point, its
 * types, the bin, the README, the LICENSE; only built code, its TypeScript sources (the source maps
 * point there) and docs, whose relative links all resolve inside it; every source map resolves
 * inside the tarball; and the manifest is one that `npm publish` sends as it is (npm 11 drops a bin
 * whose path starts with "./").
 */
import { readFileSync, rmSync } from "node:fs";
import { dirname, join, normalize } from "node:path";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import { engineManifest, npm, type Packed, packEngine, readPacked, repoRoot, run } from "./npmTools.js";

let packed: Packed;
let manifest: {
  main?: string;
  types?: string;
  exports?: Record<string, string | Record<string, string>>;
  bin?: Record<string, string>;
  license?: string;
  dependencies?: Record<string, string>;
  peerDependencies?: Record<string, string>;
};

beforeAll(() => {
  packed = packEngine();
  manifest = JSON.parse(readPacked(packed, "package.json"));
});

afterAll(() => {
  if (packed) rmSync(packed.dir, { recursive: true, force: true });
});

/** A path of the manifest ("./dist/index.js") as a tarball path ("dist/index.js"). */
const inTarball = (p: string): string => normalize(p).replace(/^\.\//, "");

describe("the tarball of @chapgame/engine", () => {
  it("holds the entry point, its types, every target the manifest names, the README, the LICENSE", () => {
    const targets = [
      "package.json",
      "README.md",
      "LICENSE",
      "dist/index.js",
      "dist/index.d.ts",
      manifest.main,
      manifest.types,
      ...Object.values(manifest.bin ?? {}),
      ...Object.values(manifest.exports ?? {}).flatMap((e) =>
        typeof e === "string" ? [e] : Object.values(e),
      ),
    ];
    expect(Object.keys(manifest.bin ?? {})).toEqual(["chapgame"]);
    for (const t of targets) {
      expect(t, "a manifest target").toBeTypeOf("string");
      expect(packed.files, String(t)).toContain(inTarball(t as string));
    }
    expect(readPacked(packed, "README.md")).toMatch(/^# @chapgame\/engine\n/);
    expect(readPacked(packed, "LICENSE")).toMatch(/^MIT License\n/);
    expect(manifest.license).toBe("MIT");
  });

  it("holds only built code, its sources and docs: no tests, test helpers, bench, editor or dev scripts", () => {
    const allowed = [
      /^(package\.json|README\.md|LICENSE)$/,
      /^docs\/[\w-]+\.md$/,
      /^dist\/[\w/]+\.(js|d\.ts|js\.map|d\.ts\.map)$/,
      /^src\/[\w/]+\.ts$/,
      /^src\/[\w/]+\/README\.md$/,
      /^src\/cli\/launcher\.mjs$/,
    ];
    const forbidden =
      /\.test\.|\.prop\.|testSupport|(^|\/)(bench|editor|tests?|e2e|node_modules)\/|timing\.mjs/;
    expect(packed.files.filter((f) => !allowed.some((a) => a.test(f)))).toEqual([]);
    expect(packed.files.filter((f) => forbidden.test(f))).toEqual([]);
  });

  it("has every relative link of its Markdown resolve inside the tarball (the README's docs ship with it)", () => {
    const docs = packed.files.filter((f) => f.endsWith(".md"));
    expect(docs).toEqual(expect.arrayContaining(["README.md", "docs/api.md", "docs/scene-format.md"]));
    const broken: string[] = [];
    let links = 0;
    for (const f of docs)
      for (const m of readPacked(packed, f).matchAll(/\]\(([^)\s]+)\)/g)) {
        const target = (m[1] as string).split("#")[0] as string;
        if (target === "" || /^[a-z]+:/.test(target)) continue; // an anchor in the page, or a URL
        links++;
        if (!packed.files.includes(normalize(join(dirname(f), target)))) broken.push(`${f} -> ${target}`);
      }
    expect(broken).toEqual([]);
    expect(links).toBeGreaterThan(2);
  });

  it("has a source map for each module whose sources are all in the tarball", () => {
    const missing: string[] = [];
    const built = packed.files.filter((f) => /^dist\/.*\.(js|d\.ts)$/.test(f));
    for (const f of built) {
      const url = /\/\/# sourceMappingURL=(\S+)\s*$/.exec(readPacked(packed, f))?.[1];
      if (url === undefined) continue; // declarations carry no map unless declarationMap is on
      const map = join(dirname(f), url);
      if (!packed.files.includes(map)) missing.push(`${f} -> ${map}`);
    }
    const maps = packed.files.filter((f) => f.endsWith(".map"));
    for (const m of maps) {
      const json = JSON.parse(readPacked(packed, m)) as { sources: string[]; sourceRoot?: string };
      for (const s of json.sources) {
        const target = join(dirname(m), json.sourceRoot ?? "", s);
        if (!packed.files.includes(target)) missing.push(`${m} -> ${target}`);
      }
    }
    expect(missing).toEqual([]);
    // Every built module has its map (dist/x.js -> dist/x.js.map): stepping into the engine works.
    const js = built.filter((f) => f.endsWith(".js"));
    expect(js.length).toBeGreaterThan(0);
    expect(js.filter((f) => !packed.files.includes(`${f}.map`))).toEqual([]);
  });

  it("has a bin Node can run (a #! line) and a manifest npm publish sends unchanged (npm pkg fix is a no-op)", () => {
    const bin = inTarball(manifest.bin?.chapgame ?? "");
    expect(readPacked(packed, bin)).toMatch(/^#!\/usr\/bin\/env node\n/);
    const before = readPacked(packed, "package.json");
    const fix = npm(["pkg", "fix"], packed.unpacked, packed.dir);
    expect(fix.code, fix.stderr).toBe(0);
    expect(JSON.parse(readFileSync(join(packed.unpacked, "package.json"), "utf8"))).toEqual(
      JSON.parse(before),
    );
  });

  it("has no runtime or peer dependencies", () => {
    expect(Object.keys(manifest.dependencies ?? {})).toEqual([]);
    expect(Object.keys(manifest.peerDependencies ?? {})).toEqual([]);
  });

  it("stays small: under 1 MB packed and 4 MB unpacked (a stray folder would show here)", () => {
    console.log(
      `@chapgame/engine tarball: ${packed.files.length} files, ${packed.size} B packed, ${packed.unpackedSize} B unpacked`,
    );
    expect(packed.size).toBeLessThan(1_000_000);
    expect(packed.unpackedSize).toBeLessThan(4_000_000);
  });
});

describe("the README's npm pack in the repository", () => {
  it("writes a tarball git ignores (it showed as untracked after following the README)", () => {
    const readme = readFileSync(join(repoRoot, "README.md"), "utf8");
    const name = /`npm pack -w @chapgame\/engine` writes `([^`]+\.tgz)`/.exec(readme)?.[1];
    expect(name).toBe(`chapgame-engine-${engineManifest().version}.tgz`);
    const r = run("git", ["check-ignore", "--no-index", join(repoRoot, name as string)], repoRoot);
    expect([r.code, r.stderr]).toEqual([0, ""]);
  });
});
