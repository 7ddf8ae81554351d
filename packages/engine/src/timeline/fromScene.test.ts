// Timeline.fromScene validates the scene once (parseScene), not again in setActions and again when
// the actions at time 0 are applied: the timeline is the one setActions builds, and every later edit
// is checked in full.
import { describe, expect, it } from "vitest";
import { parseScene } from "../scene/parse.js";
import { dilutedGas } from "../scene/presets.js";
import type { Action } from "../scene/types.js";
import { disc, fingerprint, scene } from "./testSupport.js";
import { Timeline } from "./timeline.js";

/** A gas kicked at t = 2 and t = 4, with a body added at t = 3. */
function kickedGas() {
  const s = dilutedGas({ n: 40, packing: 0.15, seed: 3 });
  const first = s.actions.find((a) => a.type === "addBody") as Action & { id: string };
  s.actions.push(
    { time: 2, type: "giveVelocity", id: first.id, v: [2, -1] },
    { time: 4, type: "giveVelocity", id: first.id, v: [-1, 1] },
    disc("late", -1000, -1000, [0, 0], 3),
  );
  return s;
}

describe("Timeline.fromScene: one validation, the same timeline", () => {
  it("builds what new Timeline + setActions builds, with history and without, computed or not", () => {
    const s = kickedGas();
    for (const options of [{}, { history: false }, { compute: false }, { history: false, compute: false }]) {
      const built = Timeline.fromScene(s, options);
      const set = new Timeline({ ...options, g: s.g, gravity: s.gravity });
      set.setActions(s.actions);
      for (const tl of [built, set]) tl.prolongTo(6);
      expect(built.counts(), JSON.stringify(options)).toEqual(set.counts());
      expect(built.stateAt(6)).toEqual(set.stateAt(6));
      if (options.history !== false) expect(fingerprint(built)).toEqual(fingerprint(set));
    }
  });

  it("from a parsed scene (the CLI's way) as from its text; the caller's scene object is not frozen", () => {
    const s = kickedGas();
    const text = JSON.stringify(s);
    const parsed = parseScene(text);
    const fromParsed = Timeline.fromParsedScene(parsed);
    fromParsed.prolongTo(6);
    const fromText = Timeline.fromScene(text);
    fromText.prolongTo(6);
    expect(fingerprint(fromParsed)).toEqual(fingerprint(fromText));
    const fromObject = Timeline.fromScene(s);
    expect(Object.isFrozen(s.actions[0])).toBe(false);
    expect(Object.isFrozen(fromObject.actions[0])).toBe(true);
  });

  it("still refuses an edit at time 0 afterwards, and a list given to setActions, that overlaps", () => {
    const tl = Timeline.fromScene(scene([disc("a", 0, 0), disc("b", 10, 0)], 0), { compute: false });
    expect(() => tl.apply(disc("c", 0.5, 0))).toThrow('action: body "c" would overlap body "a" at time 0');
    expect(() => tl.setActions([disc("a", 0, 0), disc("c", 0.5, 0)])).toThrow(
      'actions[1]: body "c" would overlap body "a" at time 0',
    );
    const headless = Timeline.fromScene(scene([disc("a", 0, 0)], 0), { history: false, compute: false });
    expect(() => headless.apply(disc("c", 0.5, 0))).toThrow('body "c" would overlap body "a" at time 0');
  });

  it("still checks the actions after time 0 against the simulation (a body that moved)", () => {
    const s = scene([disc("a", 0, 0, [1, 0]), disc("b", 3, 0, [0, 0], 3)], 0);
    expect(() => Timeline.fromScene(s)).toThrow('actions[1]: body "b" would overlap body "a" at time 3');
  });
});
