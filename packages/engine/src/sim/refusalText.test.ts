import { describe, expect, it } from "vitest";
import { parseScene } from "../scene/parse.js";
import { Timeline } from "../timeline/timeline.js";
import { ZENO_PUSH_STREAK } from "../tolerances.js";
import { ChapgameError, SimulationError } from "./errors.js";
import type { LineKind } from "./obstacles.js";
import { PushWatch } from "./pushWatch.js";
import { given, quoteId } from "./refusalText.js";
import type { BodyInit, BodyMotionInit, Vec2, WorldOptions } from "./types.js";
import { World } from "./world.js";

/** The ChapgameError `call` throws, as [path, message]. */
function refusal(call: () => unknown): [string, string] {
  try {
    call();
  } catch (e) {
    if (e instanceof ChapgameError) return [e.path, e.message];
    throw e;
  }
  throw new Error("accepted");
}

/** A World with disc a at the origin, a segment l at x = 10 and a point p at x = -10. */
function world(): World {
  const w = new World({ g: 0 });
  w.addBody("a", { x: 0, y: 0, r: 1, m: 1 });
  w.addLine("l", [10, -1], [10, 1], "segment");
  w.addPoint("p", [-10, 0]);
  return w;
}

const disc = (fields: Record<string, unknown>): BodyInit =>
  ({ x: 5, y: 5, r: 1, m: 1, ...fields }) as unknown as BodyInit;

describe("given: how a refusal names the value", () => {
  it("numbers as written, strings quoted and cut at 40, containers by size, the rest by kind", () => {
    expect([-2, Number.NaN, Number.POSITIVE_INFINITY, null, undefined, true].map(given)).toEqual([
      "-2",
      "NaN",
      "Infinity",
      "null",
      "undefined",
      "true",
    ]);
    expect(given("1")).toBe('the string "1"');
    expect(given("x".repeat(50))).toBe(`the string "${"x".repeat(40)}…"`);
    expect([given([1, 2, 3]), given({ a: 1 }), given(() => 1), given(3n)]).toEqual([
      "an array of 3",
      "an object",
      "a function",
      "3n",
    ]);
    expect(quoteId('a "b"')).toBe('"a \\"b\\""');
  });
});

describe("the World's refusals say what was given and quote ids as the scene's do (audit)", () => {
  it("addBody, updateBody, addBodyMotion", () => {
    const w = world();
    const cases: [() => unknown, string, string][] = [
      [() => w.addBody("b", disc({ x: Number.NaN })), "x", "must be a finite number (got NaN)"],
      [
        () => w.addBody("b", disc({ m: Number.NaN })),
        "m",
        "must be a positive number (or Infinity) (got NaN)",
      ],
      [() => w.addBody("b", disc({ r: "1" })), "r", 'must be a positive finite number (got the string "1")'],
      [() => w.addBody("b", disc({ mu: -1 })), "mu", "must be a non-negative finite number (got -1)"],
      [() => w.addBody("", disc({})), "id", 'must be a non-empty string (got the string "")'],
      [
        () => w.addBody("b", null as unknown as BodyInit),
        "init",
        "must be an object with fields x, y, vx, vy, r, m, mu (got null)",
      ],
      [() => w.addBody("a", disc({})), "id", 'a body with id "a" already exists'],
      [() => w.addBody("b", disc({ x: 1, y: 0 })), "x", 'the body would overlap body "a"'],
      [() => w.addBody("b", disc({ x: 10, y: 0 })), "x", 'the body would overlap line "l"'],
      [() => w.addBody("b", disc({ x: -10, y: 0 })), "x", 'the body would overlap point "p"'],
      [
        () => w.updateBody("a", { vx: Number.POSITIVE_INFINITY }),
        "vx",
        "must be a finite number (got Infinity)",
      ],
      [() => w.updateBody("zz", { vx: 1 }), "id", 'no body with id "zz"'],
      [() => w.updateBody(7 as unknown as string, { vx: 1 }), "id", "must be a non-empty string (got 7)"],
      [
        () => w.addBodyMotion("c", { t0: 5, x0: 5, y0: 5, vx: 0, vy: 0, r: 1, m: 1 }),
        "t0",
        "must be <= the world's time 0 (got 5)",
      ],
      [
        () =>
          w.addBodyMotion("c", { t0: 0, x0: 5, y0: 5, vx: 0, vy: 0, r: 1, m: 1, ax: 3 } as BodyMotionInit),
        "ax",
        "is derived from vx, vy, mu and the World's g and gravity (here 0), not set: leave it out or pass motion(id)'s own value (got 3)",
      ],
      [() => w.body("a", Number.POSITIVE_INFINITY), "t", "must be a finite time (got Infinity)"],
      [() => w.bodies("1" as unknown as number), "t", 'must be a finite time (got the string "1")'],
      [
        () => w.body("a", -1),
        "t",
        `must be a time at or after body "a"'s last event or edit, t0 = 0 (got -1): earlier states are not kept by a World (a Timeline keeps them)`,
      ],
      [() => w.body("zz"), "id", 'no body with id "zz"'],
      [() => w.bodyArrays(0, 5 as never), "into", "must be a previous result or undefined (got 5)"],
    ];
    for (const [call, path, reason] of cases) expect(refusal(call)).toEqual([path, `${path}: ${reason}`]);
    expect(w.bodies().map((b) => b.id)).toEqual(["a"]);
  });

  it("lines, points, setGlobal, options and advance", () => {
    const w = world();
    const cases: [() => unknown, string, string][] = [
      [
        () => w.addLine("m", [0, 5], [1] as unknown as Vec2, "line"),
        "p2",
        "must be an array of two finite numbers (got an array of 1)",
      ],
      [
        () => w.addLine("m", [0, 5], [1, 5], "curve" as LineKind),
        "kind",
        'must be one of "line", "ray", "segment" (got the string "curve")',
      ],
      [() => w.addLine("m", [0, -5], [0, 5], "segment"), "p1", 'the line would overlap body "a"'],
      [() => w.addLine("l", [0, 5], [1, 5], "line"), "id", 'a line with id "l" already exists'],
      [() => w.updateLine("zz", {}), "id", 'no line with id "zz"'],
      [() => w.addPoint("q", [0.5, 0]), "p", 'the point would lie inside body "a"'],
      [() => w.addPoint("p", [20, 20]), "id", 'a point with id "p" already exists'],
      [() => w.removePoint("zz"), "id", 'no point with id "zz"'],
      [() => w.setGlobal({ g: -1 }), "g", "must be a non-negative finite number (got -1)"],
      [
        () => w.setGlobal({ gravity: [0, "1"] as unknown as Vec2 }),
        "gravity[1]",
        'must be a finite number (got the string "1")',
      ],
      [
        () => new World({ optimizations: { broadPhase: "no" } } as unknown as WorldOptions),
        "optimizations.broadPhase",
        'must be true or false (got the string "no")',
      ],
      [() => new World({ g: Number.NaN }), "g", "must be a non-negative finite number (got NaN)"],
      [
        () => w.advance({ untilTime: "5" as unknown as number }),
        "untilTime",
        'must be a number (a time >= the current time 0) (got the string "5")',
      ],
      [() => w.advance({ untilTime: -1 }), "untilTime", "must be >= the current time 0 (got -1)"],
      [
        () => w.advance({ maxEvents: 1.5 }),
        "maxEvents",
        "must be a whole number >= 0, or Infinity (got 1.5)",
      ],
      [
        () => w.advance({}, 5 as unknown as () => void),
        "onEvent",
        "must be a function called with each event (got 5)",
      ],
    ];
    for (const [call, path, reason] of cases) expect(refusal(call)).toEqual([path, `${path}: ${reason}`]);
    const mu = new World({ g: 1, gravity: [0, -1] });
    expect(refusal(() => mu.addBody("b", disc({ mu: 0.5 })))).toEqual([
      "mu",
      "mu: friction (mu > 0) cannot be combined with a non-zero gravity field (got 0.5): set mu to 0, or the gravity field to [0, 0] first",
    ]);
  });

  it("a World refusal and a scene refusal of the same value say it alike", () => {
    const reasonOf = (call: () => unknown): string => {
      const [path, message] = refusal(call);
      return message.slice(path.length + 2);
    };
    for (const x of [Number.NaN, "1", null, [1, 2]]) {
      const inWorld = reasonOf(() => new World({ g: 0 }).addBody("a", disc({ x })));
      const action = { time: 0, type: "addBody", id: "a", x, y: 0, r: 1, m: 1 };
      const inScene = reasonOf(() => parseScene({ format: "chapgame", version: 1, actions: [action] }));
      expect(inWorld, String(x)).toBe(inScene);
    }
    // Every field the World and an action share, each refused value alike (review of session 26:
    // a line's kind was 'must be "line", "ray" or "segment"' in a World, 'must be one of "line",
    // "ray", "segment"' in a scene). A mass differs on purpose: a World takes the number Infinity, a
    // scene file the string "Infinity", and each says its own.
    const addBody = (f: string, v: unknown): [() => unknown, () => unknown] => [
      () => new World({ g: 1 }).addBody("a", disc({ [f]: v })),
      () =>
        parseScene({
          format: "chapgame",
          version: 1,
          actions: [{ time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, [f]: v }],
        }),
    ];
    const addLine = (p1: unknown, p2: unknown, kind: unknown): [() => unknown, () => unknown] => [
      () => new World().addLine("l", p1 as Vec2, p2 as Vec2, kind as LineKind),
      () =>
        parseScene({
          format: "chapgame",
          version: 1,
          actions: [{ time: 0, type: "addLine", id: "l", p1, p2, kind }],
        }),
    ];
    const pairs: [() => unknown, () => unknown][] = [
      ...[Number.NaN, 1e31, "1"].flatMap((v) => [addBody("x", v), addBody("y", v)]),
      ...[-1, 0, 1e-31, 1e31, Number.POSITIVE_INFINITY, "1"].map((v) => addBody("r", v)),
      ...[-0.5, 1e-31, Number.NaN, "a"].map((v) => addBody("mu", v)),
      ...["segmnet", 3, null].map((k) => addLine([0, 0], [1, 0], k)),
      ...[[0], [0, Number.NaN], "x", [0, 1e31]].map((p) => addLine(p, [1, 0], "line")),
      ...[
        [0, 1e-31],
        [0, 0],
      ].map((p) => addLine([0, 0], p, "line")),
      ...[-1, 1e-31, "1"].map((g): [() => unknown, () => unknown] => [
        () => new World({ g: g as number }),
        () => parseScene({ format: "chapgame", version: 1, g, actions: [] }),
      ]),
      ...[[0], [0, Number.NaN], [0, 1e-31], 5].map((gravity): [() => unknown, () => unknown] => [
        () => new World({ gravity: gravity as unknown as Vec2 }),
        () => parseScene({ format: "chapgame", version: 1, gravity, actions: [] }),
      ]),
    ];
    // friction under gravity (it was "must be 0 while the gravity field is non-zero" in a World)
    pairs.push([
      () => new World({ g: 0, gravity: [0, -1] }).addBody("a", disc({ mu: 0.5 })),
      () =>
        parseScene({
          format: "chapgame",
          version: 1,
          gravity: [0, -1],
          actions: [{ time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, mu: 0.5 }],
        }),
    ]);
    for (const [inWorld, inScene] of pairs) expect(reasonOf(inWorld)).toBe(reasonOf(inScene));
    // an id: `body "a"` in both (the World's overlap, the Timeline's scene rule)
    const w = world();
    const tl = new Timeline({ g: 0 });
    tl.apply({ time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1 });
    const inWorld = refusal(() => w.addBody("b", disc({ x: 1, y: 0 })))[1];
    const inScene = refusal(() => tl.apply({ time: 0, type: "addBody", id: "b", x: 1, y: 0, r: 1, m: 1 }))[1];
    expect(inWorld).toContain('overlap body "a"');
    expect(inScene).toContain('overlap body "a"');
  });
});

describe("a SimulationError quotes ids as the refusals do (session 23: it wrote 'a')", () => {
  /** The SimulationError `call` throws. */
  function failure(call: () => unknown): SimulationError {
    try {
      call();
    } catch (e) {
      if (e instanceof SimulationError) return e;
      throw e;
    }
    throw new Error("went on");
  }
  // ids that single quotes left ambiguous: a quote, a space, an apostrophe
  const ball = 'the "ball"';
  const floor = "Ann's floor";

  it("a resting contact names the body and the line as a refusal of them does", () => {
    const w = new World({ g: 0, gravity: [0, -1] });
    w.addLine(floor, [-10, 0], [10, 0], "segment");
    w.addBody(ball, { x: 0, y: 1, r: 1, m: 1 });
    const e = failure(() => w.advance({ untilTime: 1 }));
    expect(e.message).toMatch(/^body "the \\"ball\\"" rests against "Ann's floor" under an acceleration/);
    expect(e.message.startsWith(`body ${quoteId(ball)} rests against ${quoteId(floor)} `)).toBe(true);
    expect(e.ids).toEqual([ball, floor]);
    // the World's refusal of the same ids quotes them alike
    expect(refusal(() => w.addBody(ball, disc({ x: 50 })))[1]).toContain(`body with id ${quoteId(ball)}`);
    expect(refusal(() => w.addLine(floor, [0, 5], [1, 5], "segment"))[1]).toContain(quoteId(floor));
  });

  it("a sustained push and a contact doubles cannot place name their bodies the same way", () => {
    const push = new PushWatch();
    for (let i = 0; i < ZENO_PUSH_STREAK; i++) push.stop(ball, true, 1);
    expect(failure(() => push.stop(ball, true, 1)).message).toMatch(/^body "the \\"ball\\"" stopped /);
    // two discs meeting at 1e16 with radius 1 (precisionLimit.test's case)
    const w = new World({ g: 0 });
    w.addBody(ball, { x: 1e16, y: 0, r: 1, m: 1, vx: 1 });
    w.addBody(floor, { x: 1e16 + 72, y: 0, r: 1, m: 1, vx: -1 });
    const e = failure(() => w.advance({ untilTime: 100 }));
    expect(
      e.message.startsWith(
        `body ${quoteId(e.ids[0] as string)} meets body ${quoteId(e.ids[1] as string)} at t=35`,
      ),
    ).toBe(true);
    expect([...e.ids].sort()).toEqual([floor, ball].sort());
  });
});
