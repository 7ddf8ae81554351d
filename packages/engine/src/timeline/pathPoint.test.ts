/**
 * Timeline.path over a span of no length, [T, T] (path.ts): the one point where the body is at T, a
 * single piece with from = until = T and the motion it follows from T on, after everything logged
 * at T; none when the body does not exist then. Checked against stateAt(T) bit for bit and against
 * the first piece of [T, horizon] at every kind of instant: an event, a chain of events at one
 * instant, each kind of action (a move, a removal, an addition), between events, 0 and the horizon;
 * with and without history. (It gave no piece, undocumented: audit of session 23.)
 */
import { describe, expect, it } from "vitest";
import { positionAt } from "../physics/motion.js";
import { dilutedGas, newtonsCradle } from "../scene/presets.js";
import type { PathPiece } from "./path.js";
import { disc, scene } from "./testSupport.js";
import { Timeline } from "./timeline.js";

/** A piece's position at t (the contract's formula). */
const at = (p: PathPiece, t: number): [number, number] => {
  const tt = Math.min(t, p.tStop);
  return [positionAt(p.t0, p.x0, p.vx, p.ax, tt), positionAt(p.t0, p.y0, p.vy, p.ay, tt)];
};
/** The motion of a piece, without its span. */
const motion = ({ from, until, ...m }: PathPiece) => m;

/** Checks path(id, T, T) of every body ever added at each T; returns how many points it checked. */
function checkPoints(tl: Timeline, ids: readonly string[], times: readonly number[]): number {
  let points = 0;
  for (const t of times)
    for (const id of ids) {
      const point = tl.path(id, t, t);
      const state = tl.stateAt(t).bodies.find((b) => b.id === id);
      if (state === undefined) {
        expect(point, `${id} at ${t}`).toEqual([]);
        continue;
      }
      expect(
        point.map((p) => [p.from, p.until]),
        `${id} at ${t}`,
      ).toEqual([[t, t]]);
      const p = point[0] as PathPiece;
      expect(at(p, t), `${id} at ${t}`).toEqual([state.x, state.y]);
      // the motion it follows from t on: the first piece of [t, horizon] when that starts at t
      const next = t < tl.horizon ? tl.path(id, t, tl.horizon)[0] : undefined;
      if (next !== undefined && next.from === t) expect(motion(p), `${id} at ${t}`).toEqual(motion(next));
      points++;
    }
  return points;
}

describe("Timeline.path over a span of no length", () => {
  it("a gas: at its events, between them, at 0 and at the horizon, stateAt's point bit for bit", () => {
    const tl = Timeline.fromScene(dilutedGas({ n: 30, packing: 0.1, seed: 7 }), { compute: false });
    tl.prolongTo(10);
    const ids = tl.stateAt(0).bodies.map((b) => b.id);
    const events = tl
      .eventsBetween(0, tl.horizon)
      .filter((e) => e.type !== "action")
      .map((e) => e.time);
    expect(events.length).toBeGreaterThan(10);
    const times = [0, ...events.slice(0, 12), ...events.slice(0, 12).map((t) => t / 2 + 1), tl.horizon];
    expect(checkPoints(tl, ids, times)).toBe(times.length * ids.length);
  });

  it("actions at T: after a move the moved body, after a removal none, after an addition the new body", () => {
    const tl = Timeline.fromScene(
      scene(
        [
          disc("b", 0, 0, [1, 0]),
          { time: 0, type: "addLine", id: "w", p1: [3, -5], p2: [3, 5], kind: "line" },
          { time: 5, type: "updateBody", id: "b", x: -20 }, // a jump
          { time: 6, type: "removeBody", id: "b" },
          disc("b", 0, 9, [0, 1], 7), // back
          disc("c", 10, 9, [0, 0], 8), // a new body, added at the horizon
        ],
        0,
      ),
    );
    tl.prolongTo(8);
    // the wall at t = 2: b turns back
    expect(tl.path("b", 2, 2).map((p) => p.vx)).toEqual([-1]);
    expect(tl.path("b", 5, 5).map((p) => at(p, 5))).toEqual([[-20, 0]]); // after the jump
    expect(tl.path("b", 6, 6)).toEqual([]); // removed at 6
    expect(tl.path("b", 6.5, 6.5)).toEqual([]);
    expect(tl.path("b", 7, 7).map((p) => at(p, 7))).toEqual([[0, 9]]); // back at 7
    expect(tl.path("c", 8, 8).map((p) => [p.from, p.until, ...at(p, 8)])).toEqual([[8, 8, 10, 9]]);
    expect(checkPoints(tl, ["b", "c"], [0, 1, 2, 3, 5, 5.5, 6, 6.5, 7, 7.5, 8])).toBe(9 + 1); // b at all but 6 and 6.5, c at 8
    // a span of length ends at `to` before the actions there, and begins at `from` after them
    expect(tl.path("b", 4, 5).map((p) => at(p, 5))).toEqual([[-1, 0]]);
    expect(tl.path("b", 5, 5.5).map((p) => at(p, 5))).toEqual([[-20, 0]]);
  });

  it("Newton's cradle: at the chain of collisions at t = 1, the motions after the whole chain", () => {
    const tl = Timeline.fromScene(newtonsCradle(), { compute: false });
    tl.prolongTo(3);
    const ids = tl.stateAt(0).bodies.map((b) => b.id);
    expect(checkPoints(tl, ids, [0, 0.5, 1, 2, 3])).toBe(5 * ids.length);
    // one ball moves on after the chain, as stateAt(1) says
    const moving = ids.filter((id) => (tl.path(id, 1, 1)[0] as PathPiece).vx !== 0);
    expect(moving).toHaveLength(1);
    expect(moving).toEqual(
      tl
        .stateAt(1)
        .bodies.filter((b) => b.vx !== 0)
        .map((b) => b.id),
    );
  });

  it("without history: the current motion, from the last logged entry on", () => {
    const tl = Timeline.fromScene(scene([disc("b", 0, 0, [1, 0])], 0), { history: false });
    tl.apply({ time: 2, type: "giveVelocity", id: "b", v: [0, 1] });
    tl.prolongTo(5);
    for (const t of [2, 3.5, 5]) {
      expect(tl.path("b", t, t)).toEqual([
        { from: t, until: t, t0: 2, x0: 2, y0: 0, vx: 0, vy: 1, ax: 0, ay: 0, tStop: Infinity },
      ]);
      expect(at(tl.path("b", t, t)[0] as PathPiece, t)).toEqual([2, t - 2]);
    }
  });

  it("a timeline computed nowhere yet (horizon 0): path(id) is the point at 0", () => {
    const tl = Timeline.fromScene(scene([disc("b", 3, 4, [1, 0])], 0), { compute: false });
    expect(tl.horizon).toBe(0);
    expect(tl.path("b")).toEqual([
      { from: 0, until: 0, t0: 0, x0: 3, y0: 4, vx: 1, vy: 0, ax: 0, ay: 0, tStop: Infinity },
    ]);
  });
});
