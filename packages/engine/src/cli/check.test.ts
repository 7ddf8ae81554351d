// The check command (check.ts): a scene file validated whole, up to its last action.
import { describe, expect, it } from "vitest";
import { dilutedGas } from "../scene/presets.js";
import { serializeScene } from "../scene/serialize.js";
import { runCli } from "./run.js";
import { io, RESTS_AT_5, sceneText } from "./testSupport.js";

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
      error: expect.stringMatching(/^body "rest" rests/),
    });
    expect(z.stderr).toMatch(/^chapgame: s\.json: cannot simulate this scene: body "rest" rests/);
    const j = check('{"format": "chapgame", "version": 1,');
    expect(j.status).toBe(2);
    expect(j.result.valid).toBe(false);
    expect(j.result.error).toMatch(/JSON/);
  });

  it("--compact writes the same object on one line, valid or not", () => {
    const run = (text: string, argv: string[]) => {
      const { cli, out } = io({ "s.json": text });
      return { status: runCli(argv, cli), ...out };
    };
    const ok = sceneText(RESTS_AT_5.filter((a) => a.type !== "setGlobal"));
    const wide = run(ok, ["check", "s.json"]);
    const compact = run(ok, ["check", "s.json", "--compact"]);
    expect(compact.status).toBe(0);
    expect(compact.stdout).toBe('{"valid":true,"actions":5,"checkedTo":0,"events":0}\n');
    expect(JSON.parse(compact.stdout)).toEqual(JSON.parse(wide.stdout));
    const bad = sceneText([{ time: 0, type: "addBody", id: "a", x: 0, y: 0, r: -1, m: 1 }]);
    const refused = run(bad, ["check", "--compact", "s.json"]);
    expect(refused.status).toBe(2);
    expect(refused.stdout.split("\n")).toEqual([
      expect.stringMatching(/^\{"valid":false,"error":"actions\[0\]\.r: /),
      "",
    ]);
    expect(JSON.parse(refused.stdout)).toEqual(JSON.parse(run(bad, ["check", "s.json"]).stdout));
  });
});
