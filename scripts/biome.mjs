#!/usr/bin/env node
// Runs Biome (lint + format) from its platform binary package. The Biome wrapper package lists an
// optional binary for every platform, and the npm registry this project installs from serves only
// the Linux ones, which leaves `npm ci` unable to accept any lock file; so the project depends on
// the Linux binaries directly (as optional dependencies) and this script finds the right one.
import { spawnSync } from "node:child_process";
import { existsSync } from "node:fs";
import { createRequire } from "node:module";
import { dirname, join } from "node:path";

const require = createRequire(import.meta.url);
const name = `@biomejs/cli-${process.platform}-${process.arch}`;
let bin;
try {
  bin = join(
    dirname(require.resolve(`${name}/package.json`)),
    process.platform === "win32" ? "biome.exe" : "biome",
  );
} catch {
  bin = undefined;
}
if (bin === undefined || !existsSync(bin)) {
  process.stderr.write(
    `biome: no binary for ${process.platform}-${process.arch} (${name} is not installed)\n`,
  );
  process.exit(1);
}
const result = spawnSync(bin, process.argv.slice(2), { stdio: "inherit" });
process.exit(result.status ?? 1);
