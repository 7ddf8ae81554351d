// Progress on stderr (progress.ts): an updating line on a terminal, one line each with --progress,
// nothing otherwise; the result on stdout is the same either way.
import { describe, expect, it } from "vitest";
import { dilutedGas } from "../scene/presets.js";
import { serializeScene } from "../scene/serialize.js";
import { FIRST_SLICE_EVENTS, SLICE_TARGET_MS } from "./cadence.js";
import type { CliIO } from "./io.js";
import { LONG_SCENE_CHARS, READ_REPORT_BYTES } from "./progress.js";
import { runCli } from "./run.js";
import { io } from "./testSupport.js";

/** The gas's text with `extra` actions. */
function gasWith(...extra: unknown[]): string {
  const gas = dilutedGas({ n: 200, packing: 0.2 });
  return JSON.stringify({ ...gas, actions: [...gas.actions, ...extra] });
}

/** stderr with each time written as T. */
const timesAsT = (stderr: string) => stderr.replace(/t = [\d.e+]+/g, "t = T");

describe("progress on stderr", () => {
  it("shows progress on stderr when asked (a terminal), and the same result", () => {
    const files = { "gas.json": serializeScene(dilutedGas({ n: 200, packing: 0.2 })) };
    const quiet = io(files);
    const loud = io(files, true);
    expect(runCli(["simulate", "gas.json", "--max-events", "450000"], quiet.cli)).toBe(0);
    expect(runCli(["simulate", "gas.json", "--max-events", "450000"], loud.cli)).toBe(0);
    expect(quiet.out.stderr).toBe("");
    const lines = loud.out.stderr.split("\r");
    expect(lines.slice(1, 3).map((l) => l.replace(/t = [\d.e+]+/, "t = T"))).toEqual([
      "chapgame: t = T, 200000 of 450000 events",
      "chapgame: t = T, 400000 of 450000 events",
    ]);
    expect(lines[3]).toBe(`${String.fromCharCode(27)}[K`);
    expect(loud.out.stdout).toBe(quiet.out.stdout);
    expect(JSON.parse(quiet.out.stdout).events).toBe(450000);
  });

  it("--progress reports one line per slice when stderr is not a terminal, and the same result", () => {
    const files = { "gas.json": serializeScene(dilutedGas({ n: 200, packing: 0.2 })) };
    const quiet = io(files);
    const lines = io(files);
    expect(runCli(["simulate", "gas.json", "--max-events", "450000"], quiet.cli)).toBe(0);
    expect(runCli(["simulate", "gas.json", "--max-events", "450000", "--progress"], lines.cli)).toBe(0);
    expect(lines.out.stderr.replace(/t = [\d.e+]+/g, "t = T")).toBe(
      "chapgame: t = T, 200000 of 450000 events\nchapgame: t = T, 400000 of 450000 events\n",
    );
    expect(lines.out.stdout).toBe(quiet.out.stdout);
  });

  it("state --at T shows progress too (it was computed in one silent call) and gives the same state", () => {
    const files = { "gas.json": serializeScene(dilutedGas({ n: 200, packing: 0.2 })) };
    const quiet = io(files);
    const lines = io(files);
    expect(runCli(["state", "gas.json", "--at", "6000"], quiet.cli)).toBe(0);
    expect(runCli(["state", "gas.json", "--at", "6000", "--progress"], lines.cli)).toBe(0);
    expect(lines.out.stderr).toMatch(/^chapgame: t = [\d.e+]+ of 6000, 200000 events\n/);
    expect(lines.out.stdout).toBe(quiet.out.stdout);
    expect(JSON.parse(quiet.out.stdout).time).toBe(6000);
  });

  it("an error after progress was shown starts on a clean line (it was glued to the progress line)", () => {
    const gas = dilutedGas({ n: 200, packing: 0.2 });
    // at t = 6000 (about 260,000 events in) a disc resting on a floor under gravity: resting contact
    gas.actions.push(
      { time: 6000, type: "addLine", id: "floor", p1: [-50, -100], p2: [-10, -100], kind: "segment" },
      { time: 6000, type: "addBody", id: "rest", x: -30, y: -99, r: 1, m: 1 },
      { time: 6000, type: "setGlobal", gravity: [0, -1] },
    );
    const { cli, out } = io({ "gas.json": serializeScene(gas) }, true);
    expect(runCli(["simulate", "gas.json", "--until-time", "7000"], cli)).toBe(2);
    const last = out.stderr.split("\r").at(-1) as string;
    expect(
      last.startsWith(
        `${String.fromCharCode(27)}[Kchapgame: gas.json: cannot simulate this scene: body "rest"`,
      ),
    ).toBe(true);
    expect(JSON.parse(out.stdout)).toMatchObject({
      reason: "error",
      error: expect.stringMatching(/^body "rest"/),
    });
  });
});

describe("the progress line names what the run computes toward", () => {
  it("check: the time it checks to and the actions applied of all, while one is still to come", () => {
    // the gas (4 walls, 200 discs) and a kick at t = 10000, after both reports (about t = 4600, 9300)
    const files = { "gas.json": gasWith({ time: 10000, type: "giveVelocity", id: "d0", v: [1, 0] }) };
    const lines = io(files);
    expect(runCli(["check", "gas.json", "--progress"], lines.cli)).toBe(0);
    expect(timesAsT(lines.out.stderr)).toBe(
      "chapgame: t = T of 10000, 200000 events, 204 of 205 actions applied\n" +
        "chapgame: t = T of 10000, 400000 events, 204 of 205 actions applied\n",
    );
    const quiet = io(files);
    expect(runCli(["check", "gas.json"], quiet.cli)).toBe(0);
    expect(lines.out.stdout).toBe(quiet.out.stdout);
  });

  it("simulate: both bounds of the command line; the scene's own untils name none", () => {
    const files = { "gas.json": gasWith() };
    const both = io(files);
    expect(
      runCli(
        ["simulate", "gas.json", "--until-time", "1e9", "--max-events", "250000", "--progress"],
        both.cli,
      ),
    ).toBe(0);
    expect(timesAsT(both.out.stderr)).toBe("chapgame: t = T of 1000000000, 200000 of 250000 events\n");
    // an until on a kick at t = 1 (the scene's bound is that action, the until goes on past it)
    const until = { time: 1, type: "giveVelocity", id: "d0", v: [1, 0], until: { events: 250000 } };
    const own = io({ "gas.json": gasWith(until) });
    expect(runCli(["simulate", "gas.json", "--progress"], own.cli)).toBe(0);
    expect(JSON.parse(own.out.stdout).reason).toBe("until");
    expect(timesAsT(own.out.stderr)).toBe("chapgame: t = T, 200000 events\n");
  });

  it("a long scene says what it does before computing, then where the computation starts", () => {
    // a small scene made long by its meta (LONG_SCENE_CHARS characters and more)
    const scene = JSON.parse(gasWith({ time: 3, type: "giveVelocity", id: "d0", v: [1, 0] }));
    scene.meta = { note: "x".repeat(LONG_SCENE_CHARS) };
    const text = JSON.stringify(scene);
    const million = (text.length / 1e6).toFixed(1);
    const lines = io({ "long.json": text });
    expect(runCli(["check", "long.json", "--progress"], lines.cli)).toBe(0);
    expect(lines.out.stderr).toBe(
      `chapgame: reading the scene (${million} million characters)\n` +
        "chapgame: building the scene at t = 0 (205 actions)\n" +
        "chapgame: t = 0.00000 of 3, 0 events, 204 of 205 actions applied\n",
    );
    expect(JSON.parse(lines.out.stdout)).toMatchObject({ valid: true, checkedTo: 3 });
    // just below the length: nothing before the computation (and nothing during it: few events)
    scene.meta.note = "x".repeat(LONG_SCENE_CHARS - (text.length - LONG_SCENE_CHARS) - 1);
    const short = io({ "short.json": JSON.stringify(scene) });
    expect(runCli(["check", "short.json", "--progress"], short.cli)).toBe(0);
    expect(short.out.stderr).toBe("");
  });

  it("on a terminal a shorter line erases the rest of a longer one, and the line is gone before the result", () => {
    const scene = JSON.parse(gasWith());
    scene.meta = { note: "x".repeat(LONG_SCENE_CHARS) };
    const writes: string[] = [];
    const cli: CliIO = {
      readFile: () => JSON.stringify(scene),
      stdout: (t) => writes.push(`out:${t}`),
      stderr: (t) => writes.push(`err:${t}`),
      progress: true,
    };
    expect(runCli(["state", "long.json", "--at", "2"], cli)).toBe(0);
    const million = (JSON.stringify(scene).length / 1e6).toFixed(1);
    expect(writes.slice(0, 4)).toEqual([
      `err:\rchapgame: reading the scene (${million} million characters)`,
      "err:\rchapgame: building the scene at t = 0 (204 actions)\x1b[K",
      "err:\rchapgame: t = 0.00000 of 2, 0 events\x1b[K",
      "err:\r\x1b[K",
    ]);
    expect(writes.slice(4).every((w) => w.startsWith("out:"))).toBe(true);
    expect(JSON.parse(writes.slice(4).join("").replaceAll("out:", ""))).toMatchObject({ time: 2 });
  });
});

describe("progress on the bin's clock (CliIO.now), never on real time", () => {
  const files = { "gas.json": serializeScene(dilutedGas({ n: 200, packing: 0.2 })) };

  /** A clock that moves `step` ms each time it is read: once when the computation starts, then
   *  once after each slice that does not end it (as a scene that slow would). */
  function ticking(step: number) {
    let t = 1_000_000;
    return () => {
      const now = t;
      t += step;
      return now;
    };
  }
  /** Each event count of the lines of `stderr` (one line each, or a terminal's \r-separated). */
  const counts = (stderr: string) =>
    [...stderr.matchAll(/, (\d+)( of \d+)? events/g)].map((m) => Number(m[1]));

  it("shows a line half a second into the computation, then one a second, whatever the events", () => {
    // 60 ms a slice, between half the target and the target: every slice is FIRST_SLICE_EVENTS.
    // The clock reads 60, 120, ... after slices 1, 2, ...: lines after slice 9 (540 ms >= 500),
    // 26 (1560 >= 540 + 1000) and 43 (2580 >= 2560).
    expect([FIRST_SLICE_EVENTS, SLICE_TARGET_MS]).toEqual([1_000, 100]);
    const paced = io(files);
    paced.cli.now = ticking(60);
    expect(runCli(["simulate", "gas.json", "--max-events", "50000", "--progress"], paced.cli)).toBe(0);
    expect(timesAsT(paced.out.stderr)).toBe(
      "chapgame: t = T, 9000 of 50000 events\n" +
        "chapgame: t = T, 26000 of 50000 events\n" +
        "chapgame: t = T, 43000 of 50000 events\n",
    );
    // the same result as without a clock or without progress, byte for byte
    const quiet = io(files);
    expect(runCli(["simulate", "gas.json", "--max-events", "50000"], quiet.cli)).toBe(0);
    expect(quiet.out.stderr).toBe("");
    expect(paced.out.stdout).toBe(quiet.out.stdout);
  });

  it("a fast run shows no line before half a second, however many events (it showed one per 200,000)", () => {
    const fast = io(files);
    fast.cli.now = ticking(1); // 1 ms a slice: slices grow to SLICE_EVENTS, about 50 of them
    expect(runCli(["simulate", "gas.json", "--max-events", "450000", "--progress"], fast.cli)).toBe(0);
    expect(fast.out.stderr).toBe("");
    const unpaced = io(files); // without a clock: a line every 200,000 events
    expect(runCli(["simulate", "gas.json", "--max-events", "450000", "--progress"], unpaced.cli)).toBe(0);
    expect(counts(unpaced.out.stderr)).toEqual([200_000, 400_000]);
    expect(fast.out.stdout).toBe(unpaced.out.stdout);
  });

  it("a slow scene's slices shrink to the clock (down to one event) and lines keep coming; the result is the same", () => {
    // 300 ms a slice whatever its size: slices of 1000, 333, 111, 37, 12, 4, then 1 event
    const slow = io(files);
    slow.cli.now = ticking(300);
    expect(runCli(["simulate", "gas.json", "--max-events", "3000", "--progress"], slow.cli)).toBe(0);
    const shown = counts(slow.out.stderr);
    // lines at 600 ms (after slices of 1000 and 333 events), 1800 (after 111, 37, 12 and 4), then
    // every fourth slice of 1 event (1200 ms)
    expect(shown.slice(0, 2)).toEqual([1_000 + 333, 1_000 + 333 + 111 + 37 + 12 + 4]);
    expect(shown.slice(2).every((n, i) => n === (shown[i + 1] as number) + 4)).toBe(true);
    expect(shown.length).toBeGreaterThan(300);
    const quiet = io(files);
    expect(runCli(["simulate", "gas.json", "--max-events", "3000"], quiet.cli)).toBe(0);
    expect(slow.out.stdout).toBe(quiet.out.stdout);
  });

  it("on a terminal the clock's lines replace each other and are erased before the result (state, check too)", () => {
    const terminal = io(files, true);
    terminal.cli.now = ticking(60);
    expect(runCli(["state", "gas.json", "--at", "900"], terminal.cli)).toBe(0);
    const parts = terminal.out.stderr.split("\r");
    expect(parts[0]).toBe("");
    expect(parts.at(-1)).toBe("\x1b[K");
    const shown = parts.slice(1, -1).map((p) => timesAsT(p.replace("\x1b[K", "")));
    expect(shown).toEqual(["chapgame: t = T of 900, 9000 events", "chapgame: t = T of 900, 26000 events"]);
    expect(JSON.parse(terminal.out.stdout)).toMatchObject({ time: 900 });
    const check = io({ "gas.json": gasWith({ time: 900, type: "giveVelocity", id: "d0", v: [1, 0] }) });
    check.cli.now = ticking(60);
    expect(runCli(["check", "gas.json", "--progress"], check.cli)).toBe(0);
    expect(timesAsT(check.out.stderr)).toBe(
      "chapgame: t = T of 900, 9000 events, 204 of 205 actions applied\n" +
        "chapgame: t = T of 900, 26000 events, 204 of 205 actions applied\n",
    );
  });
});

describe("progress of a long read (a big file, a slow pipe, a device)", () => {
  /** A CliIO whose read reports `steps` bytes read, then gives a small valid scene. */
  function reading(steps: number[], progress = false, now?: () => number) {
    const r = io({}, progress);
    r.cli.readFile = (_path, told) => {
      for (const b of steps) told?.(b);
      return serializeScene(dilutedGas({ n: 4, packing: 0.2 }));
    };
    if (now !== undefined) r.cli.now = now;
    return r;
  }

  it("without a clock: a line each READ_REPORT_BYTES bytes, with --progress only", () => {
    const steps = [1e6, READ_REPORT_BYTES - 1, READ_REPORT_BYTES + 5e6, 2.5 * READ_REPORT_BYTES];
    const shown = reading(steps);
    expect(runCli(["check", "-", "--progress"], shown.cli)).toBe(0);
    expect(shown.out.stderr).toBe(
      "chapgame: reading the scene: 105.0 MB so far\nchapgame: reading the scene: 250.0 MB so far\n",
    );
    const quiet = reading(steps);
    expect(runCli(["check", "-"], quiet.cli)).toBe(0);
    expect(quiet.out.stderr).toBe("");
  });

  it("on the clock: the first line half a second into the read, then one a second", () => {
    let t = 0;
    const clock = () => {
      t += 300; // each read of the clock: 300 ms later
      return t;
    };
    const r = reading([1e6, 2e6, 3e6, 4e6, 5e6, 6e6], false, clock);
    expect(runCli(["check", "-", "--progress"], r.cli)).toBe(0);
    // start at 300; reads at 600 (300 ms: no), 900 (600 ms: a line), 1200, 1500 (no), 1800 (1500 ms:
    // no, 1 s after 600 ms is 1600 ms), 2100 (1800 ms: a line)
    expect(r.out.stderr.split("\n").filter((l) => l.includes("reading"))).toEqual([
      "chapgame: reading the scene: 2.0 MB so far",
      "chapgame: reading the scene: 6.0 MB so far",
    ]);
  });
});
