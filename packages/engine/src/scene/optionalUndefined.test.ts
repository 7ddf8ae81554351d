/**
 * An optional field of an action, an until or a scene given as `undefined` means the field left
 * out, as it does for the World's and the Timeline's options. This file is also a type test: the
 * repository compiles it under exactOptionalPropertyTypes (`npx tsc -p tsconfig.json --noEmit`),
 * where a value read from a config (`number | undefined`) must fit the optional fields of `Action`,
 * `Until`, `SceneFile` and `GasOptions` (audit of session 22: they did not, while the runtime
 * accepted it).
 */
import { describe, expect, it } from "vitest";
import { Timeline } from "../timeline/timeline.js";
import { checkAction } from "./action.js";
import { parseScene } from "./parse.js";
import { dilutedGas } from "./presets.js";
import { serializeScene } from "./serialize.js";
import type { Action, SceneFile, Until, Vec2 } from "./types.js";

/** What a form or a config gives: every optional value may be missing. */
interface Config {
  mu?: number | undefined;
  v?: Vec2 | undefined;
  x?: number | undefined;
  kind?: "line" | "ray" | "segment" | undefined;
  g?: number | undefined;
  seconds?: number | undefined;
  events?: number | undefined;
  meta?: Record<string, unknown> | undefined;
  seed?: number | undefined;
}

function fromConfig(cfg: Config): { scene: SceneFile; until: Until } {
  const until: Until = { time: cfg.seconds, events: cfg.events };
  const actions: Action[] = [
    { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, mu: cfg.mu, v: cfg.v, until: undefined },
    { time: 0, type: "addLine", id: "l", p1: [0, -5], p2: [1, -5], kind: "segment" },
    {
      time: 1,
      type: "updateBody",
      id: "a",
      x: cfg.x,
      y: undefined,
      v: cfg.v,
      r: undefined,
      m: undefined,
      mu: cfg.mu,
    },
    { time: 1, type: "updateLine", id: "l", p1: undefined, p2: undefined, kind: cfg.kind },
    { time: 2, type: "setGlobal", g: cfg.g, gravity: undefined, until },
  ];
  return { scene: { format: "chapgame", version: 1, g: 0, gravity: [0, 0], actions, meta: cfg.meta }, until };
}

describe("optional fields given as undefined", () => {
  it("read as left out: parseScene, checkAction and serializeScene drop them", () => {
    const { scene } = fromConfig({});
    const parsed = parseScene(scene);
    expect(parsed).not.toHaveProperty("meta");
    expect(parsed.actions).toEqual([
      { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, mu: 0, v: [0, 0] },
      { time: 0, type: "addLine", id: "l", p1: [0, -5], p2: [1, -5], kind: "segment" },
      { time: 1, type: "updateBody", id: "a" },
      { time: 1, type: "updateLine", id: "l" },
      { time: 2, type: "setGlobal", until: {} },
    ]);
    for (const a of parsed.actions) for (const v of Object.values(a)) expect(v).not.toBeUndefined();
    expect(checkAction(scene.actions[2], "action")).toEqual({ time: 1, type: "updateBody", id: "a" });
    expect(parseScene(serializeScene(scene))).toEqual(parsed);
  });

  it("a Timeline computes the same history as with the fields left out, and prolong takes such an until", () => {
    const cfg: Config = { mu: undefined, v: [2, 0], x: undefined, seconds: 3 };
    const { scene, until } = fromConfig(cfg);
    const withUndefined = Timeline.fromScene(scene);
    withUndefined.prolong(until);
    const leftOut = Timeline.fromScene(parseScene(serializeScene(scene)));
    leftOut.prolong({ time: 3 });
    expect(withUndefined.actions).toEqual(leftOut.actions);
    expect(withUndefined.horizon).toBe(leftOut.horizon);
    expect(withUndefined.stateAt(withUndefined.horizon)).toEqual(leftOut.stateAt(leftOut.horizon));
    expect(withUndefined.stateAt(withUndefined.horizon).bodies[0]?.x).toBe(2 * withUndefined.horizon);
  });

  it("dilutedGas takes a seed that may be missing: the default seed, 1", () => {
    const cfg: Config = {};
    expect(dilutedGas({ n: 20, packing: 0.1, seed: cfg.seed })).toEqual(
      dilutedGas({ n: 20, packing: 0.1, seed: 1 }),
    );
  });

  // types.ts keeps an addBody's mu and v optional, since Action is also what a program writes (the
  // Config above); what the engine returns always has them, as types.ts and scene-format.md say.
  it("every addBody the engine returns has mu and v, though the type leaves them optional", () => {
    const written: Action = { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 };
    const filled = { ...written, mu: 0, v: [0, 0] };
    const scene: SceneFile = { format: "chapgame", version: 1, g: 0, gravity: [0, 0], actions: [written] };
    expect(parseScene(scene).actions).toEqual([filled]);
    expect(parseScene(serializeScene(scene)).actions).toEqual([filled]);
    expect(checkAction(written, "action")).toEqual(filled);
    const tl = new Timeline({ g: 0 });
    tl.apply({ ...written, id: "b", x: 5, mu: undefined, v: undefined });
    tl.setActions([...tl.actions, { ...written, time: 1 }]);
    expect(tl.actions).toEqual([
      { ...filled, id: "b", x: 5 },
      { ...filled, time: 1 },
    ]);
    expect(tl.toScene().actions).toEqual(tl.actions);
    expect(Timeline.fromScene(scene).actions).toEqual([filled]);
  });
});
