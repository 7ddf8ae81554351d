/**
 * Timeline.bodyArraysAt: the reuse of `into` across times (the same object and arrays while the
 * count is the same, `ids` kept while the bodies are, new ones when they change), and the times
 * it refuses: exactly stateAt's, with stateAt's RangeError naming bodyArraysAt (beyond the
 * horizon, before a forgotten start, before the last entry without history, NaN, not a number).
 * The values themselves: bodyArrays.prop.test.ts.
 */
import { describe, expect, it } from "vitest";
import { ARRAY_FIELDS, type BodyArrays } from "../sim/bodyArrays.js";
import { disc, expectSameAsStateAt, scene } from "./testSupport.js";
import { Timeline } from "./timeline.js";

/** a and b collide at t = 1.5; c is removed at t = 2, d added at t = 3 (3 bodies, 2, then 3 again). */
function changing(history = true): Timeline {
  const tl = Timeline.fromScene(
    scene(
      [
        disc("a", 0, 0, [1, 0]),
        disc("b", 5, 0),
        disc("c", 0, 10, [0, 1]),
        { time: 2, type: "removeBody", id: "c" },
        disc("d", 20, 20, [-1, 0], 3),
      ],
      0,
    ),
    { history },
  );
  tl.prolongTo(5);
  return tl;
}

describe("Timeline.bodyArraysAt reuses `into`", () => {
  it("writes into the same object and arrays, keeping ids, while the bodies are the same", () => {
    const tl = changing();
    const into = tl.bodyArraysAt(0);
    const arrays = ARRAY_FIELDS.map((f) => into[f]);
    const ids = into.ids;
    for (const t of [0.5, 1.5, 1.9]) {
      expect(tl.bodyArraysAt(t, into)).toBe(into);
      expect(into.ids).toBe(ids);
      ARRAY_FIELDS.forEach((f, i) => {
        expect(into[f]).toBe(arrays[i]);
      });
      expectSameAsStateAt(into, tl.stateAt(t));
    }
  });

  it("gives new ids and arrays when the count changes, and new ids (same arrays) when only the ids do", () => {
    const tl = changing();
    const into = tl.bodyArraysAt(1);
    const { ids, x } = into;
    tl.bodyArraysAt(2, into); // c removed
    expect(into.ids).not.toBe(ids);
    expect(into.x).not.toBe(x);
    expect(into.x.length).toBe(2);
    expect(ids).toStrictEqual(["a", "b", "c"]); // the old ids are left as they were
    expectSameAsStateAt(into, tl.stateAt(2));
    const two = into.ids;
    tl.bodyArraysAt(2.5, into);
    expect(into.ids).toBe(two);
    const x2 = into.x;
    tl.bodyArraysAt(3, into); // d added: a, b, d
    expect(into.ids).toStrictEqual(["a", "b", "d"]);
    const abd = into.ids;
    const x3 = into.x;
    expect(x3).not.toBe(x2);
    tl.bodyArraysAt(1, into); // back to a, b, c: the same count, other ids
    expect(into.ids).not.toBe(abd);
    expect(into.x).toBe(x3);
    expectSameAsStateAt(into, tl.stateAt(1));
  });

  it("keeps the ids of an into from another source (a World, another timeline) when they are the same", () => {
    const tl = changing();
    const other = changing().bodyArraysAt(4);
    const ids = other.ids;
    expect(tl.bodyArraysAt(4.5, other).ids).toBe(ids);
    expectSameAsStateAt(other, tl.stateAt(4.5));
  });

  it("reads a timeline without history from its last entry on, the same way", () => {
    const tl = changing(false);
    const from = tl.lastLoggedTime();
    const into = tl.bodyArraysAt(from);
    const { ids, x } = into;
    expectSameAsStateAt(into, tl.stateAt(from));
    tl.bodyArraysAt(5, into);
    expect(into.ids).toBe(ids);
    expect(into.x).toBe(x);
    expectSameAsStateAt(into, tl.stateAt(5));
  });
});

/** The error `read` throws (it must throw). */
function thrown(read: () => unknown): Error {
  try {
    read();
  } catch (e) {
    return e as Error;
  }
  throw new Error("did not throw");
}

describe("Timeline.bodyArraysAt refuses what stateAt refuses", () => {
  const bad = [
    -1,
    5.5,
    Number.NaN,
    Number.POSITIVE_INFINITY,
    Number.NEGATIVE_INFINITY,
    "1",
    null,
    undefined,
  ] as unknown as number[];

  it("with stateAt's RangeError, naming bodyArraysAt, and writing nothing", () => {
    const forgot = changing();
    forgot.forgetBefore(4); // keyframes follow the action groups: the start is kept at 3
    const cases: [string, Timeline, number[]][] = [
      ["history", changing(), bad],
      ["forgotten start", forgot, [...bad, 1, 2.5]],
      ["no history", changing(false), [...bad, 1, 2.5]],
    ];
    for (const [name, tl, times] of cases) {
      const into = tl.bodyArraysAt(tl.horizon);
      const snapshot = ARRAY_FIELDS.map((f) => Array.from(into[f]));
      for (const t of times) {
        const expected = thrown(() => tl.stateAt(t));
        expect(expected, `${name}, t = ${t}`).toBeInstanceOf(RangeError);
        expect(expected.message).toMatch(/^stateAt\(t\): /);
        const got = thrown(() => tl.bodyArraysAt(t, into));
        expect(got).toBeInstanceOf(RangeError);
        expect(got.message).toBe(expected.message.replace(/^stateAt\(t\): /, "bodyArraysAt(t): "));
      }
      expect(ARRAY_FIELDS.map((f) => Array.from(into[f]))).toStrictEqual(snapshot);
      expect(into.time).toBe(tl.horizon);
    }
  });

  it("and refuses an `into` that is not a previous result with a RangeError", () => {
    const tl = changing();
    const good = tl.bodyArraysAt(1);
    for (const into of [null, 0, "into", {}, { ...good, ids: null }, { ...good, m: new Float32Array(3) }]) {
      const got = thrown(() => tl.bodyArraysAt(1, into as unknown as BodyArrays));
      expect(got).toBeInstanceOf(RangeError);
      expect(got.message).toMatch(/^bodyArraysAt\(into\): must be a previous result/);
    }
  });
});
