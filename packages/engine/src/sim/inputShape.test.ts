// The shape of the World's option and field objects (validate.ts requireFields, review 7): not an
// object, an unknown (misspelt) key, a fractional event count and a NaN time are refused by name,
// and nothing changes; what the World reports (a BodyState, a motion) can be passed back as it is.
import { describe, expect, it } from "vitest";
import { ChapgameError } from "./errors.js";
import type { BodyInit } from "./types.js";
import { World } from "./world.js";

/** The ChapgameError fn throws (fails the test when it throws nothing or something else). */
function refusal(fn: () => unknown): ChapgameError {
  try {
    fn();
  } catch (e) {
    if (e instanceof ChapgameError) return e;
    throw new Error(`expected a ChapgameError, got ${String(e)}`);
  }
  throw new Error("expected a ChapgameError, nothing was thrown");
}

function oneDisc(): World {
  const w = new World({ g: 0 });
  w.addBody("a", { x: 0, y: 0, r: 1, m: 1, vx: 1 });
  return w;
}

describe("World input objects", () => {
  it("a lookup given an id that is not a string says so, not 'no body with id \"1\"' (audit of session 20)", () => {
    const w = oneDisc();
    w.addBody("1", { x: 5, y: 0, r: 1, m: 1 });
    w.addLine("1", [0, -5], [1, -5], "line");
    w.addPoint("1", [0, 5]);
    const bad: [unknown, string][] = [
      [1, "1"],
      [{ id: "1" }, "an object"],
      [null, "null"],
      [undefined, "undefined"],
    ];
    for (const [value, shown] of bad) {
      const id = value as string;
      for (const call of [
        () => w.body(id),
        () => w.motion(id),
        () => w.removeBody(id),
        () => w.updateBody(id, { vx: 1 }),
        () => w.updateLine(id, { kind: "ray" }),
        () => w.removeLine(id),
        () => w.updatePoint(id, [0, 6]),
        () => w.removePoint(id),
      ]) {
        const e = refusal(call);
        expect(e.message).toBe(`id: must be a non-empty string (got ${shown})`);
      }
    }
    expect(w.hasBody("1") && w.hasLine("1") && w.hasPoint("1")).toBe(true);
    expect(w.bodyCount).toBe(2);
  });

  it("refuses a missing or non-object init, patch, options or limits by name", () => {
    const w = oneDisc();
    expect(refusal(() => w.addBody("b", null as unknown as BodyInit)).path).toBe("init");
    expect(refusal(() => w.addBody("b", 5 as unknown as BodyInit)).path).toBe("init");
    expect(refusal(() => w.updateBody("a", [] as unknown as BodyInit)).path).toBe("patch");
    expect(refusal(() => w.setGlobal(null as unknown as { g: number })).path).toBe("patch");
    expect(refusal(() => new World(null as unknown as { g: number })).path).toBe("options");
    expect(refusal(() => w.advance(null as unknown as { maxEvents: number })).path).toBe("limits");
    expect(w.bodies().map((b) => b.id)).toEqual(["a"]);
  });

  it('refuses an optimization switch that is not a boolean, naming it ("no" and 3 were taken as on: audit of session 19)', () => {
    for (const v of ["no", 3, 0, null, "false"]) {
      const e = refusal(
        () => new World({ optimizations: { broadPhase: v } as unknown as { broadPhase: boolean } }),
      );
      expect(e.path).toBe("optimizations.broadPhase");
      expect(e.reason).toMatch(/^must be true or false/);
    }
    expect(
      refusal(() => new World({ optimizations: { restingSkip: 1 } as unknown as { restingSkip: boolean } }))
        .path,
    ).toBe("optimizations.restingSkip");
    expect(new World({ optimizations: { broadPhase: false, pathBounds: undefined } }).bodyCount).toBe(0);
  });

  it("refuses a misspelt key instead of dropping it, named as a bad value of a known field is", () => {
    // Review of session 26 (noted in session 25): a bad r was "r" but a misspelt radius was
    // "init.radius"; both are now named alone, as a scene file names its top-level keys (`title:
    // unknown field`, `g: must be …`), and the argument's own name is kept for the argument itself.
    const w = oneDisc();
    const e = refusal(() => w.addBody("b", { x: 5, y: 0, r: 1, m: 1, vX: 5 } as unknown as BodyInit));
    expect(e.path).toBe("vX");
    // worded as a scene file's unknown key is (it said "is not a field here": audit of session 23)
    expect(e.reason).toBe("unknown field (known: x, y, vx, vy, r, m, mu)");
    expect(e.message).toBe("vX: unknown field (known: x, y, vx, vy, r, m, mu)");
    expect(w.hasBody("b")).toBe(false);
    // the same root as a known field's refusal, in every call that takes an object
    const pairs: [() => unknown, () => unknown, string, string][] = [
      [
        () => w.addBody("b", { x: 5, y: 0, radius: 1, m: 1 } as unknown as BodyInit),
        () => w.addBody("b", { x: 5, y: 0, r: -1, m: 1 }),
        "radius",
        "r",
      ],
      [
        () => w.updateBody("a", { radius: 2 } as unknown as BodyInit),
        () => w.updateBody("a", { r: Number.NaN }),
        "radius",
        "r",
      ],
      [
        () =>
          w.addBodyMotion("b", {
            t0: 0,
            x0: 5,
            y0: 0,
            vx: 0,
            vy: 0,
            r: 1,
            m: 1,
            t: 0,
          } as unknown as Parameters<World["addBodyMotion"]>[1]),
        () => w.addBodyMotion("b", { t0: 1, x0: 5, y0: 0, vx: 0, vy: 0, r: 1, m: 1 }),
        "t",
        "t0",
      ],
      [() => w.setGlobal({ G: 1 } as unknown as { g: number }), () => w.setGlobal({ g: -1 }), "G", "g"],
      [() => new World({ grav: 1 } as unknown as { g: number }), () => new World({ g: -1 }), "grav", "g"],
      [
        () => new World({ optimizations: { broadphase: false } as unknown as { broadPhase: boolean } }),
        () => new World({ optimizations: { broadPhase: 0 } as unknown as { broadPhase: boolean } }),
        "optimizations.broadphase",
        "optimizations.broadPhase",
      ],
      [
        () => w.advance({ until: 5 } as unknown as { untilTime: number }),
        () => w.advance({ untilTime: -1 }),
        "until",
        "untilTime",
      ],
    ];
    w.addLine("l", [0, 10], [10, 10], "segment");
    pairs.push([
      () => w.updateLine("l", { p3: [0, 0] } as unknown as { p1: [number, number] }),
      () => w.updateLine("l", { p1: [0] as unknown as [number, number] }),
      "p3",
      "p1",
    ]);
    for (const [unknownKey, badValue, unknownPath, knownPath] of pairs) {
      expect(refusal(unknownKey).path).toBe(unknownPath);
      expect(refusal(unknownKey).reason).toMatch(/^unknown field \(known: /);
      expect(refusal(badValue).path).toBe(knownPath);
    }
    expect(refusal(() => new World({ optimizations: 5 } as unknown as { g: number })).path).toBe(
      "optimizations",
    );
    // an action's spelling of a velocity gets the World's (review of session 25: no hint)
    const v = refusal(() => w.addBody("b", { x: 5, y: 0, r: 1, m: 1, v: [5, 0] } as unknown as BodyInit));
    expect(v.message).toBe("v: unknown field (known: x, y, vx, vy, r, m, mu; a velocity is vx, vy)");
    expect(w.body("a").vx).toBe(1);
    expect(w.time).toBe(0);
    expect(w.bodyCount).toBe(1);
  });

  it("refuses a gravity field while bodies have friction at `gravity`, naming every such body as a scene does", () => {
    // Review of session 26: the World named `bodies.<id>.mu` (no field of setGlobal's argument) and
    // only the first body added; a scene's setGlobal names `gravity` and all of them.
    const w = new World({ g: 9.81 });
    w.addBody("z", { x: 0, y: 0, r: 1, m: 1, mu: 0.2 });
    w.addBody("plain", { x: 5, y: 0, r: 1, m: 1 });
    w.addBody("a", { x: 10, y: 0, r: 1, m: 1, mu: 0.1 });
    const e = refusal(() => w.setGlobal({ gravity: [0, -9.81] }));
    expect(e.path).toBe("gravity");
    expect(e.reason).toBe(
      'a non-zero gravity field cannot be combined with friction (bodies "a", "z" have mu > 0: set their mu to 0 first)',
    );
    expect(w.gravity).toEqual([0, 0]);
    w.updateBody("a", { mu: 0 });
    expect(refusal(() => w.setGlobal({ gravity: [0, -9.81] })).reason).toBe(
      'a non-zero gravity field cannot be combined with friction (body "z" has mu > 0: set its mu to 0 first)',
    );
    w.updateBody("z", { mu: 0 });
    w.setGlobal({ gravity: [0, -9.81] });
    expect(w.gravity).toEqual([0, -9.81]);
  });

  it('refuses the string "Infinity" as a mass saying to write the number (a scene file\'s form, passed on)', () => {
    const w = oneDisc();
    const e = refusal(() => w.addBody("b", { x: 5, y: 0, r: 1, m: "Infinity" as unknown as number }));
    expect(e.path).toBe("m");
    expect(e.reason).toBe(
      'must be a positive number (or Infinity) (got the string "Infinity"): write the number Infinity (the string is how a scene file writes it)',
    );
    expect(refusal(() => w.updateBody("a", { m: "Infinity" as unknown as number })).reason).toMatch(
      /write the number Infinity/,
    );
    expect(refusal(() => w.addBody("b", { x: 5, y: 0, r: 1, m: "1" as unknown as number })).reason).toBe(
      'must be a positive number (or Infinity) (got the string "1")',
    );
    w.addBody("b", { x: 5, y: 0, r: 1, m: Number.POSITIVE_INFINITY });
    expect(w.body("b").m).toBe(Number.POSITIVE_INFINITY);
  });

  it("takes back what it reports: a BodyState, a LineState and a motion", () => {
    const w = oneDisc();
    w.advance({ untilTime: 2 });
    const state = w.body("a");
    const copy = new World({ g: 0, time: 2 });
    copy.addBody("a", state); // id, ax, ay are derived and not read
    expect(copy.body("a")).toEqual(state);
    copy.updateBody("a", { ...state, vx: 3 });
    expect(copy.body("a").vx).toBe(3);
    const rebuilt = new World({ g: 0, time: 2 });
    rebuilt.addBodyMotion("a", { ...w.motion("a"), r: 1, m: 1 });
    expect(rebuilt.body("a")).toEqual(state);
    copy.addLine("l", [0, 10], [10, 10], "segment");
    const line = copy.lines()[0];
    if (line === undefined) throw new Error("the line is missing");
    copy.updateLine("l", { ...line, kind: "ray" });
    expect(copy.lines()[0]?.kind).toBe("ray");
  });

  it("wants a whole number of events and a time that is a number", () => {
    const w = oneDisc();
    const frac = refusal(() => w.advance({ maxEvents: 1.5 }));
    expect(frac.path).toBe("maxEvents");
    expect(frac.message).toMatch(/whole number/);
    expect(refusal(() => w.advance({ maxEvents: -1 })).path).toBe("maxEvents");
    const nan = refusal(() => w.advance({ untilTime: Number.NaN }));
    expect(nan.path).toBe("untilTime");
    expect(nan.message).toMatch(/must be a number/);
    expect(refusal(() => w.advance({ untilTime: "5" as unknown as number })).message).toMatch(
      /must be a number/,
    );
    expect(w.advance({ maxEvents: Number.POSITIVE_INFINITY, untilTime: 3 })).toEqual({
      events: 0,
      reason: "idle",
    });
    expect(w.time).toBe(3);
    expect(w.advance({ maxEvents: 0 })).toEqual({ events: 0, reason: "events" });
  });
});
