// runCli in-process: --version, exit statuses and the one-line errors, a run the engine cannot
// continue (its result up to there), what the JSON writes for infinities, and a whole run.
import { describe, expect, it } from "vitest";
import { galperin } from "../scene/presets.js";
import { serializeScene } from "../scene/serialize.js";
import { OutputError, runCli } from "./run.js";
import { io, RESTS_AT_5, sceneText } from "./testSupport.js";

describe("runCli in-process", () => {
  it("--version prints the version the bin gives, or says it is unknown", () => {
    const withVersion = io({});
    withVersion.cli.version = "1.2.3";
    expect(runCli(["--version"], withVersion.cli)).toBe(0);
    expect(withVersion.out.stdout).toBe("chapgame 1.2.3\n");
    const without = io({});
    expect(runCli(["--version"], without.cli)).toBe(0);
    expect(without.out.stdout).toBe("chapgame (version unknown)\n");
  });

  it("a file that cannot be read: one line saying why in words, exit 2, nothing on stdout", () => {
    // Node's message ("ENOENT: no such file or directory, open 'nope.json'") named the file twice.
    const { cli, out } = io({});
    expect(runCli(["simulate", "nope.json"], cli)).toBe(2);
    expect(out).toEqual({ stdout: "", stderr: "chapgame: cannot read nope.json: no such file (ENOENT)\n" });
    const failing = (error: Error) => {
      const r = io({});
      r.cli.readFile = () => {
        throw error;
      };
      expect(runCli(["check", "s.json"], r.cli)).toBe(2);
      expect(r.out.stdout).toBe("");
      return r.out.stderr;
    };
    const coded = (code: string) => Object.assign(new Error(`${code}: node's text`), { code });
    expect(failing(coded("EISDIR"))).toBe(
      "chapgame: cannot read s.json: it is a folder, not a file (EISDIR)\n",
    );
    expect(failing(coded("EACCES"))).toBe("chapgame: cannot read s.json: permission denied (EACCES)\n");
    // a code without words of its own keeps the system's message (its first line)
    expect(failing(coded("EIO"))).toBe("chapgame: cannot read s.json: EIO: node's text\n");
    // a 600 MB file said only "Cannot create a string longer than 0x1fffffe8 characters" (review of session 31)
    expect(failing(coded("ERR_STRING_TOO_LONG"))).toBe(
      "chapgame: cannot read s.json: it gives more text than a JavaScript string can hold (0x1fffffe8, about 537 million characters), so no scene that large can be read: reading stopped there (ERR_STRING_TOO_LONG)\n",
    );
    // standard input is named in words, not "-"
    const stdin = io({});
    stdin.cli.readFile = () => {
      throw coded("ERR_STRING_TOO_LONG");
    };
    expect(runCli(["check", "-"], stdin.cli)).toBe(2);
    expect(stdin.out.stderr).toMatch(/^chapgame: cannot read standard input: it gives more text /);
    expect(failing(new Error("not UTF-8 text: byte 0xE9\nmore"))).toBe(
      "chapgame: cannot read s.json: not UTF-8 text: byte 0xE9\n",
    );
  });

  it("a run the engine cannot continue prints the result up to where it stopped, then exits 2", () => {
    // Audit of session 15: exit 2 and nothing on stdout, so the events computed before were lost.
    const { cli, out } = io({ "rest.json": sceneText(RESTS_AT_5) });
    expect(runCli(["simulate", "rest.json", "--events"], cli)).toBe(2);
    expect(out.stderr).toMatch(/^chapgame: rest\.json: cannot simulate this scene: body "rest" rests .*\n$/);
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
    expect(out.stderr).toMatch(/^chapgame: rest\.json: cannot simulate this scene: body "rest" rests .*\n$/);
    const result = JSON.parse(out.stdout);
    expect(result).toMatchObject({ reason: "error", time: 5, events: 3 });
    // the ball has just met the right wall (x = 10 - r) and is on its way back
    const ball = result.bodies.find((b: { id: string }) => b.id === "ball");
    expect(ball).toMatchObject({ x: 9, y: 0, vx: -9, vy: 0 });
  });

  it("refuses a time past TIME_MAX, where a fall overflowed to y = -Infinity, before reading the file (exit 2)", () => {
    // it printed "y": "-Infinity" at --at 1e160 (review of session 31: times past TIME_MAX are refused)
    const fall = sceneText([{ time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 }], [0, -10]);
    const { cli, out } = io({ "fall.json": fall });
    expect(runCli(["state", "fall.json", "--at", "1e160"], cli)).toBe(2);
    expect(out.stdout).toBe("");
    expect(out.stderr).toMatch(/^chapgame: --at: must be at most 1e\+30 \(TIME_MAX\) \(got "1e160"\)/);
    expect(runCli(["state", "fall.json", "--at", "1e30"], cli)).toBe(0);
    expect(out.stdout).toContain('"y": -5e+60');
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
