// FrontHeap: pops by key, exact ties by the canonical order, after any pushes, updates and removals.
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { FrontHeap } from "./frontHeap.js";

const SEED = Number(process.env.FC_SEED ?? 20261122);

describe("FrontHeap", () => {
  it("keeps (key, tie order) order through pushes, updates and removals", () => {
    console.log(`[FrontHeap] fast-check seed ${SEED} (set FC_SEED to change)`);
    const op = fc.record({ slot: fc.nat(15), key: fc.constantFrom(0, 1, 2), remove: fc.boolean() });
    fc.assert(
      fc.property(fc.array(op, { maxLength: 120 }), (ops) => {
        const h = new FrontHeap(16, { tieLess: (a, b) => a < b });
        const model = new Map<number, number>();
        for (const o of ops) {
          if (o.remove) {
            if (model.has(o.slot)) h.remove(o.slot);
            model.delete(o.slot);
          } else {
            if (model.has(o.slot)) h.update(o.slot, o.key);
            else h.push(o.slot, o.key);
            model.set(o.slot, o.key);
          }
          expect(h.n).toBe(model.size);
        }
        const expected = [...model.entries()].sort((a, b) => a[1] - b[1] || a[0] - b[0]).map(([s]) => s);
        const popped: number[] = [];
        while (h.n > 0) {
          const s = h.slots[0] as number;
          popped.push(s);
          h.remove(s);
        }
        expect(popped).toEqual(expected);
      }),
      { seed: SEED, numRuns: 300 },
    );
  });
});
