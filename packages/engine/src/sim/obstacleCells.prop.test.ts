// ObstacleCells answers every query as a scan of all obstacles does (the smallest id the overlap test
// holds for), through sets, moves and deletes, with the scene's and the World's overlap tests, on
// touching pairs (within OVERLAP_REL and just past it), long and short segments, points, lines and
// rays, tiny radii and far-off coordinates (where the test's round-off is largest).
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { discOverlapsLine, discOverlapsPoint } from "../scene/overlap.js";
import { seedFor } from "../timeline/testSupport.js";
import { OVERLAP_REL } from "../tolerances.js";
import { levelAtLeast, ObstacleCells } from "./obstacleCells.js";
import { distanceToLine, type LineKind, makeLine } from "./obstacles.js";
import type { Vec2 } from "./types.js";

interface Item {
  p1: Vec2;
  p2: Vec2;
  kind: LineKind | "point";
}

/** The scene's test (scene/overlap.ts) and the World's (sim/placement.ts) of a disc against an item. */
const TESTS = {
  scene: (x: number, y: number, r: number, o: Item) =>
    o.kind === "point" ? discOverlapsPoint(x, y, r, o.p1) : discOverlapsLine(x, y, r, o.p1, o.p2, o.kind),
  world: (x: number, y: number, r: number, o: Item) => {
    const rk = r * (1 - OVERLAP_REL);
    if (o.kind !== "point") return distanceToLine(makeLine("", o.p1, o.p2, o.kind), x, y) < rk;
    const dx = o.p1[0] - x;
    const dy = o.p1[1] - y;
    return dx * dx + dy * dy < rk * rk;
  },
};

/** Coordinates o + s·u of a frame (an offset and a scale), some far from the origin or tiny. */
const frame = fc.record({
  o: fc.constantFrom(0, 0, 1e6, -1e12, 3e15, 1e29),
  s: fc.constantFrom(1, 1, 1e-6, 1e3),
});
const lattice = fc.integer({ min: -24, max: 24 }).map((k) => k / 2);
const far = fc.integer({ min: -2000, max: 2000 });
const id = fc.integer({ min: 0, max: 29 }).map((k) => `o${k}`);
const item = fc.record({
  kind: fc.constantFrom("segment", "segment", "segment", "point", "point", "line", "ray") as fc.Arbitrary<
    Item["kind"]
  >,
  a: fc.tuple(lattice, lattice),
  b: fc.oneof(
    { arbitrary: fc.tuple(lattice, lattice), weight: 4 },
    { arbitrary: fc.tuple(far, far), weight: 1 },
  ),
});
/** A disc: at a lattice point, or touching an item (an end or the middle) up to a relative gap δ. */
const disc = fc.record({
  at: fc.oneof(fc.constant(-1), fc.integer({ min: 0, max: 29 })),
  c: fc.tuple(lattice, lattice),
  end: fc.constantFrom(0, 0.5, 1),
  angle: fc.constantFrom(0, 1, 2, 3, 0.5),
  rho: fc.constantFrom(0.25, 0.5, 1, 3, 40, 1e-9),
  gap: fc.constantFrom(0, 0, 3e-10, -3e-10, 1e-9, -1e-9, 2e-9, -2e-9, 1e-3, -1e-3, 0.5),
});
const step = fc.oneof(
  { arbitrary: fc.record({ op: fc.constant("set" as const), id, item }), weight: 5 },
  { arbitrary: fc.record({ op: fc.constant("delete" as const), id }), weight: 1 },
  { arbitrary: fc.record({ op: fc.constant("query" as const), disc }), weight: 6 },
);

type Step = typeof step extends fc.Arbitrary<infer S> ? S : never;

/** Runs `steps` on an index and on a plain map; returns the two lists of answers. */
function run(
  f: { o: number; s: number },
  steps: Step[],
  test: (x: number, y: number, r: number, o: Item) => boolean,
  options: ConstructorParameters<typeof ObstacleCells>[0],
): [(string | undefined)[], (string | undefined)[]] {
  const at = (u: number) => f.o + f.s * u;
  const cells = new ObstacleCells<Item>(options);
  const all = new Map<string, Item>();
  const got: (string | undefined)[] = [];
  const want: (string | undefined)[] = [];
  for (const st of steps) {
    if (st.op === "set") {
      const p1: Vec2 = [at(st.item.a[0]), at(st.item.a[1])];
      let p2: Vec2 = st.item.kind === "point" ? p1 : [at(st.item.b[0]), at(st.item.b[1])];
      if (p2[0] === p1[0] && p2[1] === p1[1] && st.item.kind !== "point") p2 = [p1[0] + f.s, p1[1]];
      if (p2[0] === p1[0] && p2[1] === p1[1] && st.item.kind !== "point") continue; // far off: no room
      const o: Item = { p1, p2, kind: st.item.kind };
      cells.set(st.id, o, p1[0], p1[1], p2[0], p2[1], o.kind === "segment" || o.kind === "point");
      all.set(st.id, o);
    } else if (st.op === "delete") {
      cells.delete(st.id);
      all.delete(st.id);
    } else {
      const d = st.disc;
      const r = f.s * d.rho;
      let x = at(d.c[0]);
      let y = at(d.c[1]);
      const target = [...all.values()][d.at];
      if (target !== undefined) {
        // a point of the item, then r (1 + gap) away from it
        x = target.p1[0] + d.end * (target.p2[0] - target.p1[0]);
        y = target.p1[1] + d.end * (target.p2[1] - target.p1[1]);
        x += r * (1 + d.gap) * Math.cos(d.angle * (Math.PI / 2));
        y += r * (1 + d.gap) * Math.sin(d.angle * (Math.PI / 2));
      }
      got.push(cells.smallestHit(x, y, r, (o) => test(x, y, r, o)));
      let best: string | undefined;
      for (const [k, o] of all) if ((best === undefined || k < best) && test(x, y, r, o)) best = k;
      want.push(best);
    }
  }
  return [got, want];
}

describe("ObstacleCells", () => {
  for (const [name, test] of Object.entries(TESTS))
    for (const [mode, options] of [
      ["indexed from the first query", { scanQueries: 0, scanSize: 0 }],
      ["default (a scan first)", {}],
    ] as const)
      it(`answers as a scan of every obstacle does (${name}'s overlap test, ${mode}) (property)`, () => {
        let hits = 0;
        fc.assert(
          fc.property(frame, fc.array(step, { minLength: 1, maxLength: 80 }), (f, steps) => {
            const [got, want] = run(f, steps, test, options);
            hits += want.filter((w) => w !== undefined).length;
            expect(got).toEqual(want);
          }),
          { seed: seedFor(`ObstacleCells against a scan (${name}, ${mode})`), numRuns: 150 },
        );
        // the cases overlap often enough for the answers to say something
        expect(hits).toBeGreaterThan(100);
      });

  it("levelAtLeast gives the smallest power of two at least v, exactly", () => {
    for (const v of [1, 2, 3, 0.75, 1e-300, 5e-324, 1e30, 2 ** 52 + 1, 1 - 2 ** -53, 1 + 2 ** -52]) {
      const k = levelAtLeast(v);
      if (v >= 2 ** -1022) {
        expect(2 ** k).toBeGreaterThanOrEqual(v);
        expect(2 ** (k - 1)).toBeLessThan(v);
      } else expect(k).toBe(-1022);
    }
  });

  it("finds a long segment from a disc near its middle, and a point under a disc far larger than it", () => {
    const cells = new ObstacleCells<string>({ scanQueries: 0, scanSize: 0 });
    cells.set("wall", "wall", -1e6, 3, 1e6, 3, true);
    cells.set("peg", "peg", 500, 500, 500, 500, true);
    cells.set("short", "short", 0, 0, 1, 0, true);
    const near = (id: string) => id === "wall" || id === "peg";
    expect(cells.smallestHit(0.5, 3.5, 1, near)).toBe("wall");
    expect(cells.smallestHit(400, 400, 1000, (id) => id === "peg")).toBe("peg");
    cells.delete("peg");
    expect(cells.smallestHit(400, 400, 1000, (id) => id === "peg")).toBeUndefined();
  });

  it("forgets a deleted or moved obstacle in every table it was in (the cells read no freed slot)", () => {
    const cells = new ObstacleCells<{ id: string }>({ scanQueries: 0, scanSize: 0 });
    const all = (o: { id: string } | undefined) => o !== undefined && o.id.length > 0;
    cells.set("a", { id: "a" }, 0, 0, 0, 0, true);
    cells.set("b", { id: "b" }, 10, 0, 12, 0, true);
    // tables for three sizes of disc
    for (const r of [0.5, 8, 1000]) expect(cells.smallestHit(0, 0, r, all)).toBe("a");
    cells.delete("a");
    cells.set("b", { id: "b" }, 100, 100, 101, 100, true);
    for (const r of [0.5, 8]) expect(cells.smallestHit(0, 0, r, all)).toBeUndefined();
    expect(cells.smallestHit(100, 100, 1, all)).toBe("b");
    expect(cells.size).toBe(1);
  });
});
