/**
 * An error thrown by `advance`'s onEvent callback ends the advance and is passed on, and the World
 * is what an advance stopped by maxEvents after that event leaves: the event processed and counted,
 * the clock at it, an edit the callback made before throwing kept; a later advance goes on from
 * there with the same events, bit for bit. (Review of session 26: a game's callback that throws, a
 * refused edit in it, was not documented.)
 */
import { describe, expect, it } from "vitest";
import { dilutedGas } from "../scene/presets.js";
import type { WorldEvent } from "./types.js";
import { World } from "./world.js";

/** 30 frictionless discs in a box (the preset's gas, seed 3) as a World. */
function gas(): World {
  const w = new World({ g: 0 });
  for (const a of dilutedGas({ n: 30, packing: 0.2, seed: 3 }).actions) {
    if (a.type === "addBody") {
      const [vx, vy] = a.v ?? [0, 0];
      w.addBody(a.id, { x: a.x, y: a.y, r: a.r, m: a.m as number, vx, vy });
    } else if (a.type === "addLine") w.addLine(a.id, a.p1, a.p2, a.kind);
  }
  return w;
}

/** Everything observable of a World: its clock, counts and every body's state. */
function snapshot(w: World): unknown {
  return { time: w.time, counts: { ...w.counts }, bodies: w.bodies(), lines: w.lines() };
}

/** The events of advancing w to `until`, copied. */
function run(w: World, until: number): WorldEvent[] {
  const log: WorldEvent[] = [];
  w.advance({ untilTime: until }, (e) => log.push({ ...e }));
  return log;
}

describe("a callback that throws", () => {
  for (const k of [1, 7, 20])
    it(`at event ${k}: the World is as maxEvents ${k} leaves it, and goes on alike`, () => {
      const thrown = gas();
      let n = 0;
      const boom = new Error("the game's own error");
      expect(() =>
        thrown.advance({ untilTime: 5 }, () => {
          if (++n === k) throw boom;
        }),
      ).toThrow(boom);
      const stopped = gas();
      expect(stopped.advance({ maxEvents: k })).toEqual({ events: k, reason: "events" });
      expect(snapshot(thrown)).toEqual(snapshot(stopped));
      expect(thrown.time).toBeGreaterThan(0);
      expect(run(thrown, 5)).toEqual(run(stopped, 5));
      expect(snapshot(thrown)).toEqual(snapshot(stopped));
    });

  it("after an edit in the callback: the edit is kept, as if made between two advances", () => {
    const thrown = gas();
    let removed = "";
    expect(() =>
      thrown.advance({ untilTime: 5 }, (e) => {
        if (e.kind !== "bodyLine") return;
        removed = e.a;
        thrown.removeBody(e.a);
        thrown.addLine("extra", [0, -100], [1, -100], "segment");
        thrown.addBody("intruder", { x: 0, y: 0, r: 1e6, m: 1 }); // refused: it overlaps
      }),
    ).toThrow(/^x: the body would overlap/);
    expect(removed).not.toBe("");
    const stopped = gas();
    const events = thrown.counts.bodyBody + thrown.counts.bodyLine + thrown.counts.stop;
    stopped.advance({ maxEvents: events });
    stopped.removeBody(removed);
    stopped.addLine("extra", [0, -100], [1, -100], "segment");
    expect(snapshot(thrown)).toEqual(snapshot(stopped));
    expect(thrown.hasBody(removed) || thrown.hasBody("intruder")).toBe(false);
    expect(run(thrown, 5)).toEqual(run(stopped, 5));
  });
});
