// A refused placement names the overlapped body, line or point with the smallest id, whatever the
// order things were added in and whether the check used the grid. Regression (review): the first
// overlap found was named, so the message depended on insertion order and on the broad phase's
// scan order (22 % of probes named another body with the grid than without it).
import { describe, expect, it } from "vitest";
import type { Optimizations } from "./types.js";
import { World } from "./world.js";

/** Discs "m" and "c" side by side at the origin, among `fillers` others far away, in either order. */
function scene(fillers: number, reversed: boolean, opt: Optimizations): World {
  const w = new World({ optimizations: opt });
  const pair: [string, number][] = [
    ["m", -1.2],
    ["c", 1.2],
  ];
  const ordered = reversed ? [...pair].reverse() : pair;
  const filler = (i: number) =>
    w.addBody(`f${i}`, { x: 100 + (i % 10) * 3, y: Math.floor(i / 10) * 3, r: 1, m: 1 });
  for (let i = 0; i < fillers / 2; i++) filler(i);
  for (const [id, x] of ordered) w.addBody(id, { x, y: 0, r: 1, m: 1 });
  for (let i = fillers / 2; i < fillers; i++) filler(i);
  for (const [id, y] of reversed
    ? ([
        ["z", 3],
        ["a", -3],
      ] as const)
    : ([
        ["a", -3],
        ["z", 3],
      ] as const))
    w.addLine(id, [-20, y], [-10, y], "segment");
  return w;
}

const refusal = (f: () => void): string => {
  try {
    f();
    return "accepted";
  } catch (e) {
    return (e as Error).message;
  }
};

describe("refused placements name the smallest id", () => {
  for (const fillers of [10, 100]) {
    it(`among ${fillers + 2} bodies, in both insertion orders, with and without the grid`, () => {
      for (const reversed of [false, true])
        for (const opt of [{}, { broadPhase: false }]) {
          const w = scene(fillers, reversed, opt);
          expect(refusal(() => w.addBody("new", { x: 0, y: 0, r: 1, m: 1 }))).toBe(
            'x: the body would overlap body "c"',
          );
          expect(refusal(() => w.addLine("cut", [-5, 0], [5, 0], "segment"))).toBe(
            'p1: the line would overlap body "c"',
          );
          expect(refusal(() => w.addBody("wide", { x: -15, y: 0, r: 3.5, m: 1 }))).toBe(
            'x: the body would overlap line "a"',
          );
        }
    });
  }
});

describe("a refused update names the field that made the overlap", () => {
  it("r when only the radius grew (it said x), y when only y moved, x when x moved", () => {
    const w = new World({ g: 0 });
    w.addBody("a", { x: 0, y: 0, r: 1, m: 1 });
    w.addBody("b", { x: 5, y: 0, r: 1, m: 1 });
    w.addLine("wall", [-10, 3], [10, 3], "segment");
    expect(refusal(() => w.updateBody("a", { r: 4.5 }))).toBe('r: the body would overlap body "b"');
    expect(refusal(() => w.updateBody("a", { r: 3.5 }))).toBe('r: the body would overlap line "wall"');
    expect(refusal(() => w.updateBody("a", { y: 2.5 }))).toBe('y: the body would overlap line "wall"');
    expect(refusal(() => w.updateBody("a", { x: 4, r: 1 }))).toBe('x: the body would overlap body "b"');
    // a state passed back whole names what changed in it (review)
    expect(refusal(() => w.updateBody("a", { ...w.body("a"), r: 4.5 }))).toBe(
      'r: the body would overlap body "b"',
    );
    expect(w.body("a")).toMatchObject({ x: 0, y: 0, r: 1 });
  });
});

// Audit of session 22: updateLine named p1 whatever changed, so a line turned from a segment into
// an infinite line through a disc was refused as "p1: …" though p1 was not touched.
describe("a refused updateLine names the field that made the overlap", () => {
  it("kind when only the kind changed, p2 when only p2 moved, p1 when p1 moved (as addLine)", () => {
    const w = new World({ g: 0 });
    w.addBody("a", { x: 20, y: 0, r: 1, m: 1 });
    w.addLine("l", [0, 0], [10, 0], "segment");
    expect(refusal(() => w.updateLine("l", { kind: "line" }))).toBe('kind: the line would overlap body "a"');
    expect(refusal(() => w.updateLine("l", { p2: [30, 0] }))).toBe('p2: the line would overlap body "a"');
    expect(refusal(() => w.updateLine("l", { p1: [30, 0] }))).toBe('p1: the line would overlap body "a"');
    expect(refusal(() => w.updateLine("l", { p1: [0, 0], p2: [30, 0] }))).toBe(
      'p2: the line would overlap body "a"',
    );
    // a LineState passed back whole names what changed in it
    const [state] = w.lines();
    expect(refusal(() => w.updateLine("l", { ...state, kind: "ray" }))).toBe(
      'kind: the line would overlap body "a"',
    );
    expect(w.lines()).toEqual([{ id: "l", p1: [0, 0], p2: [10, 0], kind: "segment" }]);
  });
});
