// Removing and updating obstacles in the middle of a long list (obstacleIndex.ts: a removal leaves
// its entry until the list is next read whole): the World's lists keep the order the plain list
// operations gave (append, map in place, filter), and its events equal those of a World built
// afresh with the final obstacles, in that order or any other. Refused placements still name the
// smallest id among the live obstacles (or bodies) overlapped, never a removed one.
import { describe, expect, it } from "vitest";
import {
  type MazePeg,
  type MazeWall,
  maze,
  mazeAdds,
  mazeWorld,
  obstacleOrder,
} from "../../test/obstacleScene.js";
import { outcome } from "../../test/outcome.js";
import type { Vec2 } from "./types.js";
import { World } from "./world.js";

/** The obstacles as the old list operations kept them: append, map in place, filter. */
class PlainLists {
  walls: MazeWall[];
  pegs: MazePeg[];
  constructor(walls: MazeWall[], pegs: MazePeg[]) {
    this.walls = walls.slice();
    this.pegs = pegs.slice();
  }
  /** A World with these walls and pegs in this order (or reversed) and the discs after them. */
  world(discs: ReturnType<typeof maze>["discs"], reversed = false): World {
    const adds = mazeAdds({ walls: this.walls, pegs: this.pegs, discs });
    const obstacles = adds.slice(0, -discs.length);
    return mazeWorld([...(reversed ? obstacles.reverse() : obstacles), ...adds.slice(-discs.length)]);
  }
}

/** A wall 0.5 shorter at each end (axis-parallel walls of length 6: exact, and still clear of the discs). */
function shrunk(l: MazeWall): [Vec2, Vec2] {
  const dx = Math.sign(l.p2[0] - l.p1[0]) * 0.5;
  const dy = Math.sign(l.p2[1] - l.p1[1]) * 0.5;
  return [
    [l.p1[0] + dx, l.p1[1] + dy],
    [l.p2[0] - dx, l.p2[1] - dy],
  ];
}

/**
 * Edits in the middle third of the walls and pegs, on the World and on the plain lists alike: every
 * 3rd wall removed, every 5th shrunk, a few others removed and added again (they go to the end),
 * every 4th peg removed and every 7th moved (a move refused, a disc being there, is left out of
 * both). `probe` runs between edits (a read, a copy). Returns the refusals.
 */
function editMiddle(w: World, plain: PlainLists, probe: (k: number) => void): string[] {
  const refused: string[] = [];
  const walls = plain.walls.slice(plain.walls.length / 3, (2 * plain.walls.length) / 3);
  const pegs = plain.pegs.slice(plain.pegs.length / 3, (2 * plain.pegs.length) / 3);
  walls.forEach((l, k) => {
    if (k % 3 === 0) {
      w.removeLine(l.id);
      plain.walls = plain.walls.filter((o) => o.id !== l.id);
    } else if (k % 5 === 0) {
      const [p1, p2] = shrunk(l);
      w.updateLine(l.id, { p1, p2 });
      plain.walls = plain.walls.map((o) => (o.id === l.id ? { id: l.id, p1, p2 } : o));
    } else if (k % 50 === 1) {
      w.removeLine(l.id);
      w.addLine(l.id, l.p1, l.p2, "segment");
      plain.walls = [...plain.walls.filter((o) => o.id !== l.id), l];
    }
    probe(k);
  });
  pegs.forEach((p, k) => {
    if (k % 4 === 0) {
      w.removePoint(p.id);
      plain.pegs = plain.pegs.filter((o) => o.id !== p.id);
    } else if (k % 7 === 0) {
      const q: Vec2 = [p.p[0], p.p[1] % 6 === 1 ? p.p[1] + 4 : p.p[1] - 4]; // the cell's other corner
      try {
        w.updatePoint(p.id, q);
        plain.pegs = plain.pegs.map((o) => (o.id === p.id ? { id: p.id, p: q } : o));
      } catch (e) {
        refused.push((e as Error).message);
      }
    }
    probe(k);
  });
  return refused;
}

describe("removals and updates in the middle of a long list of obstacles", () => {
  const m = maze(5, 30, 1500, 8);

  it("at time 0: the lists keep their order, and the events equal a World built afresh", () => {
    expect(m.walls.length).toBeGreaterThan(900);
    expect(m.pegs.length).toBeGreaterThan(1000);
    const w = mazeWorld(mazeAdds(m));
    const plain = new PlainLists(m.walls, m.pegs);
    // Between edits now and then: a read of the lines (which drops removed entries), and a probe
    // of the next event (a copy of the World, made with removals pending).
    const refused = editMiddle(w, plain, (k) => {
      if (k % 97 === 0) w.lines();
      if (k % 89 === 0) w.nextEventTime();
    });
    expect(refused).toEqual([]); // at time 0 the discs are at their cells' centres
    expect(obstacleOrder(w)).toEqual({
      lines: plain.walls.map((l) => l.id),
      points: plain.pegs.map((p) => p.id),
    });
    const afresh = plain.world(m.discs);
    expect(w.lines()).toEqual(afresh.lines());
    expect(w.points()).toEqual(afresh.points());
    const expected = outcome(afresh, 500);
    expect(expected.events.length).toBe(500);
    expect(outcome(w, 500)).toEqual(expected);
    expect(outcome(plain.world(m.discs, true), 500)).toEqual(expected);
  });

  it("inside advance's callback: as the same edits made between two advances", () => {
    const between = mazeWorld(mazeAdds(m));
    between.advance({ maxEvents: 150 });
    const refusedBetween = editMiddle(between, new PlainLists(m.walls, m.pegs), () => {});
    const inside = mazeWorld(mazeAdds(m));
    let n = 0;
    let refusedInside: string[] = [];
    inside.advance({ maxEvents: 150 }, () => {
      if (++n === 150) refusedInside = editMiddle(inside, new PlainLists(m.walls, m.pegs), () => {});
    });
    expect(refusedInside).toEqual(refusedBetween);
    expect(inside.time).toBe(between.time);
    expect(obstacleOrder(inside)).toEqual(obstacleOrder(between));
    const expected = outcome(between, 400);
    expect(expected.events.length).toBe(400);
    expect(outcome(inside, 400)).toEqual(expected);
  });
});

describe("a removal pending in a long list", () => {
  it("is gone for the next event's probe, the copy, the grid and the lists", () => {
    const w = new World({ g: 0 });
    for (let i = 0; i < 2000; i++) w.addLine(`f${i}`, [100 + i, 50], [100 + i, 52], "segment");
    w.addLine("near", [5, -3], [5, 3], "segment");
    for (let i = 2000; i < 4000; i++) w.addLine(`f${i}`, [100 + i, 50], [100 + i, 52], "segment");
    w.addLine("far", [10, -3], [10, 3], "segment");
    w.addPoint("pin", [7, 0]);
    w.addBody("a", { x: 0, y: 0, r: 1, m: 1, vx: 1 });
    expect(w.nextEventTime()).toBe(4);
    w.removeLine("near");
    expect(w.nextEventTime()).toBe(6); // the point; not the removed line at 4
    w.removePoint("pin");
    const copy = w.clone();
    expect(w.nextEventTime()).toBe(9);
    expect(copy.nextEventTime()).toBe(9);
    expect(w.hasLine("near") || w.hasPoint("pin")).toBe(false);
    expect(w.lines().map((l) => l.id)).not.toContain("near");
    expect(outcome(w, 1).events[0]).toMatchObject({ time: 9, kind: "bodyLine", b: "far" });
    expect(outcome(copy, 1).events[0]).toMatchObject({ time: 9, kind: "bodyLine", b: "far" });
  });
});

describe("refused placements among many obstacles name the smallest live id", () => {
  /** 3,000 segments far away, with segments "m5", "c3", "k9" and points "q2", "e7" through the origin spread among them. */
  function crowded(): World {
    const w = new World({ g: 0 });
    const through: Record<number, () => void> = {
      10: () => w.addLine("m5", [-3, -0.5], [3, -0.5], "segment"),
      1500: () => w.addLine("c3", [-0.5, -3], [-0.5, 3], "segment"),
      2990: () => w.addLine("k9", [-3, 0.5], [3, 0.5], "segment"),
      700: () => w.addPoint("q2", [0.3, 0]),
      2200: () => w.addPoint("e7", [-0.3, 0]),
    };
    for (let i = 0; i < 3000; i++) {
      w.addLine(
        `f${i}`,
        [100 + (i % 50) * 4, Math.floor(i / 50) * 4],
        [102 + (i % 50) * 4, Math.floor(i / 50) * 4],
        "segment",
      );
      through[i]?.();
    }
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
  const disc = { x: 0, y: 0, r: 1, m: 1 };

  it("lines, then points, through removals (pending or read), re-adds and moves", () => {
    const w = crowded();
    expect(refusal(() => w.addBody("a", disc))).toBe('x: the body would overlap line "c3"');
    w.removeLine("c3");
    expect(refusal(() => w.addBody("a", disc))).toBe('x: the body would overlap line "k9"');
    w.addLine("c3", [-0.5, -3], [-0.5, 3], "segment"); // now last in the list
    expect(refusal(() => w.addBody("a", disc))).toBe('x: the body would overlap line "c3"');
    w.updateLine("c3", { p1: [-50, -3], p2: [-50, 3] });
    w.removeLine("k9");
    w.removeLine("f1200");
    expect(refusal(() => w.addBody("a", disc))).toBe('x: the body would overlap line "m5"');
    w.removeLine("m5");
    expect(refusal(() => w.addBody("a", disc))).toBe('x: the body would overlap point "e7"');
    w.removePoint("e7");
    expect(refusal(() => w.addBody("a", disc))).toBe('x: the body would overlap point "q2"');
    w.updatePoint("q2", [5, 5]);
    w.addBody("a", disc);
    expect(w.body("a")).toMatchObject(disc);
  });

  it("a new segment through several bodies (added largest id first) names the smallest", () => {
    const w = crowded();
    w.removeLine("c3");
    w.removeLine("k9");
    w.removeLine("m5");
    w.removePoint("q2");
    w.removePoint("e7");
    for (const [id, x] of [
      ["z", 0],
      ["n", 10],
      ["b", 20],
    ] as const)
      w.addBody(id, { x, y: 0, r: 1, m: 1 });
    expect(refusal(() => w.addLine("cut", [-5, 0], [25, 0], "segment"))).toBe(
      'p1: the line would overlap body "b"',
    );
    expect(refusal(() => w.addLine("cut", [-5, 0], [15, 0], "segment"))).toBe(
      'p1: the line would overlap body "n"',
    );
    expect(refusal(() => w.addPoint("pin", [10.5, 0]))).toBe('p: the point would lie inside body "n"');
    expect(w.hasLine("cut")).toBe(false);
  });
});
