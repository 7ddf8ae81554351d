// The slot ranges of the event queue (calendarQueue.ts), its front heap (frontHeap.ts) and the grid
// (grid.ts) follow the body store's capacity (slotCapacity.test.ts): `resize` to a range that still
// holds every queued or registered slot keeps each one where it was (the pop order, the cells), and
// a range that would cut one off throws and changes nothing.
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { CalendarQueue } from "./calendarQueue.js";
import { FrontHeap } from "./frontHeap.js";
import { Grid } from "./grid.js";
import { drain } from "./testSupport.js";

const SEED = Number(process.env.FC_SEED ?? 20261124);

/** Tie order of the tests: smaller slot first. */
const tieLess = (a: number, b: number): boolean => a < b;

function expectedOrder(model: Map<number, number>): number[] {
  return [...model.entries()].sort((a, b) => a[1] - b[1] || a[0] - b[0]).map(([s]) => s);
}

describe("CalendarQueue.resize", () => {
  it("keeps every pending entry and the pop order, wherever the entries sit (front, ring, overflow)", () => {
    console.log(`[slotResize] fast-check seed ${SEED} (set FC_SEED to change)`);
    const entry = fc.record({
      slot: fc.nat(59),
      key: fc.oneof(fc.nat(20), fc.double({ min: 0, max: 1e6, noNaN: true })),
    });
    fc.assert(
      fc.property(fc.array(entry, { minLength: 1, maxLength: 120 }), fc.nat(10), (entries, peeks) => {
        const q = new CalendarQueue(200, { tieLess });
        const model = new Map<number, number>();
        entries.forEach(({ slot, key }, i) => {
          q.set(slot, key);
          model.set(slot, key);
          if (i % 7 === 0) q.peek(); // size the queue and move its window: entries in all three places
        });
        // Take the earliest few out, so the window has moved on.
        for (let k = 0; k < peeks && q.size > 1; k++) {
          const s = q.peek();
          q.remove(s);
          model.delete(s);
        }
        const top = Math.max(...model.keys()) + 1;
        q.resize(top); // down to just above the highest queued slot
        expect(q.slotCapacity).toBe(top);
        expect(q.size).toBe(model.size);
        for (const s of model.keys()) expect(q.has(s)).toBe(true);
        q.resize(top + 45); // and up again: the new slots are free
        for (let s = top; s < top + 45; s++) expect(q.has(s)).toBe(false);
        expect(drain(q)).toEqual(expectedOrder(model));
      }),
      { seed: SEED, numRuns: 200 },
    );
  });

  it("refuses a range that cuts off a queued slot, and changes nothing", () => {
    const q = new CalendarQueue(64, { tieLess });
    const model = new Map<number, number>();
    for (const [s, k] of [
      [3, 5],
      [40, 1],
      [7, 5],
      [20, 2.5],
    ] as const) {
      q.set(s, k);
      model.set(s, k);
    }
    q.peek();
    expect(() => q.resize(40)).toThrow(/slot 40 is queued, beyond the new range 40/);
    expect(q.slotCapacity).toBe(64);
    expect(drain(q)).toEqual(expectedOrder(model));
  });
});

describe("FrontHeap", () => {
  it("holds more entries than it started with, and keeps them through a resize of its slot range", () => {
    const h = new FrontHeap(500, { tieLess });
    const start = h.slots.length;
    const keys = new Map<number, number>();
    for (let s = 0; s < 300; s += 2) {
      const key = (s * 7919) % 101;
      h.push(s, key);
      keys.set(s, key);
    }
    expect(h.n).toBe(150);
    expect(h.slots.length).toBeGreaterThan(start);
    expect(h.slots.length).toBeLessThan(500);
    expect(() => h.resize(298)).toThrow(/slot 298 is queued/);
    h.resize(299);
    expect(h.slotCapacity).toBe(299);
    h.update(100, -1);
    keys.set(100, -1);
    const popped: number[] = [];
    while (h.n > 0) {
      const s = h.slots[0] as number;
      popped.push(s);
      h.remove(s);
    }
    expect(popped).toEqual(expectedOrder(keys));
  });
});

describe("Grid.resize", () => {
  it("keeps every registered slot in its cell and level, and refuses to cut one off", () => {
    const g = new Grid(64);
    g.reset(0, 0, 1, 8, 8);
    const cellOf = (s: number): number => (s * 13) % 64;
    for (let s = 0; s < 30; s++) g.enter(s, 0, cellOf(s));
    g.leave(29);
    expect(() => g.resize(28)).toThrow(/slot 28 is registered, beyond the new range 28/);
    expect(g.slotCapacity).toBe(64);
    g.resize(29);
    expect(g.slotCapacity).toBe(29);
    expect(g.count[0]).toBe(29);
    for (let s = 0; s < 29; s++) {
      expect(g.cellOf[s]).toBe(cellOf(s));
      // Each slot is found in its cell's list.
      let found = false;
      for (let o = g.head[cellOf(s)] as number; o >= 0; o = g.next[o] as number) found ||= o === s;
      expect(found).toBe(true);
    }
    g.resize(40); // grows again: the new slots are not registered
    for (let s = 29; s < 40; s++) expect(g.cellOf[s]).toBe(-1);
    g.leave(5);
    g.enter(35, 0, 7);
    expect(g.members[0]?.length).toBe(29);
  });
});
