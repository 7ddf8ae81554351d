// IndexedHeap: pops in (key, canonical tie order) whatever the sequence of inserts, re-keys and
// removals; keys drawn from a few values so that exact ties are common.
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { IndexedHeap } from "./eventQueue.js";

const SEED = Number(process.env.FC_SEED ?? 20261122);

type Op = { slot: number; key: number } | { remove: number };

function drain(heap: IndexedHeap): number[] {
  const out: number[] = [];
  while (heap.size > 0) {
    const s = heap.peek();
    out.push(s);
    heap.remove(s);
  }
  return out;
}

/** The order a correct queue must pop: by key, then by the tie order (here: larger slot first). */
function expectedOrder(keys: Map<number, number>): number[] {
  return [...keys.entries()].sort((a, b) => a[1] - b[1] || b[0] - a[0]).map(([s]) => s);
}

describe("IndexedHeap", () => {
  it("pops by key, exact ties by the canonical order, after any inserts, re-keys and removals", () => {
    console.log(`[IndexedHeap] fast-check seed ${SEED} (set FC_SEED to change)`);
    // Keys from three values: most comparisons are exact ties, the case the tie-break must get right.
    const op: fc.Arbitrary<Op> = fc.oneof(
      { weight: 4, arbitrary: fc.record({ slot: fc.nat(30), key: fc.constantFrom(0, 0.5, 1) }) },
      { weight: 1, arbitrary: fc.record({ remove: fc.nat(30) }) },
    );
    fc.assert(
      fc.property(fc.array(op, { minLength: 20, maxLength: 200 }), (ops) => {
        const heap = new IndexedHeap(4, (a, b) => a > b);
        const model = new Map<number, number>();
        for (const o of ops) {
          if ("remove" in o) {
            heap.remove(o.remove);
            model.delete(o.remove);
          } else {
            heap.reserve(o.slot + 1);
            heap.set(o.slot, o.key);
            model.set(o.slot, o.key);
          }
          expect(heap.size).toBe(model.size);
        }
        expect(drain(heap)).toEqual(expectedOrder(model));
      }),
      { seed: SEED, numRuns: 300, verbose: true },
    );
  });

  it("an infinite key removes the slot (it would never be popped)", () => {
    const heap = new IndexedHeap(4, (a, b) => a < b);
    heap.set(1, 2);
    heap.set(2, 1);
    heap.set(2, Number.POSITIVE_INFINITY);
    expect(heap.has(2)).toBe(false);
    expect(drain(heap)).toEqual([1]);
  });

  it("four children with equal keys go in the canonical order (the unrolled path's tie check)", () => {
    const heap = new IndexedHeap(8, (a, b) => a < b);
    for (const s of [7, 6, 5, 4, 3, 2]) heap.set(s, 1);
    heap.set(0, 0);
    expect(drain(heap)).toEqual([0, 2, 3, 4, 5, 6, 7]);
  });
});
