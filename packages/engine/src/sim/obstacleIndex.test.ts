// ObstacleIndex against the list operations it replaced (append a copy, map to update, filter to
// remove): after any run of adds, updates, removals (a removed id re-added too), compactions and
// copies, the compacted list holds the same obstacles in the same order, and has/get answer as the
// plain list would. Prints its seed; set FC_SEED to explore others.
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { ObstacleIndex } from "./obstacleIndex.js";

interface Item {
  readonly id: string;
  readonly v: number;
}

const SEED = Number(process.env.FC_SEED ?? 20261124);

/** An operation: kind, an id among a few (so ids collide, come back after removal), a value. */
const op = fc.tuple(fc.constantFrom("add", "update", "remove", "compact", "copy"), fc.nat(11), fc.nat(999));

describe("ObstacleIndex", () => {
  it("keeps the order and contents the plain list operations give", () => {
    console.log(`[obstacle index] fast-check seed ${SEED} (set FC_SEED to change)`);
    fc.assert(
      fc.property(fc.array(op, { minLength: 30, maxLength: 200 }), (ops) => {
        let list: Item[] = [];
        let index = new ObstacleIndex<Item>();
        let plain: Item[] = [];
        for (const [kind, n, v] of ops) {
          const id = `o${n}`;
          const there = plain.some((o) => o.id === id);
          expect(index.has(list, id)).toBe(there);
          expect(index.get(list, id)).toBe(plain.find((o) => o.id === id));
          if (kind === "add" && !there) {
            const item = { id, v };
            index.add(list, item);
            plain = [...plain, item];
          } else if (kind === "update" && there) {
            const item = { id, v };
            index.replace(list, item);
            plain = plain.map((o) => (o.id === id ? item : o));
          } else if (kind === "remove" && there) {
            index.remove(list, id);
            plain = plain.filter((o) => o.id !== id);
          } else if (kind === "compact") {
            index.compact(list);
            expect(list).toEqual(plain);
          } else if (kind === "copy") {
            // SimState.copyInto: compact, copy the list; the copy's index (which may have indexed
            // its own empty list already) is reset and indexes the copy when next asked.
            index.compact(list);
            list = list.slice();
            index = new ObstacleIndex<Item>();
            expect(index.has([], id)).toBe(false);
            index.reset();
          }
        }
        index.compact(list);
        expect(list).toEqual(plain);
        for (const o of plain) expect(index.get(list, o.id)).toBe(o);
      }),
      { seed: SEED, numRuns: 300 },
    );
  });

  it("leaves a removed entry in place until compact, then drops it keeping the others' order", () => {
    const list: Item[] = [];
    const index = new ObstacleIndex<Item>();
    for (const id of ["c", "a", "d", "b"]) index.add(list, { id, v: 0 });
    index.remove(list, "a");
    index.add(list, { id: "a", v: 1 }); // re-added: goes to the end, as filter then append put it
    expect(list.map((o) => o.id)).toEqual(["c", "a", "d", "b", "a"]);
    expect(index.get(list, "a")).toEqual({ id: "a", v: 1 });
    index.compact(list);
    expect(list).toEqual([
      { id: "c", v: 0 },
      { id: "d", v: 0 },
      { id: "b", v: 0 },
      { id: "a", v: 1 },
    ]);
    expect(index.get(list, "b")).toEqual({ id: "b", v: 0 });
  });
});
