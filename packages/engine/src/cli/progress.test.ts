// Progress on stderr (progress.ts): an updating line on a terminal, one line each with --progress,
// nothing otherwise; the result on stdout is the same either way.
import { describe, expect, it } from "vitest";
import { dilutedGas } from "../scene/presets.js";
import { serializeScene } from "../scene/serialize.js";
import { runCli } from "./run.js";
import { io } from "./testSupport.js";

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
    expect(lines.out.stderr).toMatch(/^chapgame: t = [\d.e+]+, 200000 events\n/);
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
        `${String.fromCharCode(27)}[Kchapgame: gas.json: cannot simulate this scene: body 'rest'`,
      ),
    ).toBe(true);
    expect(JSON.parse(out.stdout)).toMatchObject({
      reason: "error",
      error: expect.stringMatching(/^body 'rest'/),
    });
  });
});
