/**
 * The real bin (dist/cli/main.js, built first when older than the sources) in situations only a real
 * process has: standard output closed early by the reader (`chapgame ... | head`), and a reader that
 * does not keep up (the bin must wait for it, not hold the output in memory: read from Linux's /proc).
 */
import { execFileSync, spawn, spawnSync } from "node:child_process";
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";
import { afterAll, beforeAll, expect, it } from "vitest";
import { buildEngineIfStale } from "../../test/builtEngine.js";
import { dilutedGas } from "../scene/presets.js";
import { serializeScene } from "../scene/serialize.js";

const pkg = resolve(import.meta.dirname, "../..");
const bin = join(pkg, "dist/cli/main.js");

/** The temporary directories this file made; removed after its tests, so runs leave nothing in /tmp. */
const made: string[] = [];
function tempDir(): string {
  const dir = mkdtempSync(join(tmpdir(), "chapgame-main-"));
  made.push(dir);
  return dir;
}
afterAll(() => {
  for (const dir of made) rmSync(dir, { recursive: true, force: true });
});

beforeAll(() => buildEngineIfStale(bin));

it("a reader that closes standard output early (| head) ends the run quietly, without a stack trace", async () => {
  const dir = tempDir();
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

/** [resident set size in kB, CPU ticks used] of a live process, from /proc. */
function usage(pid: number): [number, number] {
  const rss = Number(/VmRSS:\s+(\d+)/.exec(readFileSync(`/proc/${pid}/status`, "utf8"))?.[1]);
  const stat = readFileSync(`/proc/${pid}/stat`, "utf8");
  const fields = stat.slice(stat.lastIndexOf(")") + 2).split(" ");
  return [rss, Number(fields[11]) + Number(fields[12])]; // utime + stime
}

it("a reader that does not keep up makes the bin wait, not hold the output in memory (2 GB for 2M events)", async () => {
  expect(existsSync("/proc/self/status"), "this test reads Linux's /proc").toBe(true);
  const dir = tempDir();
  const scene = join(dir, "gas.json");
  writeFileSync(scene, serializeScene(dilutedGas({ n: 200, packing: 0.2 })));
  const child = spawn("node", [bin, "simulate", scene, "--max-events", "1000000", "--events"], {
    stdio: ["ignore", "pipe", "inherit"],
  });
  const pid = child.pid as number;
  const closed = new Promise<number | null>((done) => child.on("close", (c) => done(c)));
  // Not reading: once the pipe is full the bin must block. Wait until its CPU time stands still.
  let maxRss = 0;
  let ticks = -1;
  for (let still = 0; still < 5; ) {
    await new Promise((r) => setTimeout(r, 200));
    const [rss, t] = usage(pid);
    maxRss = Math.max(maxRss, rss);
    still = t === ticks ? still + 1 : 0;
    ticks = t;
  }
  let bytes = 0;
  child.stdout.on("data", (d: Buffer) => {
    bytes += d.length;
  });
  expect(await closed).toBe(0);
  expect(bytes).toBeGreaterThan(250e6); // about 320 MB of JSON
  // Queued in memory, the output alone would be above it. The process's own memory grows with the
  // run too (the history it prints from: about 130 MB stalled after 400,000 events, as much as that
  // run's output, which made the margin of a shorter run too thin on a loaded host; 1,000,000 events
  // print 2.5 times as much, 320 MB, for about 150 MB stalled).
  expect(maxRss * 1024).toBeLessThan(bytes);
}, 120_000);

it("a result that cannot be written (a full disk: Linux's /dev/full) exits 1 saying so, not as an internal error", () => {
  const dir = tempDir();
  const scene = join(dir, "gas.json");
  writeFileSync(scene, serializeScene(dilutedGas({ n: 20, packing: 0.2 })));
  let status: number | null = 0;
  let stderr = "";
  try {
    execFileSync("sh", ["-c", `node "${bin}" simulate "${scene}" --max-events 10 > /dev/full`], {
      stdio: ["ignore", "ignore", "pipe"],
    });
  } catch (e) {
    const err = e as { status: number | null; stderr: Buffer };
    status = err.status;
    stderr = err.stderr.toString();
  }
  expect(status).toBe(1);
  expect(stderr).toMatch(/^chapgame: cannot write the result: ENOSPC/);
  expect(stderr.split("\n").filter(Boolean)).toHaveLength(1);
});

/** Runs the bin on `scene` with `args`, sends `signal` once a progress line is on stderr; resolves
 *  with the exit code, the exit signal, stdout and stderr. */
function interrupted(
  args: string[],
  signal: "SIGINT" | "SIGTERM",
): Promise<{ code: number | null; killedBy: string | null; stdout: string; stderr: string }> {
  const child = spawn("node", [bin, ...args, "--progress"], { stdio: ["ignore", "pipe", "pipe"] });
  let stdout = "";
  let stderr = "";
  let sent = false;
  child.stdout.on("data", (d: Buffer) => {
    stdout += d.toString();
  });
  child.stderr.on("data", (d: Buffer) => {
    stderr += d.toString();
    // a progress line: the computation is under way (no fixed sleep: the machine may be loaded)
    if (!sent && /^chapgame: t = .*events\n/m.test(stderr)) {
      sent = true;
      child.kill(signal);
    }
  });
  return new Promise((done) =>
    child.on("close", (code, killedBy) => done({ code, killedBy, stdout, stderr })),
  );
}

it("Ctrl-C (SIGINT) during a run without a bound prints the result so far, reason interrupted, and exits 130", async () => {
  // Audit: runCli was synchronous, so SIGINT killed the bin and the user got nothing.
  const dir = tempDir();
  const scene = join(dir, "gas.json");
  writeFileSync(scene, serializeScene(dilutedGas({ n: 200, packing: 0.2 }))); // never rests
  const r = await interrupted(["simulate", scene, "--compact"], "SIGINT");
  expect(r.killedBy).toBeNull();
  expect(r.code).toBe(130);
  const result = JSON.parse(r.stdout);
  expect(result.reason).toBe("interrupted");
  expect(result.events).toBeGreaterThan(0);
  expect(r.stderr).toContain(`: interrupted by SIGINT at t = ${result.time} after ${result.events} events`);
  // the partial result is the run bounded at that many events, bit for bit
  const bounded = execFileSync(
    "node",
    [bin, "simulate", scene, "--compact", "--max-events", String(result.events)],
    {
      encoding: "utf8",
    },
  );
  expect({ ...JSON.parse(bounded), reason: "interrupted" }).toEqual(result);
}, 60_000);

it("SIGTERM during state --at T prints the bodies where the computation got to and exits 143", async () => {
  const dir = tempDir();
  const scene = join(dir, "gas.json");
  writeFileSync(scene, serializeScene(dilutedGas({ n: 200, packing: 0.2 })));
  const r = await interrupted(["state", scene, "--at", "1e12"], "SIGTERM");
  expect(r.code).toBe(143);
  const result = JSON.parse(r.stdout);
  expect(result).toMatchObject({ reason: "interrupted" });
  expect(result.events).toBeGreaterThan(0);
  expect(result.time).toBeLessThan(1e12);
}, 60_000);

it("Ctrl-C while the bin waits for its scene on standard input ends it at once (killed by the signal)", async () => {
  // Review of session 16: the handlers were installed at start, and a handler cannot run while a
  // synchronous read waits, so SIGINT was swallowed until the input ended.
  const child = spawn("node", [bin, "simulate", "-"], { stdio: ["pipe", "pipe", "pipe"] });
  child.stdin.write('{"format": "chapgame",'); // and the pipe is held open
  await new Promise((r) => setTimeout(r, 500)); // the bin has started and waits in its read
  const closed = new Promise<{ code: number | null; killedBy: string | null }>((done) =>
    child.on("close", (code, killedBy) => done({ code, killedBy })),
  );
  child.kill("SIGINT");
  const timer = setTimeout(() => child.stdin.end(), 10_000); // would end the read, much later
  const r = await closed;
  clearTimeout(timer);
  expect(r).toEqual({ code: null, killedBy: "SIGINT" });
}, 30_000);

/** Runs the bin on a 200-disc gas for `events` events with the log, and, as soon as the first bytes
 *  of the result arrive (the computation is over, the writing has begun), stops reading its stdout
 *  (so it cannot finish: about 30 MB are left to write), sends `signals` in order, and reads on. */
function signalledWhileWriting(
  signals: ("SIGINT" | "SIGTERM")[],
): Promise<{ code: number | null; killedBy: string | null; stdout: string; stderr: string }> {
  const dir = tempDir();
  const scene = join(dir, "gas.json");
  writeFileSync(scene, serializeScene(dilutedGas({ n: 200, packing: 0.2 })));
  const child = spawn("node", [bin, "simulate", scene, "--events", "--max-events", "100000"], {
    stdio: ["ignore", "pipe", "pipe"],
  });
  const chunks: Buffer[] = [];
  let stderr = "";
  child.stderr.on("data", (d: Buffer) => {
    stderr += d.toString();
  });
  child.stdout.once("data", () => {
    child.stdout.pause();
    // SIGINT and SIGTERM are distinct signals, so the kernel never merges the two (it may merge
    // two of one kind, still pending)
    for (const s of signals) child.kill(s);
    child.stdout.resume();
  });
  child.stdout.on("data", (d: Buffer) => chunks.push(d));
  return new Promise((done) =>
    child.on("close", (code, killedBy) =>
      done({ code, killedBy, stdout: Buffer.concat(chunks).toString(), stderr }),
    ),
  );
}

it("Ctrl-C while the result is written finishes it (valid JSON), says so on stderr, and exits 130", async () => {
  // Review of session 31: the handlers were removed before writing, so a Ctrl-C 2 s into writing a
  // 3-million-event log left 53 MB of truncated JSON, exit 130 and nothing on stderr.
  const r = await signalledWhileWriting(["SIGINT"]);
  expect(r.killedBy).toBeNull();
  expect(r.code).toBe(130);
  expect(JSON.parse(r.stdout)).toMatchObject({ reason: "events", events: 100000 });
  expect(r.stderr).toMatch(/: SIGINT while the result is being written: finishing it, so that it is whole /);
}, 120_000);

it("a second signal while the result is written stops it at once, saying the output is incomplete", async () => {
  // The two signals come from one moment: Node may take them in either order (they can reach two of
  // its threads), so the first taken gets the notice and the second the abort and its status.
  const r = await signalledWhileWriting(["SIGINT", "SIGTERM"]);
  const first = /: (SIGINT|SIGTERM) while the result is being written: finishing it/.exec(r.stderr)?.[1];
  expect(first).toBeDefined();
  const second = first === "SIGINT" ? "SIGTERM" : "SIGINT";
  expect(r.code).toBe(second === "SIGINT" ? 130 : 143);
  expect(() => JSON.parse(r.stdout)).toThrow();
  expect(r.stdout.length).toBeLessThan(20e6); // far from the whole (about 32 MB)
  expect(r.stderr).toMatch(
    new RegExp(
      `: interrupted again by ${second} while the result was being written: stopped at once, so the output is incomplete \\(not valid JSON\\)\n$`,
    ),
  );
}, 120_000);

it("a device that never ends (/dev/zero) is refused once it gives more than a string holds, naming it", () => {
  // Review of session 31: `chapgame check /dev/zero` never returned (reading had no size bound).
  expect(existsSync("/dev/zero"), "this test reads Linux's /dev/zero").toBe(true);
  const r = spawnSync("node", [bin, "check", "/dev/zero"], { encoding: "utf8", timeout: 60_000 });
  expect(r.signal).toBeNull(); // not killed by the timeout
  expect(r.status).toBe(2);
  expect(r.stdout).toBe("");
  expect(r.stderr).toBe(
    "chapgame: cannot read /dev/zero: it gives more text than a JavaScript string can hold (0x1fffffe8, about 537 million characters), so no scene that large can be read: reading stopped there (ERR_STRING_TOO_LONG)\n",
  );
}, 90_000);
