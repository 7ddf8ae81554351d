/**
 * The real bin (dist/cli/main.js, built first when older than the sources) in situations only a real
 * process has: standard output closed early by the reader (`chapgame ... | head`).
 */
import { execFileSync, spawn } from "node:child_process";
import { existsSync, mkdtempSync, readdirSync, statSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";
import { beforeAll, expect, it } from "vitest";
import { dilutedGas } from "../scene/presets.js";
import { serializeScene } from "../scene/serialize.js";

const pkg = resolve(import.meta.dirname, "../..");
const bin = join(pkg, "dist/cli/main.js");

function newest(dir: string): number {
  let t = 0;
  for (const e of readdirSync(dir, { withFileTypes: true })) {
    const p = join(dir, e.name);
    t = Math.max(t, e.isDirectory() ? newest(p) : statSync(p).mtimeMs);
  }
  return t;
}

beforeAll(() => {
  if (!existsSync(bin) || statSync(bin).mtimeMs < newest(join(pkg, "src")))
    execFileSync("npm", ["run", "build"], { cwd: pkg, stdio: "ignore" });
});

it("a reader that closes standard output early (| head) ends the run quietly, without a stack trace", async () => {
  const dir = mkdtempSync(join(tmpdir(), "chapgame-main-"));
  const scene = join(dir, "gas.json");
  writeFileSync(scene, serializeScene(dilutedGas({ n: 200, packing: 0.2 })));
  // about 2 MB of JSON: far more than a pipe holds, so writing continues after the reader is gone
  const child = spawn("node", [bin, "simulate", scene, "--max-events", "10000", "--events"], {
    stdio: ["ignore", "pipe", "pipe"],
  });
  let stderr = "";
  child.stderr.on("data", (d: Buffer) => {
    stderr += d.toString();
  });
  child.stdout.once("data", () => child.stdout.destroy());
  const code = await new Promise<number | null>((done) => child.on("close", (c) => done(c)));
  expect(stderr).toBe("");
  expect(code).toBe(0);
});
