import { describe, expect, it } from "vitest";
import { dilutedGas, galperin } from "../scene/presets.js";
import { serializeScene } from "../scene/serialize.js";
import { USAGE } from "./args.js";
import { type CliIO, OutputError, runCli, runCliInterruptible } from "./run.js";
import { type InterruptSignal, SLICE_EVENTS } from "./slices.js";

function io(files: Record<string, string>, progress = false) {
  const out = { stdout: "", stderr: "" };
  const cli: CliIO = {
    readFile: (p) => {
      const f = files[p];
      if (f === undefined) throw new Error(`ENOENT: no such file or directory, open '${p}'`);
      return f;
    },
    stdout: (t) => {
      out.stdout += t;
    },
    stderr: (t) => {
      out.stderr += t;
    },
    progress,
  };
  return { cli, out };
}

/** A version-1 scene file's text: these actions, no friction field, the given gravity. */
function sceneText(actions: unknown[], gravity: [number, number] = [0, 0]): string {
  return JSON.stringify({ format: "chapgame", version: 1, g: 0, gravity, actions });
}

/** A disc bounces between two walls; at t = 5 gravity comes on under a disc resting on a floor. */
const RESTS_AT_5 = [
  { time: 0, type: "addLine", id: "left", p1: [-10, -5], p2: [-10, 5], kind: "line" },
  { time: 0, type: "addLine", id: "right", p1: [10, -5], p2: [10, 5], kind: "line" },
  { time: 0, type: "addLine", id: "floor", p1: [-50, -100], p2: [-30, -100], kind: "segment" },
  { time: 0, type: "addBody", id: "ball", x: 0, y: 0, r: 1, m: 1, v: [9, 0] },
  { time: 0, type: "addBody", id: "rest", x: -40, y: -99, r: 1, m: 1 },
  { time: 5, type: "setGlobal", gravity: [0, -1] },
];

describe("runCli in-process", () => {
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
    expect(lines.out.stderr).toMatch(/^chapgame: t = [\d.e+]+, 200000 events\n/);
    expect(lines.out.stdout).toBe(quiet.out.stdout);
    expect(JSON.parse(quiet.out.stdout).time).toBe(6000);
  });

  it("--version prints the version the bin gives, or says it is unknown", () => {
    const withVersion = io({});
    withVersion.cli.version = "1.2.3";
    expect(runCli(["--version"], withVersion.cli)).toBe(0);
    expect(withVersion.out.stdout).toBe("chapgame 1.2.3\n");
    const without = io({});
    expect(runCli(["--version"], without.cli)).toBe(0);
    expect(without.out.stdout).toBe("chapgame (version unknown)\n");
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
        `${String.fromCharCode(27)}[Kchapgame: gas.json: cannot simulate this scene: body 'rest'`,
      ),
    ).toBe(true);
    expect(JSON.parse(out.stdout)).toMatchObject({
      reason: "error",
      error: expect.stringMatching(/^body 'rest'/),
    });
  });

  it("a run the engine cannot continue prints the result up to where it stopped, then exits 2", () => {
    // Audit of session 15: exit 2 and nothing on stdout, so the events computed before were lost.
    const { cli, out } = io({ "rest.json": sceneText(RESTS_AT_5) });
    expect(runCli(["simulate", "rest.json", "--events"], cli)).toBe(2);
    expect(out.stderr).toMatch(/^chapgame: rest\.json: cannot simulate this scene: body 'rest' rests .*\n$/);
    const result = JSON.parse(out.stdout);
    const why = out.stderr.replace("chapgame: rest.json: cannot simulate this scene: ", "").trim();
    expect(result).toMatchObject({ reason: "error", error: why, time: 5, events: 3 });
    // the ball meets a wall every 2 s from t = 1: the collisions up to the failure are all there
    const hits = result.log.filter((e: { type: string }) => e.type === "bodyLine");
    expect(hits.map((e: { time: number }) => e.time)).toEqual([1, 3, 5]);
  });

  it("state meeting a Zeno state before --at prints the bodies where it stopped, then exits 2", () => {
    // Session 16 left it printing nothing: the state at T cannot be computed, the state at the
    // failure can (the same scene as above: the failure at t = 5)
    const { cli, out } = io({ "rest.json": sceneText(RESTS_AT_5) });
    expect(runCli(["state", "rest.json", "--at", "8"], cli)).toBe(2);
    expect(out.stderr).toMatch(/^chapgame: rest\.json: cannot simulate this scene: body 'rest' rests .*\n$/);
    const result = JSON.parse(out.stdout);
    expect(result).toMatchObject({ reason: "error", time: 5, events: 3 });
    // the ball has just met the right wall (x = 10 - r) and is on its way back
    const ball = result.bodies.find((b: { id: string }) => b.id === "ball");
    expect(ball).toMatchObject({ x: 9, y: 0, vx: -9, vy: 0 });
  });

  it("path prints the ball's exact pieces, split at its collisions, matching state at any time", () => {
    const files = { "rest.json": sceneText(RESTS_AT_5.filter((a) => a.id !== "rest" && a.time === 0)) };
    const { cli, out } = io(files);
    expect(runCli(["path", "rest.json", "--id", "ball", "--from", "0.5", "--to", "4"], cli)).toBe(0);
    expect(out.stderr).toBe("");
    const result = JSON.parse(out.stdout);
    expect(result).toMatchObject({ id: "ball", from: 0.5, to: 4 });
    // the ball meets a wall at t = 1 and t = 3: three pieces, each with its constant velocity
    const spans = result.pieces.map((p: { from: number; until: number; vx: number }) => [
      p.from,
      p.until,
      p.vx,
    ]);
    expect(spans).toEqual([
      [0.5, 1, 9],
      [1, 3, -9],
      [3, 4, 9],
    ]);
    expect(Object.keys(result.pieces[0])).toEqual([
      "from",
      "until",
      "t0",
      "x0",
      "y0",
      "vx",
      "vy",
      "ax",
      "ay",
      "tStop",
    ]);
    expect(result.pieces[0].tStop).toBe("Infinity"); // no friction: it never stops (JSON has no Infinity)
    for (const t of [0.5, 2.25, 3.5, 4]) {
      const at = io(files);
      expect(runCli(["state", "rest.json", "--at", String(t)], at.cli)).toBe(0);
      const ball = JSON.parse(at.out.stdout).bodies.find((b: { id: string }) => b.id === "ball");
      const p = result.pieces.find((q: { from: number; until: number }) => q.from <= t && t <= q.until);
      expect(p.x0 + (t - p.t0) * (p.vx + 0.5 * p.ax * (t - p.t0))).toBe(ball.x);
    }
    // --compact: the same JSON, one piece per line
    const compact = io(files);
    expect(
      runCli(["path", "rest.json", "--id", "ball", "--from", "0.5", "--to", "4", "--compact"], compact.cli),
    ).toBe(0);
    expect(JSON.parse(compact.out.stdout)).toEqual(result);
    expect(compact.out.stdout.split("\n")).toHaveLength(6);
    expect(JSON.stringify(JSON.parse(out.stdout), null, 2)).toBe(out.stdout.trimEnd());
  });

  it("path refuses an id no body of the scene has, listing the bodies, before computing", () => {
    const { cli, out } = io({ "rest.json": sceneText(RESTS_AT_5) });
    expect(runCli(["path", "rest.json", "--id", "bal", "--to", "4"], cli)).toBe(2);
    expect(out.stdout).toBe("");
    expect(out.stderr).toBe('chapgame: --id: no body "bal" in the scene (bodies: ball, rest)\n');
  });

  it("path of a body the scene adds only after --to prints no piece, exit 0 (it was an internal error, exit 1)", () => {
    const files = {
      "late.json": sceneText([
        { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, v: [0, 1] },
        { time: 10, type: "addBody", id: "b", x: 10, y: 0, r: 1, m: 1 },
      ]),
    };
    const spans: [string, string][] = [
      ["0", "5"],
      ["2", "5"],
      ["0", "10"],
    ];
    for (const [from, to] of spans) {
      const { cli, out } = io(files);
      expect(runCli(["path", "late.json", "--id", "b", "--from", from, "--to", to], cli)).toBe(0);
      expect(out.stderr).toBe("");
      expect(JSON.parse(out.stdout)).toEqual({ id: "b", from: Number(from), to: Number(to), pieces: [] });
    }
    const { cli, out } = io(files);
    expect(runCli(["path", "late.json", "--id", "b", "--to", "12"], cli)).toBe(0);
    expect(
      JSON.parse(out.stdout).pieces.map((p: { from: number; until: number }) => [p.from, p.until]),
    ).toEqual([[10, 12]]);
  });

  it("path meeting a Zeno state before --to prints the pieces up to where it stopped, then exits 2", () => {
    const { cli, out } = io({ "rest.json": sceneText(RESTS_AT_5) });
    expect(runCli(["path", "rest.json", "--id", "ball", "--to", "8"], cli)).toBe(2);
    expect(out.stderr).toMatch(/^chapgame: rest\.json: cannot simulate this scene: body 'rest' rests .*\n$/);
    const result = JSON.parse(out.stdout);
    expect(result).toMatchObject({ id: "ball", from: 0, to: 5, reason: "error" });
    expect(result.pieces.map((p: { until: number }) => p.until)).toEqual([1, 3, 5]);
    // started after the failure: no piece, still the reason
    const late = io({ "rest.json": sceneText(RESTS_AT_5) });
    expect(runCli(["path", "rest.json", "--id", "ball", "--from", "6", "--to", "8"], late.cli)).toBe(2);
    expect(JSON.parse(late.out.stdout)).toEqual({
      id: "ball",
      from: 6,
      to: 5,
      reason: "error",
      error: result.error,
      pieces: [],
    });
  });

  it("simulate --until-time T stops at T when an action is still scheduled after T (it printed t = 0)", () => {
    const late = sceneText([
      { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, v: [1, 0] },
      { time: 5, type: "addBody", id: "b", x: 20, y: 0, r: 1, m: 1, v: [-1, 0] },
    ]);
    const { cli, out } = io({ "late.json": late });
    expect(runCli(["simulate", "late.json", "--until-time", "2"], cli)).toBe(0);
    const r = JSON.parse(out.stdout);
    expect(r.time).toBe(2);
    expect(r.bodies.map((b: { id: string; x: number }) => [b.id, b.x])).toEqual([["a", 2]]);
  });

  it("simulate --until-time T prints the bodies at T when no event is left before T (it printed the last event's time)", () => {
    const files = {
      "pair.json": sceneText([
        { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, v: [1, 0] },
        { time: 0, type: "addBody", id: "b", x: 5, y: 0, r: 1, m: 1 },
      ]),
    };
    const atT = io(files);
    expect(runCli(["simulate", "pair.json", "--until-time", "30"], atT.cli)).toBe(0);
    const r = JSON.parse(atT.out.stdout);
    // a stops at 3 where b was hit; b glides on at 1 from x = 5: x = 32 at t = 30
    expect(r).toMatchObject({ time: 30, reason: "idle", events: 1 });
    expect(r.bodies.map((b: { id: string; x: number; vx: number }) => [b.id, b.x, b.vx])).toEqual([
      ["a", 3, 0],
      ["b", 32, 1],
    ]);
    // Without a time bound the run stops at its last event; an event bound says so.
    const open = io(files);
    expect(runCli(["simulate", "pair.json"], open.cli)).toBe(0);
    expect(JSON.parse(open.out.stdout)).toMatchObject({ time: 3, reason: "idle" });
    // An event limit that lands on the last event: nothing is left, so the run is idle at T (review).
    const capped = io(files);
    expect(runCli(["simulate", "pair.json", "--max-events", "1", "--until-time", "30"], capped.cli)).toBe(0);
    expect(JSON.parse(capped.out.stdout)).toMatchObject({ time: 30, reason: "idle" });
  });

  it("reason is idle when only discs gliding across grid cells are left (the queue still held crossings: it said time)", () => {
    // 40 discs at rest 10 apart (enough for the grid) and one gliding past them all: no event ever.
    const actions: unknown[] = [
      { time: 0, type: "addBody", id: "glider", x: -5, y: 50, r: 1, m: 1, v: [1, 0] },
    ];
    for (let i = 0; i < 40; i++)
      actions.push({
        time: 0,
        type: "addBody",
        id: `s${i}`,
        x: 10 * (i % 8),
        y: 10 * Math.floor(i / 8),
        r: 1,
        m: 1,
      });
    const files = { "glide.json": sceneText(actions) };
    const idle = io(files);
    expect(runCli(["simulate", "glide.json", "--until-time", "10"], idle.cli)).toBe(0);
    expect(JSON.parse(idle.out.stdout)).toMatchObject({ time: 10, reason: "idle", events: 0 });
    // With an event still to come, the time limit is the reason.
    const wall = { time: 0, type: "addLine", id: "wall", p1: [200, 0], p2: [200, 100], kind: "segment" };
    const timed = io({ "hit.json": sceneText([...actions, wall]) });
    expect(runCli(["simulate", "hit.json", "--until-time", "10"], timed.cli)).toBe(0);
    expect(JSON.parse(timed.out.stdout)).toMatchObject({ time: 10, reason: "time", events: 0 });
  });

  it('writes a position that overflowed to -Infinity as "-Infinity", not null', () => {
    const fall = sceneText([{ time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 }], [0, -10]);
    const { cli, out } = io({ "fall.json": fall });
    expect(runCli(["state", "fall.json", "--at", "1e160"], cli)).toBe(0);
    expect(out.stdout).toContain('"y": "-Infinity"');
    expect(out.stdout).not.toContain("null");
  });

  it("writes control characters of a key in a message as escapes (an ESC reached the terminal raw)", () => {
    const bad = '{"format":"chapgame","version":1,"\\u001b[31mX":1,"actions":[]}';
    const { cli, out } = io({ "esc.json": bad });
    expect(runCli(["simulate", "esc.json"], cli)).toBe(2);
    expect(out.stderr).toBe(
      "chapgame: esc.json: \\u001b[31mX: unknown field (known: format, version, g, gravity, actions, meta)\n",
    );
  });

  it("a result that cannot be written exits 1 naming the write, not an internal error", () => {
    const { cli, out } = io({ "g.json": serializeScene(galperin(1)) });
    cli.stdout = () => {
      throw new OutputError("ENOSPC: no space left on device, write");
    };
    expect(runCli(["simulate", "g.json"], cli)).toBe(1);
    expect(out.stderr).toBe("chapgame: cannot write the result: ENOSPC: no space left on device, write\n");
  });

  it("counts Galperin's collisions (3 digits: 314)", () => {
    const { cli, out } = io({ "g.json": serializeScene(galperin(3)) });
    expect(runCli(["simulate", "g.json"], cli)).toBe(0);
    const r = JSON.parse(out.stdout);
    expect(r.events).toBe(314);
    expect(r.counts.bodyBody + r.counts.bodyLine).toBe(314);
  });

  it("an internal error exits 1 with one line", () => {
    const { cli, out } = io({ "g.json": serializeScene(galperin(1)) });
    cli.stdout = () => {
      throw new Error("disk full");
    };
    expect(runCli(["simulate", "g.json"], cli)).toBe(1);
    expect(out.stderr).toBe("chapgame: internal error: disk full\n");
  });
});

/** Pauses at once; reports `signal` from the `after`-th pause on. */
function interruptAfter(after: number, signal: InterruptSignal) {
  let pauses = 0;
  return {
    pause: async () => {
      pauses++;
    },
    interrupted: () => (pauses >= after ? signal : null),
  };
}

describe("check: a scene file validated whole, up to its last action", () => {
  const check = (text: string) => {
    const { cli, out } = io({ "s.json": text });
    const status = runCli(["check", "s.json"], cli);
    return { status, result: JSON.parse(out.stdout), stderr: out.stderr };
  };

  it("a valid scene: its actions, the time checked to and the events on the way", () => {
    const r = check(sceneText(RESTS_AT_5.filter((a) => a.type !== "setGlobal")));
    expect(r).toEqual({
      status: 0,
      result: { valid: true, actions: 5, checkedTo: 0, events: 0 },
      stderr: "",
    });
    // a gas that never comes to rest, with an action at t = 3: checked to 3, and the run ends
    const gas = dilutedGas({ n: 50, packing: 0.1 });
    const first = gas.actions.find((a) => a.type === "addBody") as { id: string };
    gas.actions.push({ time: 3, type: "giveVelocity", id: first.id, v: [1, 1] });
    const g = check(serializeScene(gas));
    expect(g.status).toBe(0);
    expect(g.result).toMatchObject({ valid: true, checkedTo: 3 });
    expect(g.result.events).toBeGreaterThan(0);
  });

  it("a bad field, naming it", () => {
    const r = check(sceneText([{ time: 0, type: "addBody", id: "a", x: 0, y: 0, r: -1, m: 1 }]));
    expect(r.status).toBe(2);
    expect(r.result).toEqual({
      valid: false,
      error: expect.stringMatching(/^actions\[0\]\.r: /),
      path: "actions[0].r",
    });
    expect(r.stderr).toBe(`chapgame: s.json: ${r.result.error}\n`);
  });

  it("an action the simulation refuses later on (simulate --until-time before it would not see it)", () => {
    const r = check(
      sceneText([
        { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, v: [1, 0] },
        { time: 10, type: "addBody", id: "b", x: 10, y: 0, r: 1, m: 1 },
      ]),
    );
    expect(r.status).toBe(2);
    expect(r.result).toMatchObject({ valid: false, path: "actions[1]" });
    expect(r.result.error).toMatch(/overlap/);
  });

  it("a Zeno state before the last action, and broken JSON", () => {
    const z = check(sceneText([...RESTS_AT_5, { time: 8, type: "giveVelocity", id: "ball", v: [1, 0] }]));
    expect(z.status).toBe(2);
    expect(z.result).toMatchObject({
      valid: false,
      path: null,
      error: expect.stringMatching(/^body 'rest' rests/),
    });
    expect(z.stderr).toMatch(/^chapgame: s\.json: cannot simulate this scene: body 'rest' rests/);
    const j = check('{"format": "chapgame", "version": 1,');
    expect(j.status).toBe(2);
    expect(j.result.valid).toBe(false);
    expect(j.result.error).toMatch(/JSON/);
  });
});

describe("runCliInterruptible: an interrupt prints the result so far", () => {
  const files = { "gas.json": serializeScene(dilutedGas({ n: 100, packing: 0.2 })) };

  it("simulate without a bound (a gas never rests): reason interrupted, exit 130, the bodies of exactly that many events", async () => {
    // Audit: Ctrl-C killed the synchronous run and printed nothing.
    const cut = io(files);
    expect(
      await runCliInterruptible(["simulate", "gas.json", "--events"], cut.cli, interruptAfter(3, "SIGINT")),
    ).toBe(130);
    const r = JSON.parse(cut.out.stdout);
    expect(r).toMatchObject({ reason: "interrupted", events: 3 * SLICE_EVENTS });
    expect(cut.out.stderr).toMatch(
      new RegExp(
        `^chapgame: gas\\.json: interrupted by SIGINT at t = [\\d.]+ after ${3 * SLICE_EVENTS} events: the result up to there is printed\n$`,
      ),
    );
    // slicing changed nothing: the same history as a run bounded at that many events
    const capped = io(files);
    expect(
      runCli(["simulate", "gas.json", "--events", "--max-events", String(3 * SLICE_EVENTS)], capped.cli),
    ).toBe(0);
    expect({ ...JSON.parse(capped.out.stdout), reason: "interrupted" }).toEqual(r);
  });

  it("state --at T interrupted before T: the bodies where the computation got to, reason interrupted, exit 143 (SIGTERM)", async () => {
    const cut = io(files);
    expect(
      await runCliInterruptible(["state", "gas.json", "--at", "1e9"], cut.cli, interruptAfter(1, "SIGTERM")),
    ).toBe(143);
    const r = JSON.parse(cut.out.stdout);
    expect(r).toMatchObject({ reason: "interrupted", events: SLICE_EVENTS });
    expect(r.time).toBeLessThan(1e9);
    const at = io(files);
    expect(runCli(["state", "gas.json", "--at", String(r.time)], at.cli)).toBe(0);
    expect(JSON.parse(at.out.stdout).bodies).toEqual(r.bodies);
  });

  it("path --to T interrupted before T: the pieces up to where the computation got to, exit 130", async () => {
    const id = (JSON.parse(files["gas.json"]).actions as { type: string; id: string }[]).find(
      (a) => a.type === "addBody",
    )?.id as string;
    const cut = io(files);
    expect(
      await runCliInterruptible(
        ["path", "gas.json", "--id", id, "--to", "1e9"],
        cut.cli,
        interruptAfter(1, "SIGINT"),
      ),
    ).toBe(130);
    const r = JSON.parse(cut.out.stdout);
    expect(r).toMatchObject({ id, from: 0, reason: "interrupted" });
    expect(r.to).toBeLessThan(1e9);
    expect(r.pieces.length).toBeGreaterThan(0);
    expect(r.pieces.at(-1).until).toBe(r.to);
    // the same pieces as a run that computes just up to there
    const upTo = io(files);
    expect(runCli(["path", "gas.json", "--id", id, "--to", String(r.to)], upTo.cli)).toBe(0);
    expect(JSON.parse(upTo.out.stdout).pieces).toEqual(r.pieces);
  });

  it("check interrupted before its last action: nothing on stdout, a line on stderr, exit 130, as the help says", async () => {
    // Audit of session 21: the help said every interrupted run prints its result; check prints none.
    const scene = JSON.parse(files["gas.json"]);
    scene.actions.push({ time: 1e9, type: "removeBody", id: scene.actions.at(-1).id });
    const cut = io({ "late.json": JSON.stringify(scene) });
    expect(await runCliInterruptible(["check", "late.json"], cut.cli, interruptAfter(1, "SIGINT"))).toBe(130);
    expect(cut.out.stdout).toBe("");
    expect(cut.out.stderr).toMatch(
      /^chapgame: late\.json: interrupted by SIGINT at t = [\d.e+]+: the check did not finish\n$/,
    );
    expect(USAGE).toContain("an interrupted check prints nothing on standard\noutput");
  });

  it("a run that ends before any interrupt gives the result runCli gives", async () => {
    const { cli, out } = io({ "g.json": serializeScene(galperin(3)) });
    expect(await runCliInterruptible(["simulate", "g.json"], cli, interruptAfter(1, "SIGINT"))).toBe(0);
    expect(JSON.parse(out.stdout)).toMatchObject({ reason: "idle", events: 314 });
  });
});

describe("simulate honours the scene's own until when the command line gives no bound", () => {
  // a disc between two walls (it never rests); the addBody's until says how far to compute
  const box = (until: unknown) =>
    sceneText([
      { time: 0, type: "addLine", id: "l", p1: [-10, -5], p2: [-10, 5], kind: "line" },
      { time: 0, type: "addLine", id: "r", p1: [10, -5], p2: [10, 5], kind: "line" },
      { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, v: [3, 0], until },
      { time: 2, type: "giveVelocity", id: "a", v: [-5, 0] },
    ]);

  it('until { time: 30 }: up to t = 30, "reason": "until", the state --until-time 30 gives (it ran for ever)', () => {
    const files = { "box.json": box({ time: 30 }) };
    const own = io(files);
    expect(runCli(["simulate", "box.json"], own.cli)).toBe(0);
    const r = JSON.parse(own.out.stdout);
    expect(r).toMatchObject({ time: 30, reason: "until", events: 7 });
    const timed = io(files);
    expect(runCli(["simulate", "box.json", "--until-time", "30"], timed.cli)).toBe(0);
    expect({ ...JSON.parse(timed.out.stdout), reason: "until" }).toEqual(r);
  });

  it("until { events: 5 }: five events after the action; the command line's bounds win", () => {
    const files = { "box.json": box({ events: 5 }) };
    const own = io(files);
    expect(runCli(["simulate", "box.json"], own.cli)).toBe(0);
    expect(JSON.parse(own.out.stdout)).toMatchObject({ reason: "until", events: 5 });
    const events = io(files);
    expect(runCli(["simulate", "box.json", "--max-events", "2"], events.cli)).toBe(0);
    expect(JSON.parse(events.out.stdout)).toMatchObject({ reason: "events", events: 2 });
    const time = io(files);
    expect(runCli(["simulate", "box.json", "--until-time", "50"], time.cli)).toBe(0);
    expect(JSON.parse(time.out.stdout)).toMatchObject({ time: 50, reason: "time" });
  });

  it("a scene idle before its bound: reason idle, the bodies at the bound (they glide on)", () => {
    const files = {
      "pair.json": sceneText([
        { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, v: [1, 0], until: { time: 30 } },
        { time: 0, type: "addBody", id: "b", x: 5, y: 0, r: 1, m: 1 },
      ]),
    };
    const { cli, out } = io(files);
    expect(runCli(["simulate", "pair.json"], cli)).toBe(0);
    const r = JSON.parse(out.stdout);
    expect(r).toMatchObject({ time: 30, reason: "idle", events: 1 });
    expect(r.bodies.map((b: { id: string; x: number }) => [b.id, b.x])).toEqual([
      ["a", 3],
      ["b", 32],
    ]);
  });
});
