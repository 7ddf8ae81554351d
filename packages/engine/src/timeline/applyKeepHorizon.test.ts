// Timeline.apply(action, { keepHorizon: false }): an edit in the past recomputes only up to the last
// action, so a UI can compute the rest in slices with progress and cancel (editor audit: an edit at
// t = 3 of a 4.2 million event history blocked the worker for 10 s with no progress bar).
import { describe, expect, it } from "vitest";
import { galperin } from "../scene/presets.js";
import type { Action } from "../scene/types.js";
import { disc, fingerprint, scene } from "./testSupport.js";
import { Timeline } from "./timeline.js";

/** Four discs bouncing in a box of segments, no friction: events for ever. */
function boxed(options: { compute?: boolean } = {}): Timeline {
  const wall = (id: string, p1: [number, number], p2: [number, number]): Action => ({
    time: 0,
    type: "addLine",
    id,
    p1,
    p2,
    kind: "segment",
  });
  return Timeline.fromScene(
    scene(
      [
        wall("s", [0, 0], [20, 0]),
        wall("e", [20, 0], [20, 20]),
        wall("n", [20, 20], [0, 20]),
        wall("w", [0, 20], [0, 0]),
        disc("a", 3, 3, [2, 1.3]),
        disc("b", 10, 4, [-1.1, 2]),
        disc("c", 15, 15, [0.7, -2.2]),
        disc("d", 5, 12, [1.9, 0.4]),
      ],
      0,
    ),
    options,
  );
}

const nudge: Action = { time: 2.5, type: "giveVelocity", id: "b", v: [3, -1] };

describe("Timeline.apply with keepHorizon: false", () => {
  it("recomputes an edit in the past only to its time, and prolongTo the old horizon gives the same history bit for bit", () => {
    const full = boxed();
    full.prolongTo(200);
    const cut = boxed();
    cut.prolongTo(200);
    expect(full.eventCount).toBeGreaterThan(100);

    full.apply(nudge);
    cut.apply(nudge, { keepHorizon: false });
    expect(full.horizon).toBe(200);
    expect(cut.horizon).toBe(2.5);
    expect(cut.eventCount).toBeLessThan(full.eventCount);

    for (let k = 0; k < 10_000 && !cut.prolongSlice({ time: 200 - 2.5 }, 64).done; k++);
    expect(cut.horizon).toBe(200);
    expect(fingerprint(cut)).toEqual(fingerprint(full));
  });

  it("still computes through the later actions, so an edit that makes one invalid is refused at once and changes nothing", () => {
    const tl = boxed();
    tl.apply({ time: 6, type: "addBody", id: "e", x: 10, y: 10, r: 1, m: 1 });
    tl.prolongTo(50);
    const before = fingerprint(tl);
    // A disc placed at (10, 10) at t = 4 moving at 0 is where e is added at t = 6: e would overlap it.
    const blocker: Action = { time: 4, type: "addBody", id: "z", x: 10, y: 10.5, r: 1, m: 1 };
    expect(() => tl.apply(blocker, { keepHorizon: false })).toThrow(
      /^actions\[8\]: .*\(once this action is in place\)$/,
    );
    expect(fingerprint(tl)).toEqual(before);

    // An edit that leaves the later action valid computes up to it (t = 6), not to 50.
    tl.apply({ time: 4, type: "giveVelocity", id: "a", v: [0, 0] }, { keepHorizon: false });
    expect(tl.horizon).toBe(6);
    expect(tl.stateAt(6).bodies.map((b) => b.id)).toContain("e");
  });

  it("changes nothing for an edit at or after the horizon, and refuses options it does not know", () => {
    const tl = Timeline.fromScene(galperin(3));
    tl.prolongTo(5);
    tl.apply({ time: 7, type: "giveVelocity", id: "small", v: [0, 0] }, { keepHorizon: false });
    expect(tl.horizon).toBe(7);
    expect(() => tl.apply(nudge, { keepHorizn: false } as unknown as { keepHorizon: boolean })).toThrow(
      "options.keepHorizn: unknown field (known: keepHorizon, checkLater)",
    );
    expect(() => tl.apply(nudge, { keepHorizon: "no" } as unknown as { keepHorizon: boolean })).toThrow(
      'options.keepHorizon: must be true or false (got the string "no")',
    );
    expect(() => tl.apply(nudge, { checkLater: 0 } as unknown as { checkLater: boolean })).toThrow(
      "options.checkLater: must be true or false (got 0)",
    );
    expect(() => tl.apply(nudge, 5 as unknown as { keepHorizon: boolean })).toThrow(
      "options: must be an object with optional keepHorizon and checkLater (got 5)",
    );
    expect(() => tl.prolong(5 as unknown as { time: number })).toThrow(
      "until: must be an object with optional time and events (got 5)",
    );
    expect(() => tl.apply(nudge, { checkLater: false })).toThrow(
      "options.checkLater: can be false only with keepHorizon: false",
    );
  });
});

describe("Timeline.apply with keepHorizon: false and checkLater: false (compute: false)", () => {
  it("recomputes only to the edit's own time; prolonging through the later actions gives the same history bit for bit", () => {
    const full = boxed({ compute: false });
    full.apply({ time: 60, type: "giveVelocity", id: "c", v: [1, 1] });
    full.prolongTo(200);
    const lazy = boxed({ compute: false });
    lazy.apply({ time: 60, type: "giveVelocity", id: "c", v: [1, 1] });
    lazy.prolongTo(200);
    full.apply(nudge);
    lazy.apply(nudge, { keepHorizon: false, checkLater: false });
    expect(lazy.horizon).toBe(2.5); // not 60, where the later action is
    for (let k = 0; k < 10_000 && !lazy.prolongSlice({ time: 200 - lazy.horizon }, 64).done; k++);
    expect(fingerprint(lazy)).toEqual(fingerprint(full));
  });

  it("a later action made invalid is refused by the prolong that reaches it, named by its index in actions; setActions takes the edit back", () => {
    const tl = boxed({ compute: false });
    tl.apply({ time: 6, type: "addBody", id: "e", x: 10, y: 10, r: 1, m: 1 });
    tl.prolongTo(50);
    const before = tl.actions.slice();
    const fresh = fingerprint(tl);
    const blocker: Action = { time: 4, type: "addBody", id: "z", x: 10, y: 10.5, r: 1, m: 1 };
    tl.apply(blocker, { keepHorizon: false, checkLater: false });
    expect(tl.horizon).toBe(4);
    // actions[9] is e's addBody in `actions`, the edit included (z's addBody at t = 4 is before it)
    expect(tl.actions[9]).toMatchObject({ type: "addBody", id: "e" });
    expect(() => tl.prolongTo(50)).toThrow(/^actions\[9\]: body "e" would overlap body "z" at time 6$/);
    expect(tl.horizon).toBe(6);
    tl.setActions(before);
    tl.prolongTo(50);
    expect(fingerprint(tl)).toEqual(fresh);
  });
});
