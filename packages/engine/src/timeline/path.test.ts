/**
 * Timeline.path(id, from, to): a body's exact motions over a span. Checked against stateAt bit for
 * bit at many times of every piece (a friction billiards break, bouncing balls under gravity, a
 * gas), against the body's own log entries (every collision or stop at a new time starts a piece),
 * for actions (a move breaks the path, a no-op update does not, removal leaves a gap, setGlobal
 * restarts the motion), spans, Newton's cradle's chain, forgetBefore, without history, and errors.
 */
import { describe, expect, it } from "vitest";
import { positionAt } from "../physics/motion.js";
import { billiardsBreak, bouncingBalls, dilutedGas, newtonsCradle } from "../scene/presets.js";
import type { PathPiece } from "./path.js";
import { disc, scene } from "./testSupport.js";
import { Timeline } from "./timeline.js";

/** A piece's position at t (the contract's formula). */
const at = (p: PathPiece, t: number): [number, number] => {
  const tt = Math.min(t, p.tStop);
  return [positionAt(p.t0, p.x0, p.vx, p.ax, tt), positionAt(p.t0, p.y0, p.vy, p.ay, tt)];
};

/** Checks every piece of every body against stateAt at its ends and 5 times inside; the count. */
function checkAgainstStateAt(tl: Timeline): number {
  const ids = tl.stateAt(0).bodies.map((b) => b.id);
  let checked = 0;
  for (const id of ids) {
    const pieces = tl.path(id);
    expect(pieces.length).toBeGreaterThan(0);
    for (const p of pieces) {
      expect(p.until).toBeGreaterThan(p.from);
      for (let k = 0; k <= 6; k++) {
        // a piece's start is the instant after its event; stateAt gives the state after it too
        const t = k === 6 ? p.until : p.from + ((p.until - p.from) * k) / 6;
        if (k === 6 && p.until < tl.horizon) continue; // at `until` stateAt shows the next motion
        const s = tl.stateAt(t).bodies.find((b) => b.id === id);
        expect([s?.x, s?.y]).toEqual(at(p, t));
        checked++;
      }
    }
  }
  return checked;
}

describe("Timeline.path", () => {
  it("a friction break, balls under gravity and a gas: every piece gives stateAt's numbers bit for bit", () => {
    for (const sc of [billiardsBreak(), bouncingBalls(), dilutedGas({ n: 30, packing: 0.1, seed: 4 })]) {
      const tl = Timeline.fromScene(sc, { compute: false });
      tl.prolongTo(8);
      expect(checkAgainstStateAt(tl)).toBeGreaterThan(100);
    }
  });

  it("pieces join end to end, and each collision or stop of the body at a new time starts one", () => {
    const tl = Timeline.fromScene(dilutedGas({ n: 30, packing: 0.1, seed: 7 }), { compute: false });
    tl.prolongTo(10);
    for (const id of ["d0", "d7", "d19"]) {
      const pieces = tl.path(id);
      const times = new Set(
        tl
          .eventsBetween(0, tl.horizon)
          .filter((e) => e.type !== "action" && e.ids.includes(id) && e.time > 0 && e.time < tl.horizon)
          .map((e) => e.time),
      );
      expect(pieces.slice(1).map((p) => p.from)).toEqual([...times]);
      for (let k = 1; k < pieces.length; k++) {
        const [a, b] = [pieces[k - 1] as PathPiece, pieces[k] as PathPiece];
        expect(b.from).toBe(a.until);
        expect(at(b, b.from)).toEqual(at(a, a.until));
      }
      expect(pieces[0]?.from).toBe(0);
      expect(pieces[pieces.length - 1]?.until).toBe(tl.horizon);
    }
  });

  it("actions: a move breaks the path, a no-op update does not, a removal leaves a gap, setGlobal splits", () => {
    const tl = Timeline.fromScene(
      scene(
        [
          { time: 0, type: "addBody", id: "b", x: 0, y: 0, r: 1, m: 1, mu: 0.1, v: [1, 0] },
          { time: 1, type: "updateBody", id: "b", m: 1 }, // changes nothing: no new piece
          { time: 2, type: "updateBody", id: "b", x: 50 }, // a jump
          { time: 3, type: "setGlobal", g: 1 }, // friction restarts the motion
          { time: 4, type: "removeBody", id: "b" },
          { ...disc("b", 0, 9, [0, 1]), time: 6 },
        ],
        0,
      ),
    );
    tl.prolongTo(8);
    const pieces = tl.path("b");
    expect(pieces.map((p) => [p.from, p.until])).toEqual([
      [0, 2],
      [2, 3],
      [3, 4],
      [6, 8],
    ]);
    expect(at(pieces[0] as PathPiece, 2)).toEqual([2, 0]);
    expect(at(pieces[1] as PathPiece, 2)).toEqual([50, 0]);
    expect(pieces[1]?.ax).toBe(0); // g = 0 until t = 3
    expect(pieces[2]?.ax).toBeCloseTo(-0.1, 15);
    expect(at(pieces[3] as PathPiece, 8)).toEqual([0, 11]);
  });

  it("at `to` the last piece shows the body just before the actions logged at `to`", () => {
    const tl = Timeline.fromScene(
      scene([disc("b", 0, 0, [1, 0]), { time: 2, type: "updateBody", id: "b", x: 50 }], 0),
    );
    tl.prolongTo(4);
    const upTo2 = tl.path("b", 0, 2);
    expect(upTo2.map((p) => [p.from, p.until])).toEqual([[0, 2]]);
    expect(at(upTo2[0] as PathPiece, 2)).toEqual([2, 0]); // before the move
    expect(tl.stateAt(2).bodies[0]?.x).toBe(50); // stateAt: after it
    expect(at(tl.path("b", 2, 4)[0] as PathPiece, 2)).toEqual([50, 0]);
  });

  it("a span [from, to] clips the pieces to it; from = to gives the one point there (pathPoint.test.ts)", () => {
    const tl = Timeline.fromScene(dilutedGas({ n: 30, packing: 0.1, seed: 7 }), { compute: false });
    tl.prolongTo(10);
    const all = tl.path("d3");
    const part = tl.path("d3", 2.5, 7.25);
    expect(part[0]?.from).toBe(2.5);
    expect(part[part.length - 1]?.until).toBe(7.25);
    const inside = all.filter((p) => p.until > 2.5 && p.from < 7.25);
    expect(part.map(({ from, until, ...m }) => m)).toEqual(inside.map(({ from, until, ...m }) => m));
    const point = tl.path("d3", 4, 4);
    expect(point.map(({ from, until }) => [from, until])).toEqual([[4, 4]]);
    const around = all.find((p) => p.from <= 4 && 4 < p.until) as PathPiece;
    expect(point.map(({ from, until, ...m }) => m)).toEqual([(({ from, until, ...m }) => m)(around)]);
  });

  it("Newton's cradle: the chain of collisions at t = 1 gives no pieces of no length", () => {
    const tl = Timeline.fromScene(newtonsCradle(), { compute: false });
    tl.prolongTo(3);
    const ids = tl.stateAt(0).bodies.map((b) => b.id);
    for (const id of ids) for (const p of tl.path(id)) expect(p.until).toBeGreaterThan(p.from);
    // a middle ball: at rest throughout (its two collisions at t = 1 pass the momentum on)
    const middle = tl.path("c3");
    expect(middle.map((p) => [p.from, p.until, p.vx])).toEqual([
      [0, 1, 0],
      [1, 3, 0],
    ]);
  });

  it("after forgetBefore it reads from historyStart on; without history only the current motion", () => {
    const tl = Timeline.fromScene(dilutedGas({ n: 30, packing: 0.1, seed: 7 }), { compute: false });
    tl.apply({ time: 150, type: "giveVelocity", id: "d1", v: [1, 0] }); // a keyframe at 150
    tl.prolongTo(300);
    const whole = tl.path("d5", 200, 300);
    const start = tl.forgetBefore(200);
    expect(start).toBeGreaterThan(0);
    expect(tl.path("d5", 200, 300)).toEqual(whole);
    expect(tl.path("d5")[0]?.from).toBe(start);
    expect(() => tl.path("d5", start / 2)).toThrow(RangeError);

    const headless = Timeline.fromScene(scene([disc("b", 0, 0, [1, 0])], 0), { history: false });
    headless.prolongTo(5);
    expect(headless.path("b")).toEqual([
      { from: 0, until: 5, t0: 0, x0: 0, y0: 0, vx: 1, vy: 0, ax: 0, ay: 0, tStop: Number.POSITIVE_INFINITY },
    ]);
  });

  it("refuses an unknown id and a time outside [historyStart, horizon] or before `from`, naming it", () => {
    const tl = Timeline.fromScene(scene([disc("b", 0, 0, [1, 0])], 0));
    tl.prolongTo(5);
    expect(() => tl.path("nobody")).toThrow(
      'path(id): must name a body of this timeline (got the string "nobody")',
    );
    expect(() => tl.path("b", -1)).toThrow("path(from): must be a number in [0, 5] (got -1)");
    expect(() => tl.path("b", 0, 6)).toThrow("path(to): must be a number in [0, 5] (got 6)");
    expect(() => tl.path("b", 3, 2)).toThrow("path(to): must be a number in [3, 5] (got 2)");
    expect(() => tl.path("b", Number.NaN)).toThrow(RangeError);
  });

  it("says why a time before `from`, or before a headless timeline's last entry, is refused (nothing was forgotten)", () => {
    const tl = Timeline.fromScene(scene([disc("b", 0, 0, [1, 0])], 0));
    tl.prolongTo(5);
    const reason = (f: () => unknown) => {
      try {
        f();
      } catch (e) {
        return (e as Error).message;
      }
      return "no error";
    };
    expect(reason(() => tl.path("b", 3, 2))).toBe(
      "path(to): must be a number in [3, 5] (got 2): to must not be before from (3)",
    );
    const headless = Timeline.fromScene(scene([disc("b", 0, 0, [1, 0])], 0), { history: false });
    headless.apply({ time: 2, type: "giveVelocity", id: "b", v: [0, 1] });
    headless.prolongTo(5);
    const keepsNone =
      "this timeline keeps no history (history: false), so the earliest readable time is 2, its last logged event or action: to read earlier times, create the Timeline with history: true (the default)";
    expect(reason(() => headless.path("b", 1))).toBe(
      `path(from): must be a number in [2, 5] (got 1): ${keepsNone}`,
    );
    // review: a to after the last entry but before from is refused as before from
    expect(reason(() => headless.path("b", 3, 2.5))).toBe(
      "path(to): must be a number in [3, 5] (got 2.5): to must not be before from (3)",
    );
    expect(reason(() => headless.path("b", 4, 3))).toBe(
      "path(to): must be a number in [4, 5] (got 3): to must not be before from (4)",
    );
    expect(reason(() => headless.path("b", 2, 1))).toBe(
      `path(to): must be a number in [2, 5] (got 1): ${keepsNone}`,
    );
  });
});
