// The path command (pathCommand.ts): a body's exact pieces over [--from, --to], an unknown id
// refused before computing, a body not there yet, and the pieces up to a Zeno state.
import { describe, expect, it } from "vitest";
import { runCli } from "./run.js";
import { io, RESTS_AT_5, sceneText } from "./testSupport.js";

describe("path: a body's exact pieces", () => {
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

  it("path refuses an id no body of the scene has, after the file's name, listing the bodies, before computing", () => {
    // the file's name first, as the other errors about a file's contents (audit of session 23: it had none)
    const { cli, out } = io({ "rest.json": sceneText(RESTS_AT_5) });
    expect(runCli(["path", "rest.json", "--id", "bal", "--to", "4"], cli)).toBe(2);
    expect(out.stdout).toBe("");
    expect(out.stderr).toBe('chapgame: rest.json: --id: no body "bal" in the scene (bodies: ball, rest)\n');
    const none = io({ "-": sceneText([]) });
    expect(runCli(["path", "-", "--id", "a", "--to", "1"], none.cli)).toBe(2);
    expect(none.out.stderr).toBe('chapgame: <stdin>: --id: no body "a" in the scene (it adds no body)\n');
    // an error about the arguments alone names no file
    const args = io({ "rest.json": sceneText(RESTS_AT_5) });
    expect(runCli(["path", "rest.json", "--id", "ball", "--from", "5", "--to", "4"], args.cli)).toBe(2);
    expect(args.out.stderr).toBe("chapgame: --from: must not be after --to (4) (got 5)\n");
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

  it("path --from T --to T prints the one point where the body is at T, as state --at T (it printed no piece)", () => {
    const files = {
      "late.json": sceneText([
        { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, v: [0, 1] },
        { time: 0, type: "addLine", id: "w", p1: [-5, 3], p2: [5, 3], kind: "line" },
        { time: 4, type: "removeBody", id: "a" },
        { time: 10, type: "addBody", id: "b", x: 10, y: 0, r: 1, m: 1 },
      ]),
    };
    const point = (id: string, t: string) => {
      const { cli, out } = io(files);
      expect(runCli(["path", "late.json", "--id", id, "--from", t, "--to", t], cli)).toBe(0);
      expect(out.stderr).toBe("");
      const result = JSON.parse(out.stdout);
      expect(result).toMatchObject({ id, from: Number(t), to: Number(t) });
      return result.pieces as {
        from: number;
        until: number;
        t0: number;
        x0: number;
        y0: number;
        vy: number;
        ay: number;
      }[];
    };
    // a hits the line at t = 2 and turns back: at 2 the motion after the collision
    for (const t of ["0", "1.5", "2", "3"]) {
      const pieces = point("a", t);
      expect(pieces.map((p) => [p.from, p.until, p.vy])).toEqual([
        [Number(t), Number(t), t === "0" || t === "1.5" ? 1 : -1],
      ]);
      const at = io(files);
      expect(runCli(["state", "late.json", "--at", t], at.cli)).toBe(0);
      const a = JSON.parse(at.out.stdout).bodies.find((q: { id: string }) => q.id === "a");
      const p = pieces[0] as (typeof pieces)[number];
      expect(p.y0 + (Number(t) - p.t0) * (p.vy + 0.5 * p.ay * (Number(t) - p.t0))).toBe(a.y);
    }
    expect(point("a", "4")).toEqual([]); // removed at 4
    expect(point("b", "9")).toEqual([]); // not added yet
    expect(point("b", "10").map((p) => [p.from, p.until, p.x0, p.y0])).toEqual([[10, 10, 10, 0]]); // added at 10
  });

  it("path meeting a Zeno state before --to prints the pieces up to where it stopped, then exits 2", () => {
    const { cli, out } = io({ "rest.json": sceneText(RESTS_AT_5) });
    expect(runCli(["path", "rest.json", "--id", "ball", "--to", "8"], cli)).toBe(2);
    expect(out.stderr).toMatch(/^chapgame: rest\.json: cannot simulate this scene: body "rest" rests .*\n$/);
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
});
